#pragma once
// Random-phase realisations of a long-crested head sea, for time-domain simulation (the time-marching path)
// and for checking spectral statistics against time series (docs/evaluate.md, 'Verification (tests)': rms and
// mean |a| of a long record must match σ_a and 0.798 σ_a).
//
// The wave spectrum is split into N equal bins in wave frequency ω; each component has amplitude
// a_i = √(2 S(ω_i) Δω), a uniform random phase φ_i and a frequency drawn uniformly inside its bin (so the
// record does not repeat after 2π/Δω). Elevation at the CG, seen from the ship: ζ(t) = Σ a_i cos(ω_e,i t +
// φ_i). Random numbers: std::mt19937_64 with the given seed, mapped to [0, 1) by the top 53 bits, so a seed
// gives the same sea on every platform.
#include <cstdint>
#include <string>
#include <vector>

#include "seakeeping/motions/rao_table.h"
#include "seas/wave_spectrum.h"

namespace hullopt::sk {

/// One random-phase component (named apart from head_sea_wave.h's WaveComponent, which the marcher takes:
/// the two structs shared a name in one namespace, an ODR clash that kept both headers out of one file).
struct IrregularSeaComponent {
  double omega_rad_s = 0.0;    ///< [rad/s] wave frequency
  double omega_e_rad_s = 0.0;  ///< [rad/s] encounter frequency in head seas
  double amplitude_m = 0.0;    ///< [m]
  double phase_rad = 0.0;      ///< [rad]
};

struct IrregularSeaOptions {
  int components = 400;        ///< number of frequency bins (≥ 10)
  double omega_min_rad_s = 0;  ///< [rad/s] lower end of the band; 0 = 0.2 ωp
  double omega_max_rad_s = 0;  ///< [rad/s] upper end of the band; 0 = 5 ωp
  std::uint64_t seed = 1;
  bool IsValid(std::string* error) const;
};

/// Components of one realisation at speed U [m/s] (head seas). Throws std::invalid_argument for bad options.
std::vector<IrregularSeaComponent> IrregularSeaComponents(const WaveSpectrum& spectrum, double speed_m_s,
                                                          double g_m_s2,
                                                          const IrregularSeaOptions& options = {});

/// Wave elevation at the CG ζ(t) [m] at time t [s].
double WaveElevationAtCg(const std::vector<IrregularSeaComponent>& components, double t_s);

/// Vertical acceleration [m/s²] at x [m] forward of the CG, sampled at t = i·dt, i = 0..n−1, by linear
/// superposition of the RAO responses to each component (s = x3 − x·x5, a = −ω_e² s). Components outside the
/// RAO table's ω_e range are dropped. Throws std::invalid_argument for an invalid table.
std::vector<double> PointAccelerationTimeSeries(const RaoTable& rao,
                                                const std::vector<IrregularSeaComponent>& components,
                                                double x_from_cg_m, double dt_s, int n);

}  // namespace hullopt::sk
