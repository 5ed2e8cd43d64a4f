#include "seakeeping/motions/calm_water.h"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "seakeeping/motions/instantaneous_sections.h"
#include "seakeeping/strip/contour_motion.h"
#include "seakeeping/strip/strip_marcher.h"
#include "seakeeping/strip/strip_power.h"

namespace hullopt::sk {
namespace {

void CheckScalars(double speed_m_s, double rho_kg_m3, double g_m_s2, const CalmWaterOptions& options) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument(err);
  if (!(speed_m_s > 0.0) || !std::isfinite(speed_m_s) || !(rho_kg_m3 > 0.0) || !std::isfinite(rho_kg_m3) ||
      !(g_m_s2 > 0.0) || !std::isfinite(g_m_s2))
    throw std::invalid_argument("calm water: U, rho and g must be finite and > 0");
}

// The steady elevation at the water-line points of one side (outer: the free surface beside them lies away from
// the centre plane), η_n = −(1/g) dφ/dt of their mean potential along the march: φ comes from the pressure
// form's transport rows of a contour whose only motion is a unit speed of the selected water-line points
// (then ρT = ρ Σ φ over them, contour_motion.h), applied to the march's sources; central differences in time
// (one-sided at the ends). Empty when the side has no water-line point anywhere.
std::vector<double> SideElevation(const std::vector<std::vector<Panel>>& panels, const std::vector<ContourMotion>& motions,
                                  const std::vector<Eigen::VectorXd>& sources, double dt, double rho, double g,
                                  bool outer) {
  const int steps = static_cast<int>(panels.size());
  std::vector<ContourMotion> probe(steps);
  std::vector<int> count(steps, 0);
  bool any = false;
  for (int n = 0; n < steps; ++n) {
    probe[n].normal_speed_m_s.assign(panels[n].size(), 0.0);
    for (WaterlinePoint w : motions[n].waterline) {
      if ((w.outward * w.y_m > 0.0) != outer) continue;
      w.speed_m_s = -1.0;  // T = −Σ φ ẏ_out = Σ φ
      probe[n].waterline.push_back(w);
      ++count[n];
      any = true;
    }
  }
  if (!any) return {};
  StripOperatorOptions o;
  o.sectional_force = SectionalForce::kPressure;
  o.layout = StationLayout::kCellFaces;
  o.use_mirror_symmetry = true;
  const StripOperators ops = BuildStripOperators(panels, dt, rho, g, o, &probe);
  if (ops.TimeInvariant()) return {};
  std::vector<double> phi(steps, 0.0);
  for (int n = 0; n < steps; ++n) {
    if (count[n] == 0 || ops.PanelCount(n) == 0) continue;
    double t = ops.TransportCurrent(n).dot(sources[n]);
    for (int k = 0; k < n; ++k)
      if (ops.PanelCount(k) > 0) t += ops.TransportMemory(n, k).dot(sources[k]);
    phi[n] = t / (rho * count[n]);
  }
  std::vector<double> eta(steps, 0.0);
  for (int n = 0; n < steps; ++n) {
    if (count[n] == 0) continue;
    const int a = std::max(n - 1, 0), b = std::min(n + 1, steps - 1);
    eta[n] = -(phi[b] - phi[a]) / (g * (b - a) * dt);
  }
  return eta;
}

}  // namespace

bool CalmWaterOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  std::string g;
  if (!geometry.IsValid(&g)) {
    os << g;
  } else if (geometry.layout != StationLayout::kCellFaces) {
    os << "the calm-water path needs stations at the cell faces (bow and transom included)";
  } else if (max_iterations < 1) {
    os << "max_iterations = " << max_iterations << ": must be >= 1";
  } else if (!(sinkage_tolerance_m > 0.0) || !std::isfinite(sinkage_tolerance_m)) {
    os << "sinkage_tolerance_m = " << sinkage_tolerance_m << ": must be > 0";
  } else if (!(trim_tolerance_deg > 0.0) || !std::isfinite(trim_tolerance_deg)) {
    os << "trim_tolerance_deg = " << trim_tolerance_deg << ": must be > 0";
  } else if (sectional_force == SectionalForce::kPressure) {
    StripOperatorOptions o;
    o.sectional_force = sectional_force;
    if (!o.IsValid(&g)) os << g;
  }
  if (os.str().empty()) return true;
  if (error) *error = "calm water: " + os.str();
  return false;
}

