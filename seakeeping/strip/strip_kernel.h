#pragma once
// The frequency-independent response of one water strip as the hull passes through it (docs/ship-motions.md).
//
// A strip of water fixed in space is entered by the bow at step 0; at step n (n = 0 .. N−1) it holds the hull
// section at x_m[n] (from the AP), one time step dt = dx/U after the previous one, and it is discarded after the
// stern has passed. With the linear body condition on the mean hull every strip sees the same sequence of
// panelled sections, so one strip's linear response describes all of them:
//
//   f_n = Σ_{m ≤ n} force[n][m] · V_m
//
// f_n [N/m]: vertical hydrodynamic force per unit length on the section held at step n, from the disturbance
// potential only (radiation and diffraction together; the incident-wave Froude–Krylov and hydrostatic forces
// and the empirical damping are added by the ship equations), V_m [m/s]: the normal velocity prescribed at the
// collocation points (panel midpoints) of the panels of step m, positive into the fluid, i.e. (body velocity −
// incident-wave velocity) · n. force[n][m] is a row vector over the panels of step m [N/m per m/s].
#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "seakeeping/green/panel.h"

namespace hullopt::sk {

/// Where the steps of a strip sit along the hull (docs/ship-motions.md, "Convergence"), with N = sections
/// cells of length dx between the hull's extreme stations x_fwd and x_T:
///  - kCellMidpoints: N steps at x_fwd − (n + ½)dx, weight dx each; the force is the second-order backward
///    difference (BDF2) of the strip momentum I. The hull sum then telescopes to U·I at the transom
///    extrapolated linearly from the last two stations, dx/2 and 3dx/2 ahead of it.
///  - kCellFaces: N + 1 steps at x_fwd − n dx (bow and transom included), trapezoid weights (dx/2 at both
///    ends); BDF2 inside with end rows chosen so that the hull sum telescopes exactly to U·I_T, the momentum
///    of the strip holding the transom section itself, and stays second order (StripForceStencil).
enum class StationLayout { kCellMidpoints, kCellFaces };
/// The layout of StripKernelGeometry and of the strip operators' force unless asked otherwise (one constant,
/// so that geometry and marcher agree by default). Cell faces: they converge faster to the same limit
/// (docs/ship-motions.md, "Convergence": the Delft 372 demihull is converged in sections at 20, where the
/// midpoints are 12% low), because the transom momentum is taken on the transom section itself.
inline constexpr StationLayout kDefaultStationLayout = StationLayout::kCellFaces;

/// Steps of a strip over `sections` cells in a layout.
inline int StationCount(StationLayout layout, int sections) {
  return layout == StationLayout::kCellFaces ? sections + 1 : sections;
}

/// Quadrature weight of step n of `steps` [m]: the hull force is Σ_n weight_n f_n.
inline double StationWeight(StationLayout layout, int n, int steps, double dx) {
  if (layout == StationLayout::kCellFaces && (n == 0 || n == steps - 1)) return 0.5 * dx;
  return dx;
}

/// Sectional force of step n from the strip's momentum: f_n = (c[0] I_n + c[1] I_{n−1} + c[2] I_{n−2})/(2
/// dt), I before the first step zero. kCellMidpoints: BDF2 (3, −4, 1) on every row. kCellFaces (steps >= 4):
/// BDF2 inside; with the trapezoid weights w the columns of w_n c_{n,k} satisfy, for every momentum I_k: Σ_n
/// w_n c_{n,k} = 2dx·δ_{k,last} (the strip's momentum leaves only at the transom, so the hull sum telescopes
/// exactly to U·I_T), first moments giving a second-order quadrature of iω_e∫I dx (dx/2 at the bow, 3dx/2 on
/// the last face before the transom and 0 on the transom face, which a causal difference cannot weight in
/// time) and, inside, zero second moments (the BDF2 error (ω_e dt)²). Bow rows (3), (3, −2), (3, −4, 1/2);
/// transom row (4, −6, 2).
inline std::array<double, 3> StripForceStencil(StationLayout layout, int n, int steps) {
  if (layout == StationLayout::kCellFaces) {
    if (n == steps - 1) return {4.0, -6.0, 2.0};
    if (n == 1) return {3.0, -2.0, 0.0};
    if (n == 2) return {3.0, -4.0, 0.5};
  }
  return {3.0, -4.0, 1.0};
}

/// A strip step whose 2D system is worse conditioned than this is reported (StripKernelWarnings). Measured
/// (L1 estimate, largest step of the hull): 2.7–11 for the Table 1 catamarans and monohulls and Delft 372 at
/// 40 × 14, up to 55 at 160 × 14 where the bow stations become tiny; on the generator's SWATH SW2, whose bow
/// bulb flattens into a plate thinner than its panels are long, 314–1730 at 14–28 panels, with heave and pitch
/// damping that changed sign from one resolution to the next (docs/study-14-hulls.md). 200 lies between, with a
/// factor 3.6 above the well-posed cases; 150–300 (SW2 with 20–24 panels) is a grey zone.
inline constexpr double kIllConditionedStrip = 200.0;

struct StripKernel {
  double speed_m_s = 0.0;  ///< [m/s] ship speed U
  double dx_m = 0.0;       ///< [m] strip advance per step (section spacing)
  double dt_s = 0.0;       ///< [s] time step dx/U
  double rho_kg_m3 = 0.0;  ///< [kg/m³]
  double g_m_s2 = 0.0;     ///< [m/s²]
  StationLayout layout = StationLayout::kCellMidpoints;     ///< where the steps sit (weights of the hull sum)
  std::vector<double> x_m;                                  ///< [m] station from AP held at step n
  std::vector<std::vector<Panel>> panels;                   ///< panels (all bodies in the strip) at step n
  std::vector<std::vector<Eigen::RowVectorXd>> force;       ///< force[n][m], m = 0..n [N/m per m/s]
  /// Built with StripOperatorOptions::lateral_rows only (else empty): lateral_force[n][m] (2 × P_m), the
  /// sway force per unit length (row 0, + to port) [N/m per m/s] and the roll moment per unit length about
  /// y = z = 0 of the strip (row 1, right-handed about x) [N m/m per m/s] on the section held at step n, for
  /// the same normal velocities as `force`.
  std::vector<std::vector<Eigen::MatrixXd>> lateral_force;
  /// Per step: the condition-number estimate of its 2D system (StripOperators::ConditionEstimate); empty when
  /// the builder has none (impulsive stand-in). Large values flag sections the panels cannot resolve.
  std::vector<double> system_condition;
  int Steps() const { return static_cast<int>(x_m.size()); }
  /// [m] weight of step n in the hull sums F3 = Σ weight_n f_n (dx, or dx/2 at the end faces).
  double Weight(int n) const { return StationWeight(layout, n, Steps(), dx_m); }
};

/// One message (rule and numbers) if any step's system_condition exceeds `limit`: the worst step's station
/// and value, how many steps exceed it, and the usual remedy. Empty otherwise.
std::vector<std::string> StripKernelWarnings(const StripKernel& kernel, double limit = kIllConditionedStrip);

}  // namespace hullopt::sk
