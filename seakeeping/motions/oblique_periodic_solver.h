#pragma once
// The time-domain strip method's periodic steady state (periodic_motion_solver.h) at any heading, for sway,
// heave, roll, pitch and yaw (docs/ship-motions.md, "Oblique seas in the time-domain strip method").
//
// Axes, dofs and the heading as oblique_strip_theory.h: x forward, y to port, z up; sway + to port, heave +
// up, roll + starboard down, pitch + bow down, yaw + bow to port, rotations about the CG; β the direction the
// waves travel (180° head seas, 90° beam seas from starboard); wave Re[A e^{i(ω_e t − k(x cosβ + y sinβ))}]
// with x from the CG, ω_e = ω − kU cosβ; motions Re[X e^{iω_e t}].
//
// Every strip is the same strip shifted in time, as in head seas, and its kernel now gives three rows per
// (n, m): the sway force, the vertical force and the roll moment about y = z = 0 per unit length on the
// section held at step n from the normal velocities of step m (strip_kernel.h, lateral_force). A section at x
// moving with the ship has, seen in the earth-fixed strip (∂/∂t − U ∂/∂x of its displacement), the normal
// velocity per unit amplitude of
//   sway iω_e n_y,  heave iω_e n_z,  roll iω_e (y n_z − (z − z_G) n_y),  pitch (U − iω_e x) n_z,
//   yaw (iω_e x − U) n_y,
// and the oblique wave's orbital velocity (v, w) = ω A e^{kz} (sinβ, i) e^{iθ} enters as −(v n_y + w n_z),
// varying across the section as e^{−ik y sinβ}. The hull sums: F2 = Σ w f_y, F3 = Σ w f_z, F4 = Σ w (m_x +
// z_G f_y), F5 = −Σ w x f_z, F6 = Σ w x f_y. Froude–Krylov: the incident pressure ρ g A e^{kz} e^{iθ} over
// each section's wetted panels (exact along straight panels), without the n_x (longitudinal slope) part that
// the head-sea path leaves out too. Heave and pitch keep the head-sea path's hydrostatic strip sums and the
// Cs damping ½ Cs ρ U ∫(v − ζ_t) dy over the waterline (the wave's ζ_t varying across it), so that at
// β = 180° heave and pitch are the head-sea periodic path's to round-off; roll takes C44 = ρ g V GM_T and the
// optional viscous roll damping of oblique_strip_theory.h (ObliqueRestoring, ObliqueViscousRollB44). Surge is
// left out, as in the oblique strip theory.
#include <Eigen/Dense>
#include <complex>
#include <functional>
#include <vector>

#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/oblique_strip_theory.h"

namespace hullopt::sk {

/// The strip force with lateral rows in periodic steady state: f̃_n = Σ_{m = first_step(n)}^{n}
/// e^{−iω_e(n−m)Δt} dot(n, m, Ṽ_m, ω_e), dot the (sway force, vertical force, roll moment about y = z = 0)
/// per unit length on the section of step n from complex normal velocities Ṽ on the panels of step m.
struct ObliquePeriodicStripForce {
  std::function<int(int n)> first_step;
  std::function<Eigen::Vector3cd(int n, int m, const Eigen::VectorXcd& v, double omega_e)> dot;
};

/// The time-domain kernel with lateral rows (StripOperatorOptions::lateral_rows) as a strip force: rows
/// (lateral_force[n][m] row 0, force[n][m], lateral_force[n][m] row 1). kernel must outlive the result.
/// Throws std::invalid_argument when the kernel has no lateral rows.
ObliquePeriodicStripForce KernelObliqueStripForce(const StripKernel& kernel);

/// The settings beyond the head-sea model's: the CG height, the roll and yaw inertia and the viscous roll
/// damping (oblique_strip_theory.h).
struct ObliquePeriodicOptions {
  /// z_g_m and the inertia; its mass_kg and I55 are replaced by the model's mass and pitch inertia and x_g_m
  /// by the model's LCG (its stations' x from the CG).
  ObliqueMassProperties mass;
  /// Only roll_damping and roll_damping_hull are used (rho, g and speed replaced by the model's).
  ObliqueStripOptions roll;
  bool IsValid(std::string* error) const;
};

/// Sway, heave, roll, pitch and yaw at every heading [deg, finite] and wave frequency [rad/s, > 0], the
/// periodic steady state of the strip equations (exact motion derivatives iω_e). The result is laid out as
/// the oblique strip theory's (waves heading-major; frequencies empty; hydrostatics from the kernel's panels;
/// added_mass and damping with the speed terms and the Cs damping; froude_krylov, diffraction (with the Cs
/// damping's wave part) and excitation; rao: translations per A, rotations per kA). Throws
/// std::invalid_argument for bad options, an empty heading list or an empty or non-positive frequency list,
/// and std::domain_error for an encounter frequency <= 0 (following and quartering seas at speed) or a
/// non-finite RAO (HeadSeaShipModel::ReportNonFinite). Frequencies are solved in parallel (identical results
/// for any thread count).
ObliqueStripResult SolveObliquePeriodic(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                                        const std::vector<double>& headings_deg,
                                        const ObliquePeriodicOptions& options,
                                        const ObliquePeriodicStripForce& strip);

/// The same with the model's kernel (KernelObliqueStripForce(model.kernel())).
ObliqueStripResult SolveObliquePeriodic(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                                        const std::vector<double>& headings_deg,
                                        const ObliquePeriodicOptions& options);

}  // namespace hullopt::sk
