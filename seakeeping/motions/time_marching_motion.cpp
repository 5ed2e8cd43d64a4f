#include "seakeeping/motions/time_marching_motion.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {

bool MarchingOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  if (!(hydrodynamic_fraction > 0.0) || !(hydrodynamic_fraction <= 1.0)) {
    os << "hydrodynamic_fraction = " << hydrodynamic_fraction << ": must satisfy 0 < fraction <= 1";
  } else if (!(ramp_periods >= 0.0) || !std::isfinite(ramp_periods)) {
    os << "ramp_periods = " << ramp_periods << ": must be >= 0";
  } else if (fit_periods < 1) {
    os << "fit_periods = " << fit_periods << ": must be >= 1";
  } else if (max_periods <= ramp_periods + fit_periods) {
    os << "max_periods = " << max_periods << ": must exceed ramp_periods + fit_periods";
  } else if (!(steady_tolerance > 0.0)) {
    os << "steady_tolerance = " << steady_tolerance << ": must be > 0";
  } else if (max_passes < 1) {
    os << "max_passes = " << max_passes << ": must be >= 1";
  } else if (!(pass_tolerance > 0.0)) {
    os << "pass_tolerance = " << pass_tolerance << ": must be > 0";
  }
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

TimeMarcher::TimeMarcher(const HeadSeaShipModel& model, StripForceModel& forces,
                         const MarchingOptions& options)
    : model_(model), forces_(forces), options_(options) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument("time marching: " + err);
  if (forces.Steps() != model.Steps())
    throw std::invalid_argument("time marching: the strip force model and the ship model differ in steps");
  for (int n = 0; n < model.Steps(); ++n)
    if (forces.PanelsAt(n).size() != static_cast<std::size_t>(model.stations()[n].nz.size()))
      throw std::invalid_argument("time marching: panel counts differ at step " + std::to_string(n));
  velocity_.resize(model.Steps());
}

void TimeMarcher::Start(const std::vector<WaveComponent>& sea, double ramp_s) {
  sea_ = sea;
  ramp_s_ = ramp_s;
  const double g = model_.g(), U = model_.speed();
  const auto J = static_cast<Eigen::Index>(sea.size());
  k_.clear();
  omega_e_.clear();
  for (const auto& c : sea) {
    k_.push_back(c.omega_rad_s * c.omega_rad_s / g);
    omega_e_.push_back(HeadSeaEncounterFrequency(c.omega_rad_s, U, g));
  }
  const auto& st = model_.stations();
  fk_width_.assign(st.size(), std::vector<double>(sea.size()));
  ekz_.resize(st.size());
  for (std::size_t n = 0; n < st.size(); ++n) {
    ekz_[n].resize(st[n].z_mid.size(), J);
    for (Eigen::Index j = 0; j < J; ++j) {
      fk_width_[n][j] = st[n].FroudeKrylovWidth(k_[j]);
      ekz_[n].col(j) = (k_[j] * st[n].z_mid.array()).exp().matrix();
    }
  }
  forces_.Reset();
  t_ = 0.0;
  k_step_ = 0;
  for (int i = 0; i < 2; ++i) x_[i] = v_[i] = a_[i] = a_prev_[i] = a_scale_[i] = 0.0;
}

double TimeMarcher::WaveAtCg() const {
  const double r = (ramp_s_ > 0.0 && t_ < ramp_s_) ? 0.5 * (1.0 - std::cos(M_PI * t_ / ramp_s_)) : 1.0;
  double z = 0.0;
  for (std::size_t j = 0; j < sea_.size(); ++j)
    z += sea_[j].amplitude_m * std::cos(omega_e_[j] * t_ + sea_[j].phase_rad);
  return r * z;
}

