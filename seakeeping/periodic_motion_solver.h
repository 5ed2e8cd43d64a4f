#pragma once
// Path 2b (ARCHITECTURE §5): heave and pitch RAOs as the periodic steady state over one strip kernel.
//
// At steady state every strip is the same strip shifted by whole time steps, so the force on the section held
// at step n is f̃_n = Σ_{m ≤ n} e^{−iω_e (n−m)Δt} force[n][m] · Ṽ_m, with Ṽ_m the complex amplitude of the
// panel normal velocities at station m. Heave, pitch and wave inputs are linear, which gives one 2×2 complex
// system per frequency: [−ω_e² M − F3,3 , −F3,5 ; −F5,3 , −ω_e² I5 − F5,5] [X3 ; X5] = [F3,A ; F5,A] A.
// Motion derivatives are exact (iω_e), so this is the continuous-time steady state of the strip equations.
#include <vector>

#include "seakeeping/head_sea_ship_model.h"
#include "seakeeping/rao_table.h"

namespace hullopt::sk {

/// RAOs at the wave frequencies omega_rad_s [rad/s] (> 0, increasing). Frequencies are solved in parallel
/// with OpenMP (identical results for any thread count). Throws std::domain_error (via
/// HeadSeaShipModel::ReportNonFinite) naming the hull and frequency if a result is not finite, and
/// std::invalid_argument for an empty or non-positive frequency list.
RaoTable SolvePeriodicRaos(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s);

}  // namespace hullopt::sk