SteadyForce CalmWaterForce(const hull::HullForm& at_rest, const hull::MassProperties& mass,
                           const hull::RunningAttitude& attitude, double speed_m_s, double rho_kg_m3,
                           double g_m_s2, const CalmWaterOptions& options) {
  CheckScalars(speed_m_s, rho_kg_m3, g_m_s2, options);
  const hull::HullForm hull = hull::ApplyRunningAttitude(at_rest, attitude);
  const StripGeometryOptions& geo = options.geometry;
  const CellFaceStations grid = CellFaceGrid(at_rest, geo.sections);
  const int steps = geo.sections + 1;
  const double dt = grid.dx_m / speed_m_s;

  // The one strip every strip repeats: station n at step n, the hull's waterline fixed.
  std::vector<std::vector<Panel>> panels(steps), contours(steps);
  for (int n = 0; n < steps; ++n) panels[n] = StripSectionPanels(hull, grid.x_m[n], hull.draught_m, geo, &contours[n]);
  std::vector<ContourMotion> motions(steps);
  for (int n = 0; n < steps; ++n) motions[n] = StepContourMotion(panels, n, dt, &contours);
  StripOperatorOptions ops_options;
  ops_options.sectional_force = options.sectional_force;
  ops_options.layout = StationLayout::kCellFaces;
  ops_options.use_mirror_symmetry = true;
  const StripOperators ops = BuildStripOperators(panels, dt, rho_kg_m3, g_m_s2, ops_options, &motions);
  StripMarcher marcher(ops);

  SteadyForce r;
  std::vector<Eigen::VectorXd> sources;
  for (int n = 0; n < steps; ++n) {
    Eigen::VectorXd vn = Eigen::VectorXd::Zero(ops.PanelCount(n));
    const auto& index = ops.ReducedIndex(n);
    const auto& share = ops.ReducedShare(n);
    for (std::size_t p = 0; p < index.size(); ++p) vn(index[p]) += share[p] * motions[n].normal_speed_m_s[p];
    const double f = marcher.Advance(vn);
    if (options.elevation) sources.push_back(marcher.Sources().back());
    const double buoyancy = rho_kg_m3 * g_m_s2 * WetSectionSums(hull, grid.x_m[n], hull.draught_m, geo).area_m2;
    const double weight = rho_kg_m3 * g_m_s2 * WetSectionSums(at_rest, grid.x_m[n], at_rest.draught_m, geo).area_m2;
    const double lever = grid.x_m[n] - mass.lcg_m_from_ap, w = grid.weight_m[n];
    r.x_m.push_back(grid.x_m[n]);
    r.force_N_per_m.push_back(f);
    r.buoyancy_N_per_m.push_back(buoyancy);
    r.hydrodynamic_heave_N += f * w;
    r.hydrodynamic_moment_N_m -= lever * f * w;
    r.heave_N += (f + buoyancy - weight) * w;
    r.moment_N_m -= lever * (f + buoyancy - weight) * w;
  }
  if (options.wave_resistance) {
    r.power_W_per_m = StripPower(ops, marcher.Sources(), motions);
    for (int n = 0; n < steps; ++n) r.wave_resistance_N += r.power_W_per_m[n] * grid.weight_m[n] / speed_m_s;
  }
  if (options.elevation) {
    r.elevation_outer_m = SideElevation(panels, motions, sources, dt, rho_kg_m3, g_m_s2, true);
    r.elevation_inner_m = SideElevation(panels, motions, sources, dt, rho_kg_m3, g_m_s2, false);
  }
  return r;
}

