#pragma once
// Head-sea (heading 180°) encounter frequency on deep water: ω_e = ω + ω²U/g (docs/evaluate.md, 'Method').
// The map ω → ω_e is monotone for U ≥ 0 (dω_e/dω = 1 + 2ωU/g > 0), so a head-sea spectrum transforms without
// the following-sea singularity: S(ω_e) = S(ω) / (dω_e/dω), which keeps ∫ S dω_e = ∫ S dω.
#include <cmath>

namespace hullopt::sk {

/// Encounter frequency ω_e [rad/s] of wave frequency ω [rad/s] at speed U [m/s] in head seas.
inline double HeadSeaEncounterFrequency(double omega, double speed_m_s, double g_m_s2) {
  return omega + omega * omega * speed_m_s / g_m_s2;
}

/// Wave frequency ω [rad/s] met at encounter frequency ω_e [rad/s] in head seas (the positive root).
inline double HeadSeaWaveFrequency(double omega_e, double speed_m_s, double g_m_s2) {
  if (speed_m_s <= 0.0) return omega_e;
  const double c = 4.0 * speed_m_s * omega_e / g_m_s2;
  // (−1 + √(1 + c)) g/(2U), written as 2ω_e/(1 + √(1 + c)) to avoid cancellation at small c.
  return 2.0 * omega_e / (1.0 + std::sqrt(1.0 + c));
}

/// dω_e/dω = 1 + 2ωU/g [-].
inline double HeadSeaEncounterJacobian(double omega, double speed_m_s, double g_m_s2) {
  return 1.0 + 2.0 * omega * speed_m_s / g_m_s2;
}

}  // namespace hullopt::sk
