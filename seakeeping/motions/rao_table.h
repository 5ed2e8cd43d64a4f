#pragma once
// Complex heave and pitch response amplitude operators of one design at one speed in head seas: the hand-over
// from the ship-motion solvers to spectra, accelerations and MSI.
//
// Conventions (docs/conventions.md): ship axes x forward, z up, origin at the CG; heave x3 positive up, pitch
// x5 positive bow-down. Regular head wave of amplitude A with elevation A cos(ω_e t) at the CG.
// heave = X3 / A [m/m], pitch = X5 / (k A) [rad/rad], k = ω²/g; phase = arg, lead positive, relative to the wave
// crest at the CG. Vertical displacement at x forward of the CG: s = x3 − x·x5.
#include <complex>
#include <string>
#include <vector>

namespace hullopt::sk {

struct RaoTable {
  double speed_m_s = 0.0;                    ///< [m/s] ship speed U
  double g_m_s2 = 9.81;                      ///< [m/s²] gravity used (k = ω²/g)
  std::vector<double> omega_rad_s;           ///< [rad/s] wave frequency ω, increasing
  std::vector<double> omega_e_rad_s;         ///< [rad/s] encounter frequency ω_e = ω + ω²U/g
  std::vector<std::complex<double>> heave;   ///< X3/A [m/m]
  std::vector<std::complex<double>> pitch;   ///< X5/(kA) [rad/rad]: pitch per wave slope amplitude
  /// Numerical warnings of the solve (rule and numbers), e.g. near-singular strip sections; empty when none.
  std::vector<std::string> warnings;
};

}  // namespace hullopt::sk
