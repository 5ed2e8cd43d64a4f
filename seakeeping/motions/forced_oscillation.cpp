#include "seakeeping/motions/forced_oscillation.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "seakeeping/motions/instantaneous_sections.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/strip/contour_motion.h"
#include "seakeeping/strip/strip_marcher.h"

namespace hullopt::sk {
namespace {

// Smooth start: ½(1 − cos πt/T) over [0, T], 1 after, 0 before.
double Ramp(double t, double ramp_s) {
  if (t <= 0.0) return 0.0;
  if (t >= ramp_s) return 1.0;
  return 0.5 * (1.0 - std::cos(M_PI * t / ramp_s));
}

}  // namespace

bool ForcedOscillationOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  std::string g;
  if (!geometry.IsValid(&g)) {
    os << g;
  } else if (geometry.layout != StationLayout::kCellFaces) {
    os << "the forced-oscillation path needs stations at the cell faces (bow and transom included)";
  } else if (!(amplitude > 0.0) || !std::isfinite(amplitude)) {
    os << "amplitude = " << amplitude << ": must be > 0";
  } else if (!(omega_e_rad_s > 0.0) || !std::isfinite(omega_e_rad_s)) {
    os << "omega_e = " << omega_e_rad_s << " rad/s: must be > 0";
  } else if (!(damping_cs >= 0.0) || !std::isfinite(damping_cs)) {
    os << "damping Cs = " << damping_cs << ": must be >= 0";
  } else if (!(ramp_periods >= 0.0) || !std::isfinite(ramp_periods)) {
    os << "ramp_periods = " << ramp_periods << ": must be >= 0";
  } else if (analysed_periods < 1) {
    os << "analysed_periods = " << analysed_periods << ": must be >= 1";
  } else if (sectional_force == SectionalForce::kPressure) {
    StripOperatorOptions o;
    o.sectional_force = sectional_force;
    if (!o.IsValid(&g)) os << g;
  }
  if (os.str().empty()) return true;
  if (error) *error = "forced oscillation: " + os.str();
  return false;
}

ForcedOscillationResult SimulateForcedOscillation(const hull::HullForm& at_rest, const hull::MassProperties& mass,
                                                  double speed_m_s, double rho_kg_m3, double g_m_s2,
                                                  const ForcedOscillationOptions& options) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument(err);
  if (!(speed_m_s > 0.0) || !std::isfinite(speed_m_s) || !(rho_kg_m3 > 0.0) || !(g_m_s2 > 0.0))
    throw std::invalid_argument("forced oscillation: U, rho and g must be > 0");
  const hull::HullForm hull = hull::ApplyRunningAttitude(at_rest, options.attitude);
  const StripGeometryOptions& geo = options.geometry;
  CellFaceStations grid;
  try {
    grid = CellFaceGrid(hull, geo.sections);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("forced oscillation: ") + e.what());
  }
  const int N = geo.sections, steps = N + 1;
  const double dx = grid.dx_m, dt = dx / speed_m_s, w = options.omega_e_rad_s, T = hull.draught_m;
  if (w * dt > kMaxEncounterStepPhase) {
    std::ostringstream os;
    os << "forced oscillation: omega_e dt = " << w * dt << " > pi/4 (8 strip steps per period): use more sections";
    throw std::domain_error(os.str());
  }
  const std::vector<double>& x = grid.x_m;
  const std::vector<double>& weight = grid.weight_m;
  std::vector<double> lever(steps);
  for (int n = 0; n < steps; ++n) lever[n] = x[n] - mass.lcg_m_from_ap;
  // Static restoring of the hull at rest (the strip sums of head_sea_ship_model.h), removed as the tank does.
  double C33 = 0, C35 = 0, C55 = 0;
  for (int n = 0; n < steps; ++n) {
    const double B = WetSectionSums(at_rest, x[n], at_rest.draught_m, geo).beam_m, k = rho_kg_m3 * g_m_s2 * B * weight[n];
    C33 += k, C35 -= k * lever[n], C55 += k * lever[n] * lever[n];
  }
  const bool heave = options.mode == ForcedMode::kHeave;
  ForcedOscillationResult r;
  r.omega_e_rad_s = w;
  r.static_restoring = heave ? std::array<double, 2>{C33, C35} : std::array<double, 2>{C35, C55};

  const double period = 2.0 * M_PI / w, ramp_s = options.ramp_periods * period;
  auto motion = [&](double t) { return options.amplitude * Ramp(t, ramp_s) * std::sin(w * t); };
  // Local draught at station n at time t: the hull point there is raised by x3 − (x − x_G) x5.
  auto draught = [&](int n, double t) {
    const double m = motion(t);
    return heave ? T - m : T + lever[n] * m;
  };
  // ẋ3 − (x − x_G) ẋ5 + U x5 of the section at station n: the vertical speed of the hull element that the
  // fixed strip sees (the U x5 as the pitched hull passes the strip).
  auto vertical_velocity = [&](int n, double t) {
    double ramp = Ramp(t, ramp_s), ramp_rate = 0.0;
    if (t > 0.0 && t < ramp_s) ramp_rate = 0.5 * M_PI / ramp_s * std::sin(M_PI * t / ramp_s);
    const double m = options.amplitude * ramp * std::sin(w * t);
    const double rate = options.amplitude * (ramp_rate * std::sin(w * t) + ramp * w * std::cos(w * t));
    return heave ? rate : -lever[n] * rate + speed_m_s * m;
  };
  // Analysis from one hull passage after the ramp (every strip then on the hull was born into the periodic
  // motion) over whole periods.
  const int j0 = static_cast<int>(std::ceil(ramp_s / dt)) + steps;
  const int j1 = j0 + static_cast<int>(std::lround(options.analysed_periods * period / dt));
  const int s0 = j0 - N, s1 = j1;  // strips born at step s hold station n at time (s + n) dt
  const int S = s1 - s0 + 1;
  std::vector<std::vector<double>> f(S, std::vector<double>(steps, 0.0));
  StripOperatorOptions ops_options;
  ops_options.sectional_force = options.sectional_force;
  ops_options.layout = StationLayout::kCellFaces;
  ops_options.use_mirror_symmetry = true;
  std::string failure;
