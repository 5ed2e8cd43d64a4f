#pragma once
// Path 2b (docs/ship-motions.md): heave and pitch RAOs as the periodic steady state over one strip kernel.
//
// At steady state every strip is the same strip shifted by whole time steps, so the force on the section held
// at step n is f̃_n = Σ_{m ≤ n} e^{−iω_e (n−m)Δt} force[n][m] · Ṽ_m, with Ṽ_m the complex amplitude of the
// panel normal velocities at station m. Heave, pitch and wave inputs are linear, which gives one 2×2 complex
// system per frequency: [−ω_e² M − F3,3 , −F3,5 ; −F5,3 , −ω_e² I5 − F5,5] [X3 ; X5] = [F3,A ; F5,A] A.
// Motion derivatives are exact (iω_e), so this is the continuous-time steady state of the strip equations.
#include <Eigen/Dense>
#include <array>
#include <complex>
#include <functional>
#include <vector>

#include "seakeeping/motions/head_sea_coefficients.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/rao_table.h"

namespace hullopt::sk {

/// The strip force in periodic steady state, generalised: f̃_n = Σ_{m = first_step(n)}^{n} e^{−iω_e(n−m)Δt}
/// dot(n, m, Ṽ_m, ω_e). The time-domain kernel gives dot = force[n][m]·Ṽ (real rows, any ω_e); a
/// frequency-domain strip theory gives complex, ω_e-dependent rows (strip_theory_stf.h).
struct PeriodicStripForce {
  std::function<int(int n)> first_step;
  std::function<std::complex<double>(int n, int m, const Eigen::VectorXd& v, double omega_e)> dot;
};

/// How motion, velocity and acceleration amplitudes relate. kExact: v = iω_e x, a = −ω_e² x (the steady state
/// of the strip equations in continuous time). kTrapezoid: v = iΩ x, a = −Ω² x with Ω = (2/Δt) tan(ω_e Δt/2),
/// the steady state of the time-marching scheme (Newmark average acceleration, passes converged) to
/// round-off; the two differ by the trapezoid frequency warp (ω_e Δt)²/12.
enum class PeriodicKinematics { kExact, kTrapezoid };

/// The coefficients of the 2×2 system at one wave frequency ω [rad/s] (head_sea_coefficients.h): the strip
/// force's response to unit heave, unit pitch (radiation, with the forward-speed terms) and the unit wave
/// (diffraction), plus the hydrostatic, Froude–Krylov and Cs parts. No finiteness check.
HeadSeaCoefficients PeriodicCoefficients(const HeadSeaShipModel& model, double omega_rad_s,
                                         const PeriodicStripForce& strip,
                                         PeriodicKinematics kinematics = PeriodicKinematics::kExact);

/// PeriodicCoefficients at each frequency (> 0; in parallel, identical for any thread count).
std::vector<HeadSeaCoefficients> PeriodicCoefficientSweep(
    const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s, const PeriodicStripForce& strip,
    PeriodicKinematics kinematics = PeriodicKinematics::kExact);

/// The time-domain kernel as a periodic strip force: dot = force[n][m]·Ṽ. kernel must outlive the result.
PeriodicStripForce KernelStripForce(const StripKernel& kernel);

/// X3/A and X5/(kA) at one wave frequency ω [rad/s]: PeriodicCoefficients(...).Solve() (no finiteness check).
std::array<std::complex<double>, 2> SolvePeriodicFrequency(
    const HeadSeaShipModel& model, double omega_rad_s, const PeriodicStripForce& strip,
    PeriodicKinematics kinematics = PeriodicKinematics::kExact);

/// RAOs with a general strip force (frequencies in parallel; std::domain_error for non-finite results).
RaoTable SolvePeriodicRaos(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                           const PeriodicStripForce& strip,
                           PeriodicKinematics kinematics = PeriodicKinematics::kExact);

/// RAOs at the wave frequencies omega_rad_s [rad/s] (> 0, increasing). Frequencies are solved in parallel
/// with OpenMP (identical results for any thread count). Throws std::domain_error (via
/// HeadSeaShipModel::ReportNonFinite) naming the hull and frequency if a result is not finite, and
/// std::invalid_argument for an empty or non-positive frequency list.
RaoTable SolvePeriodicRaos(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                           PeriodicKinematics kinematics = PeriodicKinematics::kExact);

}  // namespace hullopt::sk
