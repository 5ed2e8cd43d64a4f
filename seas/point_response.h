#pragma once
// Vertical motion of a point on the centreline, x [m] forward of the CG, in one irregular head sea, from the
// complex RAOs (docs/evaluate.md, 'Method'): s = x3 − x·x5, so the displacement transfer function per unit
// wave amplitude is H(ω) = X3/A − x·k·(X5/(kA)) with k = ω²/g of the incident wave; S_s(ω_e) = |H|² S_ζ(ω_e),
// a = −ω_e² s, S_a = ω_e⁴ S_s. Phases matter: heave and pitch add or cancel depending on x.
//
// Moments m_n = ∫ ω_eⁿ S_s(ω_e) dω_e are integrated in wave frequency ω, which is exact and regular in head
// seas (docs/evaluate.md, 'Method'): m_n = ∫ ω_e(ω)ⁿ |H(ω_e(ω))|² S_ζ(ω) dω, composite Simpson, with the RAOs
// interpolated in complex form on ω_e. Because |H|² is quadratic in x, the sums are stored once per sea as
// three coefficient sets and every point costs O(1).
//
// Truncation: the integral covers only the RAO table's frequency range ∩ [0.2 ωp, 12 ωp] (the spectrum is
// < 1e-300 of its peak below 0.2 ωp; above 12 ωp the wave energy fraction is < 1e-4). Wave energy outside the
// integrated range is reported as truncated_wave_energy_fraction(); callers warn when it is large. The RAO
// table should span the spectrum: its upper end bounds the acceleration moment, which weights high ω_e by
// ω_e⁴.
#include <string>
#include <vector>

#include "seakeeping/motions/rao_table.h"
#include "seas/wave_spectrum.h"

namespace hullopt::sk {

struct ResponseOptions {
  int quadrature_intervals = 800;  ///< Simpson intervals in ω (even, ≥ 20)
  bool IsValid(std::string* error) const;
};

/// Moments of the vertical displacement spectrum S_s(ω_e) at one point.
struct PointMoments {
  double m0 = 0.0;         ///< [m²]        displacement variance
  double m2 = 0.0;         ///< [m²/s²]     velocity variance
  double m4 = 0.0;         ///< [m²/s⁴]     acceleration variance σ_a²
  double m6 = 0.0;         ///< [m²/s⁶]
  double m4_iso_wf = 0.0;  ///< [m²/s⁴] ISO 2631-1 W_f weighted acceleration variance ∫|W_f|² ω_e⁴ S_s dω_e

  double rms_displacement_m() const;
  double rms_acceleration_m_s2() const;  ///< σ_a = √m4
};

/// One design (RAO table) in one sea: precomputed quadrature for any point along the centreline.
class SeaResponse {
 public:
  /// Throws std::invalid_argument for an invalid table or options.
  SeaResponse(const RaoTable& rao, const WaveSpectrum& spectrum, const ResponseOptions& options = {});

  /// Moments at x [m] forward of the CG (negative aft).
  PointMoments Moments(double x_from_cg_m) const;
  /// Fraction of the wave variance m0 outside the integrated frequency range [-].
  double truncated_wave_energy_fraction() const { return truncated_fraction_; }
  /// Integrated wave-frequency range [rad/s].
  double omega_min() const { return omega_lo_; }
  double omega_max() const { return omega_hi_; }

 private:
  static constexpr int kMoments = 5;  // n = 0, 2, 4, 6 and ISO-weighted 4
  // m(x) = a − 2x b + x² c for each moment
  double a_[kMoments] = {}, b_[kMoments] = {}, c_[kMoments] = {};
  double truncated_fraction_ = 0.0, omega_lo_ = 0.0, omega_hi_ = 0.0;
};

/// Spectra on an encounter-frequency grid, for plots (Fig. 7 and response spectra).
struct EncounterSpectrumSample {
  double omega_e = 0.0;       ///< [rad/s]
  double wave = 0.0;          ///< S_ζ(ω_e) [m²s/rad]
  double displacement = 0.0;  ///< S_s(ω_e) at the point [m²s/rad] (0 when no RAO is given)
  double acceleration = 0.0;  ///< S_a(ω_e) = ω_e⁴ S_s [m²/s³ per rad]
};

/// Wave spectrum in encounter frequency, S_ζ(ω_e) = S_ζ(ω)/(1 + 2ωU/g), at n points uniformly spaced on
/// [omega_e_min, omega_e_max].
std::vector<EncounterSpectrumSample> HeadSeaEncounterSpectrum(const WaveSpectrum& spectrum, double speed_m_s,
                                                              double g_m_s2, double omega_e_min,
                                                              double omega_e_max, int n);
/// Wave, displacement and acceleration spectra at x forward of the CG over the RAO table's ω_e range.
std::vector<EncounterSpectrumSample> PointResponseSpectrum(const RaoTable& rao, const WaveSpectrum& spectrum,
                                                           double x_from_cg_m, int n);
/// ω_e [rad/s] at which S_ζ(ω_e) peaks (the modal encounter frequency of the paper's Fig. 7).
double PeakEncounterFrequency(const WaveSpectrum& spectrum, double speed_m_s, double g_m_s2);

}  // namespace hullopt::sk
