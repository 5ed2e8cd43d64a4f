#pragma once
// Calm water on the strips of the instantaneous hull: the steady force of the hull passing through strips of
// water fixed in space, and the running sinkage and trim that balance it (docs/ship-motions.md, "Calm water and
// the running attitude").
//
// In calm water every strip sees the same history: the bow enters it, the sections at stations x_0 > x_1 > ...
// pass through it one step dt = dx/U apart, and the transom leaves it. One strip march therefore gives the
// steady sectional force f(x) of the whole hull: the disturbance flow of the section's growth and shrinking
// (the body condition is the contour's own normal speed, contour_motion.h), with the transient free-surface
// Green function, reduced to a force by the chosen sectional-force form. The hull's steady vertical force is
//   F3 = Σ_n (f_n + ρ g (A_n − A⁰_n)) w_n,      F5 = −Σ_n (x_n − x_G) (f_n + ρ g (A_n − A⁰_n)) w_n  (+ bow down),
// A_n the section's immersed area at the attitude, A⁰_n at rest, w_n the station weights: the hull as given
// floats freely at rest, so its weight and the weight's moment are the strips' own buoyancy at rest. The
// attitude is then the speed's effect alone, not a mismatch between a stated mass and the discretised hull.
// The running attitude is the sinkage and trim at which F3 = F5 = 0, found by Newton steps on the hydrostatic
// stiffness of the current attitude (the hydrodynamic force's own change with attitude is left to the
// iteration, which converges linearly while it is small against the hydrostatic one).
//
// What the model holds and does not: a linear free surface and deep water (a tank of depth h adds the depth
// Froude number U/√(gh) effects the kernel cannot see), no spray, no breaking, stations vertical; the force is
// linear in the contour's normal speed, so the steady displacement flow is the only source of the sinkage and
// trim (no quadratic Bernoulli suction). Below Fn ≈ 0.5 the strip assumption ∂/∂x ≪ ∂/∂y, ∂/∂z of the steady
// flow fails (the hull's own wave is shorter than the hull); the result there is diagnostic only.
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "parametric_hull/running_attitude.h"
#include "seakeeping/strip/strip_geometry.h"
#include "seakeeping/strip/strip_operators.h"

namespace hullopt::sk {

struct CalmWaterOptions {
  StripGeometryOptions geometry;  ///< sections, panels, body, spacing; layout must be kCellFaces
  SectionalForce sectional_force = SectionalForce::kMomentum;
  int max_iterations = 30;          ///< attitude iterations before giving up, >= 1
  double sinkage_tolerance_m = 1e-5;  ///< [m] last sinkage step below this ... (and)
  double trim_tolerance_deg = 1e-3;   ///< [deg] ... last trim step below this: converged
  /// Also the steady elevation at the hull's water line (SteadyForce::elevation_*): one more set of strip
  /// operators per side. SolveRunningAttitude computes it at the converged attitude only.
  bool elevation = false;
  /// Also the 2D+t wave resistance (SteadyForce::wave_resistance_N, strip_power.h): the power of the strips'
  /// dynamic pressure on the moving contours, about ten times the cost of the force alone.
  /// SolveRunningAttitude computes it at the converged attitude only.
  bool wave_resistance = false;
  bool IsValid(std::string* error) const;
};

/// The steady force of the hull at one attitude.
struct SteadyForce {
  double heave_N = 0.0;     ///< [N] F3: hydrodynamic + buoyancy − weight (the buoyancy at rest), + up
  double moment_N_m = 0.0;  ///< [N m] F5 about the centre of gravity, + bow down
  double hydrodynamic_heave_N = 0.0;     ///< [N] the strips' part of F3 (+ up)
  double hydrodynamic_moment_N_m = 0.0;  ///< [N m] the strips' part of F5 (+ bow down)
  std::vector<double> x_m;                 ///< [m from AP] stations, bow first
  std::vector<double> force_N_per_m;       ///< [N/m] steady hydrodynamic force per unit length f_n, + up
  std::vector<double> buoyancy_N_per_m;    ///< [N/m] ρ g A_n at the attitude
  /// [m] with options.elevation: the linear free-surface elevation η = −φ_t/g of the steady disturbance at the
  /// water line of each station, + up, on the outer side of the bodies and (multihulls) on the inner side (the
  /// mean of the points of that side); empty without, and for a strip whose sections do not change.
  std::vector<double> elevation_outer_m, elevation_inner_m;
  /// With options.wave_resistance: the power per unit strip length the contour of each station delivers to the
  /// water [W/m] (strip_power.h), and R = Σ P_n w_n / U [N], the linear 2D+t wave resistance (the hydrostatic
  /// force missing on a dry transom is not in it). Empty and 0 without.
  std::vector<double> power_W_per_m;
  double wave_resistance_N = 0.0;
};

struct CalmWaterResult {
  hull::RunningAttitude attitude;  ///< the running sinkage (+ down) and trim (+ bow up) about the CG
  SteadyForce force;               ///< at that attitude
  int iterations = 0;
  bool converged = false;
  std::string note;  ///< why it did not converge (empty when it did)
};

/// Steady force of `at_rest` moved to `attitude` at speed U (> 0); mass.lcg_m_from_ap is the moment axis. Throws std::invalid_argument for invalid options or scalars, std::domain_error
/// for a section that cannot be panelled or an attitude ApplyRunningAttitude refuses.
SteadyForce CalmWaterForce(const hull::HullForm& at_rest, const hull::MassProperties& mass,
                           const hull::RunningAttitude& attitude, double speed_m_s, double rho_kg_m3,
                           double g_m_s2, const CalmWaterOptions& options);

/// The running attitude at speed U: iterates sinkage and trim (pivot at the centre of gravity) until F3 and F5
/// vanish. Does not throw when the iteration fails (trim beyond hull::kMaxTrimDeg, a hull lifting out, no
/// convergence within max_iterations): converged is false and note says why. Throws std::invalid_argument for
/// invalid options or scalars.
CalmWaterResult SolveRunningAttitude(const hull::HullForm& at_rest, const hull::MassProperties& mass,
                                     double speed_m_s, double rho_kg_m3, double g_m_s2,
                                     const CalmWaterOptions& options);

}  // namespace hullopt::sk
