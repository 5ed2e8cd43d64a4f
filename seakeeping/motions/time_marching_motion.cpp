#include "seakeeping/motions/time_marching_motion.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {

bool MarchingOptions::IsValid(std::string* error) const {
  if (!SchemeParameters().IsValid(error)) return false;
  std::ostringstream os;
  if (TimeSchemeName(scheme) == "unknown") {
    os << "scheme = " << static_cast<int>(scheme) << ": not a registered time scheme";
  } else if (!(ramp_periods >= 0.0) || !std::isfinite(ramp_periods)) {
    os << "ramp_periods = " << ramp_periods << ": must be >= 0";
  } else if (fit_periods < 1) {
    os << "fit_periods = " << fit_periods << ": must be >= 1";
  } else if (max_periods <= ramp_periods + fit_periods) {
    os << "max_periods = " << max_periods << ": must exceed ramp_periods + fit_periods";
  } else if (!(steady_tolerance > 0.0)) {
    os << "steady_tolerance = " << steady_tolerance << ": must be > 0";
  }
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

WeightedAverageParameters MarchingOptions::SchemeParameters() const {
  WeightedAverageParameters p;
  p.hydrodynamic_fraction = hydrodynamic_fraction;
  p.max_passes = max_passes;
  p.pass_tolerance = pass_tolerance;
  return p;
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
  scheme_ = MakeTimeScheme(options.scheme, options.SchemeParameters());
  const auto N = static_cast<std::size_t>(model.Steps());
  velocity_.resize(N);
  fk_.resize(N);
  surface_rate_.resize(N);
  orbital_.resize(N);
  section_force_.resize(N);
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
  scheme_->Restart();
  t_ = 0.0;
  state_ = MarchingState{};
}

double TimeMarcher::WaveAtCg() const {
  const double r = (ramp_s_ > 0.0 && t_ < ramp_s_) ? 0.5 * (1.0 - std::cos(M_PI * t_ / ramp_s_)) : 1.0;
  double z = 0.0;
  for (std::size_t j = 0; j < sea_.size(); ++j)
    z += sea_[j].amplitude_m * std::cos(omega_e_[j] * t_ + sea_[j].phase_rad);
  return r * z;
}

DofPair TimeMarcher::HullAcceleration(const DofPair& x3x5, const DofPair& v3v5, int trial) {
  const double U = model_.speed(), rho = model_.rho(), g = model_.g(), damp = model_.DampingFactor();
  const auto& st = model_.stations();
  const int N = model_.Steps();
  for (int n = 0; n < N; ++n) {
    const StationData& s = st[n];
    const double x = s.x_cg_m;
    const double disp = x3x5[0] - x * x3x5[1];
    const double v_hull = v3v5[0] - x * v3v5[1] + U * x3x5[1];
    velocity_[n] = s.nz.array() * (v_hull - orbital_[n].array());
    section_force_[n] = -rho * g * s.beam_m * disp + fk_[n] - damp * s.beam_m * (v_hull - surface_rate_[n]);
  }
  if (trial == 0) {
    forces_.Advance(velocity_, &kernel_force_);
  } else {
    forces_.Revise(velocity_, &kernel_force_);
  }
  double F3 = 0.0, F5 = 0.0;
  for (int n = 0; n < N; ++n) {
    const double f = kernel_force_[n] + section_force_[n];
    F3 += f * st[n].weight_m;
    F5 -= st[n].x_cg_m * f * st[n].weight_m;
  }
  return {F3 / model_.mass(), F5 / model_.pitch_inertia()};
}

void TimeMarcher::Step() {
  const double dt = model_.dt(), rho = model_.rho(), g = model_.g();
  t_ += dt;
  const double r = (ramp_s_ > 0.0 && t_ < ramp_s_) ? 0.5 * (1.0 - std::cos(M_PI * t_ / ramp_s_)) : 1.0;
  const auto& st = model_.stations();
  const int N = model_.Steps();
  const auto J = static_cast<Eigen::Index>(sea_.size());
  Eigen::VectorXd wz(J);
  for (int n = 0; n < N; ++n) {
    fk_[n] = 0.0;
    surface_rate_[n] = 0.0;
    for (Eigen::Index j = 0; j < J; ++j) {
      const double th = omega_e_[j] * t_ + k_[j] * st[n].x_cg_m + sea_[j].phase_rad;
      const double amp = r * sea_[j].amplitude_m;
      fk_[n] += rho * g * fk_width_[n][j] * amp * std::cos(th);
      wz[j] = -sea_[j].omega_rad_s * amp * std::sin(th);
      surface_rate_[n] += wz[j];
    }
    orbital_[n] = ekz_[n] * wz;
  }
  scheme_->Step(dt, [this](const DofPair& x, const DofPair& v, int trial) { return HullAcceleration(x, v, trial); },
                &state_);
  const DofPair& x = state_.x;
  const DofPair& a = state_.a;
  if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(a[0]) || !std::isfinite(a[1]) ||
      std::fabs(x[0]) > 1e6 || std::fabs(x[1]) > 1e6) {
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
