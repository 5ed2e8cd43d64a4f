#pragma once
// Long-crested wave spectra S_ζ(ω) [m²s/rad] of wave frequency ω [rad/s]: JONSWAP in the DNV-RP-C205 form and
// the ITTC/Bretschneider (Pierson–Moskowitz shape) two-parameter spectrum, both renormalised numerically so
// that 4√m0 = Hs exactly (docs/theory.md, 'JONSWAP period ratios': the DNV factor A_γ alone is off by
// ~0.1 %).
//
// A sea state is given by Hs with either the zero-crossing period Tz = 2π√(m0/m2) or the peak period Tp.
// Tz/Tp depends on γ only and is computed numerically from the spectrum shape (0.7774 at γ = 3.3, 0.7104 at
// γ = 1), moments taken to infinity (analytic ω⁻⁵ tail).
#include <string>

namespace hullopt::sk {

enum class SpectrumType {
  kJonswap,       ///< DNV-RP-C205 JONSWAP with peak enhancement γ, σ = 0.07 / 0.09
  kBretschneider  ///< ITTC / Bretschneider two-parameter spectrum (= JONSWAP shape with γ = 1)
};

/// Name used in configs and outputs: "jonswap", "bretschneider".
std::string SpectrumName(SpectrumType type);

/// One sea state (options struct). Exactly one of Tz_s, Tp_s is given (the other NaN).
struct SeaState {
  SpectrumType spectrum = SpectrumType::kJonswap;
  double Hs_m = 0.0;   ///< [m] significant wave height 4√m0
  double Tz_s;         ///< [s] zero-crossing period 2π√(m0/m2), or NaN when Tp_s is given
  double Tp_s;         ///< [s] peak period, or NaN when Tz_s is given
  double gamma = 3.3;  ///< [-] JONSWAP peak enhancement; must be 1 for Bretschneider

  SeaState();
  static SeaState JonswapTz(double Hs_m, double Tz_s, double gamma = 3.3);
  static SeaState JonswapTp(double Hs_m, double Tp_s, double gamma = 3.3);
  static SeaState BretschneiderTz(double Hs_m, double Tz_s);

  /// Hs > 0 (≤ 30 m); exactly one of Tz, Tp; Tz (given or implied by Tp) within 2–25 s; 1 ≤ γ ≤ 10
  /// (A_γ = 1 − 0.287 ln γ stays well positive), γ = 1 for Bretschneider.
  bool IsValid(std::string* error) const;
};

/// Tz/Tp of the spectrum shape with peak enhancement gamma (DNV σ = 0.07/0.09), by numerical moments. [-]
double ZeroCrossingToPeakPeriodRatio(double gamma);

/// A sea state's spectrum, ready to evaluate. Throws std::invalid_argument if !sea.IsValid().
class WaveSpectrum {
 public:
  explicit WaveSpectrum(const SeaState& sea);

  /// S_ζ(ω) [m²s/rad], ω [rad/s] (0 for ω ≤ 0).
  double Density(double omega_rad_s) const;
  /// n-th moment ∫_0^∞ ωⁿ S dω for n = 0, 1, 2 (tail analytic) [mⁿ... SI].
  double Moment(int n) const;

  double Hs_m() const { return sea_.Hs_m; }
  double Tp_s() const { return tp_s_; }
  double Tz_s() const { return tz_s_; }
  double omega_peak() const { return omega_p_; }  ///< [rad/s] 2π/Tp
  const SeaState& sea() const { return sea_; }

 private:
  double Shape(double omega) const;  // unnormalised DNV form
  SeaState sea_;
  double tp_s_ = 0.0, tz_s_ = 0.0, omega_p_ = 0.0;
  double scale_ = 1.0;  // numerical renormalisation so that 4√m0 = Hs
};

}  // namespace hullopt::sk