void TimeMarcher::Step() {
  const double dt = model_.dt(), U = model_.speed(), rho = model_.rho(), g = model_.g();
  const double w = options_.hydrodynamic_fraction, damp = model_.DampingFactor();
  const double x0[2] = {x_[0], x_[1]}, v0[2] = {v_[0], v_[1]};
  double guess[2];
  for (int i = 0; i < 2; ++i) guess[i] = k_step_ >= 1 ? 2.0 * a_[i] - a_prev_[i] : a_[i];
  t_ += dt;
  ++k_step_;
  const double r = (ramp_s_ > 0.0 && t_ < ramp_s_) ? 0.5 * (1.0 - std::cos(M_PI * t_ / ramp_s_)) : 1.0;
  const auto& st = model_.stations();
  const int N = model_.Steps();
  const auto J = static_cast<Eigen::Index>(sea_.size());
  // Wave terms of this time, fixed during the passes: Froude–Krylov force, rate of rise of the surface and
  // the orbital velocity at the collocation points.
  std::vector<double> fk(N, 0.0), surface_rate(N, 0.0);
  std::vector<Eigen::VectorXd> orbital(N);
  Eigen::VectorXd wz(J);
  for (int n = 0; n < N; ++n) {
    for (Eigen::Index j = 0; j < J; ++j) {
      const double th = omega_e_[j] * t_ + k_[j] * st[n].x_cg_m + sea_[j].phase_rad;
      const double amp = r * sea_[j].amplitude_m;
      fk[n] += rho * g * fk_width_[n][j] * amp * std::cos(th);
      wz[j] = -sea_[j].omega_rad_s * amp * std::sin(th);
      surface_rate[n] += wz[j];
    }
    orbital[n] = ekz_[n] * wz;
  }
  std::vector<double> section_force(N);
  double next[2] = {0, 0};
  for (int pass = 0; pass < options_.max_passes; ++pass) {
    for (int i = 0; i < 2; ++i) {
      const double a_mean = 0.5 * (a_[i] + guess[i]);
      x_[i] = x0[i] + dt * v0[i] + 0.5 * dt * dt * a_mean;
      v_[i] = v0[i] + dt * a_mean;
    }
    for (int n = 0; n < N; ++n) {
      const StationData& s = st[n];
      const double x = s.x_cg_m;
      const double disp = x_[0] - x * x_[1];
      const double v_hull = v_[0] - x * v_[1] + U * x_[1];
      velocity_[n] = s.nz.array() * (v_hull - orbital[n].array());
      section_force[n] = -rho * g * s.beam_m * disp + fk[n] - damp * s.beam_m * (v_hull - surface_rate[n]);
    }
    if (pass == 0) {
      forces_.Advance(velocity_, &kernel_force_);
    } else {
      forces_.Revise(velocity_, &kernel_force_);
    }
    double F3 = 0.0, F5 = 0.0;
    for (int n = 0; n < N; ++n) {
      const double f = kernel_force_[n] + section_force[n];
      F3 += f * st[n].weight_m;
      F5 -= st[n].x_cg_m * f * st[n].weight_m;
    }
    const double a_hydro[2] = {F3 / model_.mass(), F5 / model_.pitch_inertia()};
    bool settled = true;
    for (int i = 0; i < 2; ++i) {
      next[i] = w * a_hydro[i] + (1.0 - w) * guess[i];
      a_scale_[i] = std::max(a_scale_[i], std::fabs(next[i]));
      if (std::fabs(next[i] - guess[i]) > options_.pass_tolerance * a_scale_[i]) settled = false;
    }
    if (!std::isfinite(next[0]) || !std::isfinite(next[1])) break;
    if (settled || pass + 1 == options_.max_passes) break;
    guess[0] = next[0];
    guess[1] = next[1];
  }
  // The state stays the one the strips were last solved with, so that the strip history and the motion agree.
  for (int i = 0; i < 2; ++i) {
    a_prev_[i] = a_[i];
    a_[i] = next[i];
  }
  if (!std::isfinite(x_[0]) || !std::isfinite(x_[1]) || !std::isfinite(a_[0]) || !std::isfinite(a_[1]) ||
      std::fabs(x_[0]) > 1e6 || std::fabs(x_[1]) > 1e6) {
    std::ostringstream os;
    os << "hull '" << (model_.options().hull_name.empty() ? "(unnamed)" : model_.options().hull_name)
       << "': time marching diverged at t = " << t_ << " s (try a smaller hydrodynamic_fraction)";
    throw std::domain_error(os.str());
  }
}