#pragma omp parallel for schedule(dynamic, 1)
  for (int i = 0; i < S; ++i) {
    try {
      const int s = s0 + i;
      std::vector<std::vector<Panel>> panels(steps), contours(steps);
      for (int n = 0; n < steps; ++n) {
        const double t = (s + n) * dt;
        try {
          panels[n] = StripSectionPanels(hull, x[n], draught(n, t), geo, &contours[n]);
        } catch (const std::domain_error& e) {
          std::ostringstream os;
          os << e.what() << " (forced oscillation at t = " << t << " s)";
          throw std::domain_error(os.str());
        }
      }
      // The hull element's normal velocity in the strip: the rigid motion, n_z (ẋ3 − (x − x_G) ẋ5 + U x5),
      // exactly, plus the change of the section's shape as the hull passes, measured between the neighbouring
      // stations' contours cut at this station's waterline (the same vertical position). The waterline points
      // move with both: their speeds are read from the contours where they really are.
      std::vector<ContourMotion> motions(steps);
      for (int n = 0; n < steps; ++n) {
        const double t = (s + n) * dt;
        std::vector<std::vector<Panel>> near(3), near_contours(3);
        near[1] = panels[n], near_contours[1] = contours[n];
        for (int side : {-1, 1})
          if (n + side >= 0 && n + side < steps)
            near[1 + side] = StripSectionPanels(hull, x[n + side], draught(n, t), geo, &near_contours[1 + side]);
        motions[n] = StepContourMotion(near, 1, dt, &near_contours);
        motions[n].waterline = StepContourMotion(panels, n, dt, &contours).waterline;
        const double v = vertical_velocity(n, t);
        for (std::size_t p = 0; p < panels[n].size(); ++p) motions[n].normal_speed_m_s[p] += panels[n][p].Normal()[1] * v;
      }
      const StripOperators ops = BuildStripOperators(panels, dt, rho_kg_m3, g_m_s2, ops_options, &motions);
      StripMarcher marcher(ops);
      for (int n = 0; n < steps; ++n) {
        Eigen::VectorXd vn = Eigen::VectorXd::Zero(ops.PanelCount(n));
        const auto& index = ops.ReducedIndex(n);
        const auto& share = ops.ReducedShare(n);
        for (std::size_t p = 0; p < index.size(); ++p) vn(index[p]) += share[p] * motions[n].normal_speed_m_s[p];
        f[i][n] = marcher.Advance(vn);
      }
    } catch (const std::exception& e) {
#pragma omp critical(forced_oscillation_failure)
      if (failure.empty()) failure = e.what();
    }
  }
  if (!failure.empty()) throw std::domain_error(failure);
  r.strips = S;

  // The hull's force at each analysed time: the strips on the hull, the buoyancy of its sections and the Cs
  // damping on their waterline beams.
  const double damping = 0.5 * options.damping_cs * rho_kg_m3 * speed_m_s;
  const int J = j1 - j0 + 1;
  Eigen::MatrixXd basis(J, 5);
  Eigen::MatrixXd force(J, 2);
  for (int j = j0; j <= j1; ++j) {
    const double t = j * dt;
    double F3 = 0, F5 = 0;
    for (int n = 0; n < steps; ++n) {
      const SectionSums sec = WetSectionSums(hull, x[n], draught(n, t), geo);
      const double buoyancy = rho_kg_m3 * g_m_s2 * sec.area_m2;
      const double fn = (f[j - n - s0][n] + buoyancy - damping * sec.beam_m * vertical_velocity(n, t)) * weight[n];
      F3 += fn, F5 -= lever[n] * fn;
    }
    const int row = j - j0;
    basis.row(row) << 1.0, std::cos(w * t), std::sin(w * t), std::cos(2 * w * t), std::sin(2 * w * t);
    force(row, 0) = F3, force(row, 1) = F5;
    r.time_s.push_back(t), r.motion.push_back(motion(t)), r.force_N.push_back(F3), r.moment_N_m.push_back(F5);
  }
  const Eigen::MatrixXd c = basis.colPivHouseholderQr().solve(force);
  const std::complex<double> X(0.0, -options.amplitude);  // a sin ωt = Re(−i a e^{iωt})
  for (int i = 0; i < 2; ++i) {
    const std::complex<double> F(c(1, i), -c(2, i));
    const std::complex<double> Z = -F / X;
    r.added_mass[i] = (r.static_restoring[i] - Z.real()) / (w * w);
    r.damping[i] = Z.imag() / w;
    r.mean[i] = c(0, i);
    r.second_harmonic_ratio[i] = std::hypot(c(3, i), c(4, i)) / std::max(std::hypot(c(1, i), c(2, i)), 1e-300);
  }
  return r;
}

}  // namespace hullopt::sk