CalmWaterResult SolveRunningAttitude(const hull::HullForm& at_rest, const hull::MassProperties& mass,
                                     double speed_m_s, double rho_kg_m3, double g_m_s2,
                                     const CalmWaterOptions& options) {
  CheckScalars(speed_m_s, rho_kg_m3, g_m_s2, options);
  const CellFaceStations grid = CellFaceGrid(at_rest, options.geometry.sections);
  CalmWaterResult r;
  r.attitude.pivot_x_m = mass.lcg_m_from_ap;
  CalmWaterOptions iterate = options;  // the elevation and resistance only at the converged attitude
  iterate.elevation = false;
  iterate.wave_resistance = false;
  for (int it = 1; it <= options.max_iterations; ++it) {
    r.iterations = it;
    hull::HullForm hull;
    try {
      hull = hull::ApplyRunningAttitude(at_rest, r.attitude);
      r.force = CalmWaterForce(at_rest, mass, r.attitude, speed_m_s, rho_kg_m3, g_m_s2, iterate);
    } catch (const std::exception& e) {
      r.note = std::string("the attitude iteration left the hull's range: ") + e.what();
      return r;
    }
    // Hydrostatic stiffness of the current attitude in (sinkage + down, trim + bow up): a sinkage s deepens
    // every station by s, a trim θ by −(x − x_G) tan θ.
    double k = 0, kx = 0, kxx = 0;
    for (std::size_t n = 0; n < grid.x_m.size(); ++n) {
      const double c = rho_kg_m3 * g_m_s2 * WetSectionSums(hull, grid.x_m[n], hull.draught_m, options.geometry).beam_m * grid.weight_m[n];
      const double lever = grid.x_m[n] - mass.lcg_m_from_ap;
      k += c, kx += c * lever, kxx += c * lever * lever;
    }
    // dF3/ds = k, dF3/dθ = −kx; dF5/ds = −kx, dF5/dθ = kxx (F5 + bow down, per radian of tan θ).
    Eigen::Matrix2d J;
    J << k, -kx, -kx, kxx;
    const Eigen::Vector2d step = J.fullPivLu().solve(-Eigen::Vector2d(r.force.heave_N, r.force.moment_N_m));
    const double ds = step(0), dtheta_deg = std::atan(step(1)) * 180.0 / M_PI;
    r.attitude.sinkage_m += ds;
    r.attitude.trim_deg = std::atan(std::tan(r.attitude.trim_deg * M_PI / 180.0) + step(1)) * 180.0 / M_PI;
    if (!std::isfinite(r.attitude.sinkage_m) || !std::isfinite(r.attitude.trim_deg)) {
      r.note = "the attitude iteration diverged (non-finite sinkage or trim)";
      return r;
    }
    if (std::abs(r.attitude.trim_deg) > hull::kMaxTrimDeg) {
      std::ostringstream os;
      os << "the attitude iteration reached a trim of " << r.attitude.trim_deg << " deg, beyond the "
         << hull::kMaxTrimDeg << " deg the strips' attitude model holds";
      r.note = os.str();
      return r;
    }
    if (std::abs(ds) < options.sinkage_tolerance_m && std::abs(dtheta_deg) < options.trim_tolerance_deg) {
      try {
        r.force = CalmWaterForce(at_rest, mass, r.attitude, speed_m_s, rho_kg_m3, g_m_s2, options);
      } catch (const std::exception& e) {
        r.note = std::string("the attitude iteration left the hull's range: ") + e.what();
        return r;
      }
      r.converged = true;
      return r;
    }
  }
  std::ostringstream os;
  os << "the attitude iteration did not converge in " << options.max_iterations << " iterations";
  r.note = os.str();
  return r;
}

}  // namespace hullopt::sk
