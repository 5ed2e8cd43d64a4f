#pragma once
// A forced-oscillation test simulated as it is run in a towing tank, with the strips on the instantaneous
// hull (docs/ship-motions.md, "Forced oscillation on the instantaneous hull").
//
// The hull moves at speed U through water at rest and is forced in heave x3 = a r(t) sin ω_e t or pitch
// x5 = a r(t) sin ω_e t about its centre of gravity (r a smooth ramp over the first periods). Every strip of
// water, fixed in space, holds at each step the hull's section at that step's station cut at the water line of
// the hull's position at that time: the local draught T(x, t) = T − x3(t) + (x − x_G) x5(t) (heave up, pitch
// bow-down, stations staying vertical). Its body condition is the contour's own normal speed in the strip
// (contour_motion.h), which holds the section's growth or shrinking as the hull passes, its vertical speed
// ẋ3 − (x − x_G) ẋ5 and the U x5 of a pitched hull passing the strip, and the wetted girth coming and going;
// sections out of the water leave their step empty. A strip contributes to the hull only while the hull is in
// it: what happens in the strip after the transom has passed cannot act on the hull, so no wake condition is
// needed for the force. The hull force adds the buoyancy of the instantaneous sections (ρ g × area) and the
// Cs damping.
//
// The force is reduced as the tank reduces it: the first harmonic of heave force and pitch moment over whole
// periods after the start-up, per unit amplitude, with only the static restoring C_ij of the hull at rest
// removed; any speed-dependent or nonlinear restoring stays in A_ij:
//   A_ij = (C_ij − Re Z_ij) / ω_e²,  B_ij = Im Z_ij / ω_e,  Z_ij = −F̂_i / X̂_j,
// with x = Re(X̂ e^{iω_e t}) and F = Re(F̂ e^{iω_e t}); signs and axes as head_sea_coefficients.h.
#include <array>
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "parametric_hull/running_attitude.h"
#include "seakeeping/strip/strip_geometry.h"
#include "seakeeping/strip/strip_operators.h"

namespace hullopt::sk {

enum class ForcedMode { kHeave, kPitch };

struct ForcedOscillationOptions {
  StripGeometryOptions geometry;  ///< sections, panels, body, spacing; layout must be kCellFaces
  SectionalForce sectional_force = SectionalForce::kMomentum;
  ForcedMode mode = ForcedMode::kHeave;
  double amplitude = 0.0;      ///< [m] heave or [rad] pitch amplitude, > 0
  double omega_e_rad_s = 0.0;  ///< [rad/s] oscillation (encounter) frequency, > 0
  /// The steady running attitude the oscillation is about (even keel: the hull as given).
  hull::RunningAttitude attitude;
  /// Cs [-] of the paper's sectional damping −½ Cs ρ U B v on each section's instantaneous waterline beam B and
  /// vertical speed v (head_sea_ship_model.h), >= 0.
  double damping_cs = 0.0;
  double ramp_periods = 1.0;  ///< periods over which the amplitude grows as ½(1 − cos πt/T_ramp), >= 0
  int analysed_periods = 2;   ///< whole periods of the first-harmonic analysis, after ramp and one hull passage
  bool IsValid(std::string* error) const;
};

struct ForcedOscillationResult {
  double omega_e_rad_s = 0.0;
  /// [kg, kg m, kg m²] and [kg/s, ...]: index 0 the heave force, 1 the pitch moment, for the forced mode:
  /// heave (A33, A53), (B33, B53); pitch (A35, A55), (B35, B55).
  std::array<double, 2> added_mass{}, damping{};
  std::array<double, 2> static_restoring{};  ///< the C_i,mode removed [N/m, N, N/rad, N m/rad]
  /// [N, N m] mean heave force and pitch moment over the analysed periods (the hull's steady hydrodynamic and
  /// hydrostatic force at its attitude, less the weight is not included).
  std::array<double, 2> mean{};
  /// Second-harmonic amplitude over first-harmonic amplitude of each force: how far from linear the run is.
  std::array<double, 2> second_harmonic_ratio{};
  int strips = 0;  ///< strips computed
  std::vector<double> time_s, motion, force_N, moment_N_m;  ///< the analysed record
};

/// Simulates one forced-oscillation run of the hull (at rest geometry `at_rest`, moved to options.attitude)
/// at speed U, water density rho and gravity g; mass.lcg_m_from_ap is the oscillation axis. Throws
/// std::invalid_argument for invalid options or scalars, std::domain_error for a section that cannot be
/// panelled (naming body, x and time), a time step that cannot resolve the oscillation (ω_e Δt > π/4) or an
/// attitude or amplitude that lifts a body out of the water.
ForcedOscillationResult SimulateForcedOscillation(const hull::HullForm& at_rest, const hull::MassProperties& mass,
                                                  double speed_m_s, double rho_kg_m3, double g_m_s2,
                                                  const ForcedOscillationOptions& options);

}  // namespace hullopt::sk
