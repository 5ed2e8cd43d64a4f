#pragma once
// Deep-water regular and irregular head waves seen from a ship moving at speed U (docs/conventions.md).
//
// Earth frame: the ship advances in +X at speed U; the CG is at X = U t; head waves travel in −X. In ship
// axes (x forward of the CG) a component of amplitude A, wave frequency ω and phase ε has the elevation
//   ζ(x, t) = A cos(ω_e t + k x + ε),   k = ω²/g,   ω_e = ω + ω²U/g,
// so with ε = 0 the crest is at the CG at t = 0 (the RAO phase reference) and crests ahead of the CG arrive
// earlier (phase lead k x). The incident potential φ_I = −(gA/ω) e^{kz} sin(ωt + kX) gives, in a strip fixed
// in space (the earth frame, where the strip solver works), the vertical orbital velocity
//   w(x, z, t) = −ω A e^{kz} sin(ω_e t + k x + ε)   (the earth-frame rate uses ω, not ω_e)
// and the Froude–Krylov pressure p = −ρ ∂φ_I/∂t = ρ g e^{kz} ζ(x, t). The transverse orbital velocity is zero
// in head seas, and the longitudinal one lies outside the strip plane.
#include <vector>

#include "seakeeping/motions/encounter_frequency.h"

namespace hullopt::sk {

// Encounter frequency: HeadSeaEncounterFrequency / HeadSeaWaveFrequency in encounter_frequency.h.
/// Deep-water wave frequency ω [rad/s] of wave length λ [m]: ω = √(2πg/λ).
double WaveFrequencyFromLength(double wave_length_m, double g_m_s2);
/// Deep-water wave length λ = 2πg/ω² [m].
double WaveLength(double omega_rad_s, double g_m_s2);

/// One regular component of a head sea.
struct WaveComponent {
  double amplitude_m = 0.0;  ///< [m] A
  double omega_rad_s = 0.0;  ///< [rad/s] wave frequency ω
  double phase_rad = 0.0;    ///< [rad] ε (0: crest at the CG at t = 0)
};

/// A head sea as a sum of regular components, as seen from a ship at speed U.
class HeadSea {
 public:
  HeadSea(std::vector<WaveComponent> components, double speed_m_s, double g_m_s2);
  /// Elevation ζ(x, t) [m] at x [m] forward of the CG, time t [s].
  double Elevation(double x_m, double t_s) const;
  /// Earth-frame vertical orbital velocity w(x, z, t) [m/s] at depth z ≤ 0 [m]; at z = 0 it is the rate of
  /// rise of the local water surface seen from a strip fixed in space.
  double VerticalVelocity(double x_m, double z_m, double t_s) const;
  const std::vector<WaveComponent>& components() const { return components_; }

 private:
  struct Term {
    double a, omega, omega_e, k, phase;
  };
  std::vector<WaveComponent> components_;
  std::vector<Term> terms_;
};

}  // namespace hullopt::sk