namespace {
// Least-squares fit x ≈ c0 + c cos(ω_e t) + s sin(ω_e t) over samples [begin, end); returns X = c − i s.
std::complex<double> FourierFit(const std::vector<double>& t, const std::vector<double>& x, std::size_t begin,
                                double we) {
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (std::size_t i = begin; i < t.size(); ++i) {
    const Eigen::Vector3d row(1.0, std::cos(we * t[i]), std::sin(we * t[i]));
    ata += row * row.transpose();
    atb += row * x[i];
  }
  const Eigen::Vector3d c = ata.ldlt().solve(atb);
  return {c[1], -c[2]};
}
}  // namespace

RaoTable SolveMarchingRaos(const HeadSeaShipModel& model, StripForceModel& forces,
                           const std::vector<double>& omega_rad_s, const MarchingOptions& options) {
  if (omega_rad_s.empty()) throw std::invalid_argument("RAO sweep: the frequency list is empty");
  RaoTable out;
  out.speed_m_s = model.speed();
  out.g_m_s2 = model.g();
  TimeMarcher marcher(model, forces, options);
  const double dt = model.dt();
  for (double w : omega_rad_s) {
    if (!(w > 0.0) || !std::isfinite(w))
      throw std::invalid_argument("RAO sweep: wave frequency " + std::to_string(w) + " rad/s must be > 0");
    const double we = HeadSeaEncounterFrequency(w, model.speed(), model.g());
    const double k = w * w / model.g();
    const double period = 2.0 * M_PI / we;
    marcher.Start({{1.0, w, 0.0}}, options.ramp_periods * period);
    MotionTimeSeries ts;
    // Settle at least the ramp plus one passage of a strip along the hull before the first fit.
    const double t_first = options.ramp_periods * period + model.Steps() * dt + options.fit_periods * period;
    const double t_max = options.max_periods * period + model.Steps() * dt;
    double next_fit = t_first;
    std::complex<double> prev3, prev5;
    bool have_prev = false, settled = false;
    while (marcher.time_s() < t_max) {
      marcher.Step();
      ts.t_s.push_back(marcher.time_s());
      ts.heave_m.push_back(marcher.heave_m());
      ts.pitch_rad.push_back(marcher.pitch_rad());
      if (marcher.time_s() < next_fit) continue;
      next_fit += period;
      const double t0 = marcher.time_s() - options.fit_periods * period;
      std::size_t begin = ts.t_s.size();
      while (begin > 0 && ts.t_s[begin - 1] > t0) --begin;
      const auto x3 = FourierFit(ts.t_s, ts.heave_m, begin, we);
      const auto x5 = FourierFit(ts.t_s, ts.pitch_rad, begin, we) / k;
      if (have_prev && std::abs(x3 - prev3) + std::abs(x5 - prev5) < options.steady_tolerance) {
        out.omega_rad_s.push_back(w);
        out.omega_e_rad_s.push_back(we);
        out.heave.push_back(x3);
        out.pitch.push_back(x5);
        settled = true;
        break;
      }
      prev3 = x3;
      prev5 = x5;
      have_prev = true;
    }
    if (!settled) {
      std::ostringstream os;
      os << "hull '" << (model.options().hull_name.empty() ? "(unnamed)" : model.options().hull_name)
         << "': time marching did not reach a steady state within " << options.max_periods
         << " periods at omega = " << w << " rad/s (omega_e = " << we << " rad/s)";
      throw std::domain_error(os.str());
    }
  }
  return out;
}

MotionTimeSeries MarchHeadSea(const HeadSeaShipModel& model, StripForceModel& forces,
                              const std::vector<WaveComponent>& sea, double duration_s, double ramp_s,
                              const MarchingOptions& options) {
  if (!(duration_s > 0.0) || !(ramp_s >= 0.0))
    throw std::invalid_argument("MarchHeadSea: duration must be > 0 and ramp >= 0");
  TimeMarcher marcher(model, forces, options);
  marcher.Start(sea, ramp_s);
  MotionTimeSeries ts;
  while (marcher.time_s() < duration_s) {
    marcher.Step();
    ts.t_s.push_back(marcher.time_s());
    ts.heave_m.push_back(marcher.heave_m());
    ts.pitch_rad.push_back(marcher.pitch_rad());
    ts.wave_at_cg_m.push_back(marcher.WaveAtCg());
  }
  return ts;
}

}  // namespace hullopt::sk
