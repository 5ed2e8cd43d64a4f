#pragma once
// Free heave decay of a floating 2D section released from rest at an offset, predicted from frequency-domain
// added mass and damping: the reference the time-domain release is compared with (docs/theory.md, free
// decay). Linear theory, body held at x0 for t < 0 (fluid at rest) and released at t = 0:
//   x(t)/x0 = 1 − s(t),   s(t) = (2C/π) ∫_0^∞ Re H(ω) sin(ωt)/ω dω,
//   H(ω) = 1/(C − ω² (m + a33(ω)) + iω b33(ω))      (h(t) causal, so h = (2/π)∫ Re H cos ωt dω).
#include <vector>

namespace hullopt::sk {

struct FreeDecayInput {
  std::vector<double> omega_rad_s;   ///< ascending, > 0
  std::vector<double> a33_kg_per_m;  ///< at omega_rad_s
  std::vector<double> b33_kg_per_m_s;
  double a33_infinite_kg_per_m = 0;  ///< used beyond the last frequency (b33 taken as 0 there)
  double mass_kg_per_m = 0;          ///< body mass per unit length
  double restoring_n_per_m2 = 0;     ///< C = ρ g B [N/m per m]
};

/// x(t)/x0 at the given times [s] (>= 0). Coefficients are interpolated linearly in ω and held at their first
/// values below the first frequency (H → 1/C as ω → 0 regardless). The integral runs on a uniform grid fine
/// enough for the largest time (>= 64 points per period of sin ωt, <= ω_1/8) up to 4× the last frequency.
/// Throws std::invalid_argument for inconsistent sizes, fewer than 2 frequencies, or non-positive
/// mass/restoring.
std::vector<double> FreeDecayFromCoefficients(const FreeDecayInput& in, const std::vector<double>& times_s);

}  // namespace hullopt::sk
