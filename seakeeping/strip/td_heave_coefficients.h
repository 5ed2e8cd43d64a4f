#pragma once
// Heave added mass and damping per unit length of a fixed 2D section (or several sections sharing a strip,
// heaving in phase) from the time-domain solver (`hullopt section`, docs/sections.md).
//
// Method: the exact periodic steady state of the time-marching scheme. For a section that does not change,
// the operators depend on the lag only, so with V_n = n_z e^{iωt_n} the sources are σ_n = σ̂ e^{iωt_n},
//   [System − Σ_{l>=1} LagMemory(l) e^{−iωl·dt}] σ̂ = n_z,
//   Î = [MomentumCurrent + Σ_{l>=1} LagMomentum(l) e^{−iωl·dt}] σ̂,
// i.e. the impulse response of the scheme Fourier-transformed, with no start-up transient. The lag sum runs
// to a horizon where the slowest (near-surface) Cauchy–Poisson memory has decayed by e^{−memory_decay};
// beyond it the memory potential is the position-independent 4/t tail of G~, summed in closed form through
// the complex exponential integral E1. The force f = dI/dt = iω Î per unit heave velocity gives
//   a33 = −Re Î [kg/m],   b33 = ω Im Î [kg/(m s)]   (f = −a33 ẍ3 − b33 ẋ3).
#include <Eigen/Dense>
#include <array>
#include <complex>
#include <string>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/strip/strip_operators.h"

namespace hullopt::sk {

struct TimeDomainSectionOptions {
  int steps_per_period = 40;   ///< time steps per period of the highest frequency requested
  double memory_decay = 10.0;  ///< horizon: near-surface memory decayed by e^{−memory_decay}
  int max_lags = 6000;         ///< cap on the lag horizon (cost is linear in it)
  StripOperatorOptions operators;
  bool IsValid(std::string* error) const;
};

struct HeaveCoefficients {
  std::vector<double> omega_rad_s;
  std::vector<double> a33_kg_per_m;
  std::vector<double> b33_kg_per_m_s;
  /// Damping from the far-field radiated wave energy flux of the same solution, ρg²(|A+|² + |A−|²)/(2ω): an
  /// energy-balance check of b33 (agrees to the O(1/N) panel error).
  std::vector<double> b33_energy_kg_per_m_s;
  double a33_infinite_kg_per_m = 0.0;  ///< impulsive (t = 0+) added mass: the ω → ∞ limit
  double dt_s = 0.0;                   ///< time step used
  int lags = 0;                        ///< lag horizon used (steps)
};

/// Heave coefficients at the frequencies omega_rad_s (> 0) of the section(s) `panels` (all heaving together).
/// Throws std::invalid_argument for empty or non-positive frequencies, bad options or bad panels.
HeaveCoefficients TimeDomainHeaveCoefficients(const std::vector<Panel>& panels,
                                              const std::vector<double>& omega_rad_s, double rho, double g,
                                              const TimeDomainSectionOptions& options = {});

/// Steady-state complex source amplitudes σ̂ [m/s per m/s of heave velocity] at one ω (V = n_z e^{iωt}), from
/// built time-invariant operators; lags <= ops.Steps() − 1.
Eigen::VectorXcd SteadyHeaveSources(const StripOperators& ops, double omega_rad_s, int lags);

/// Far-field radiated wave amplitudes [m per m/s of heave velocity] towards +y and −y of the steady state
/// with source amplitudes σ̂ on `panels`: the memory part of the potential behaves like i σ̂ e^{K(z+ζ)}
/// e^{−iK|y−η|} far away (K = ω²/g), so |A±| = (ω/g) |Σ_j σ̂_j ∫_j e^{Kζ ± iKη} ds|. Energy balance: b33 = ρ
/// g² (|A+|² + |A−|²)/(2ω).
std::array<double, 2> FarFieldWaveAmplitudes(const std::vector<Panel>& panels, const Eigen::VectorXcd& sigma,
                                             double omega_rad_s, double g);

/// Steady-state complex momentum response Î [kg/m] per unit heave velocity at one ω, from built
/// time-invariant operators (exposed for tests and for callers that reuse the operators). lags <= ops.Steps()
/// − 1.
std::complex<double> SteadyHeaveMomentum(const StripOperators& ops, double omega_rad_s, int lags);

}  // namespace hullopt::sk
