#pragma once
// Relative vertical motion between a point of the hull and the incident wave beside it, and the probabilities
// built on it: deck wetness (the relative motion exceeds the freeboard) and slamming after Ochi (the keel
// emerges and re-enters faster than a threshold velocity). Head seas, linear, narrow-band Gaussian statistics.
//
// At x [m] forward of the CG (docs/conventions.md: s = x3 − x·x5, pitch positive bow-down) the incident head
// wave of amplitude A whose crest is at the CG at t = 0 is ζ(x, t) = A cos(ω_e t + k x): a crest reaches the
// bow before the CG. The relative motion r = s − ζ(x) (positive: the hull rises out of the wave) has the
// transfer function per unit wave amplitude
//     H_r(ω) = X3/A − x·k·X5/(kA) − e^{i k x},   k = ω²/g,
// its spectrum S_r(ω_e) = |H_r|² S_ζ(ω_e), and moments m_n = ∫ ω_eⁿ S_r dω_e, integrated in wave frequency as
// in point_response.h (same range and Simpson rule). The radiated and diffracted waves (swell-up at the bow)
// are not included.
//
// Probabilities (Rayleigh exceedance of the amplitude of a narrow-band Gaussian process, per wave encounter):
//     deck wetness  P_w = exp(−f²/(2 m0))                         f: freeboard at the station [m]
//     slamming      P_s = exp(−T²/(2 m0) − v_th²/(2 m2))          T: draught at the station [m]
//                   v_th = 0.093 √(g L) (Ochi 1964, threshold relative velocity for a slam)
//     events per hour N = 3600 · (1/2π) √(m2/m0) · P              (mean zero up-crossing rate × P)
#include <complex>
#include <string>

#include "seakeeping/motions/rao_table.h"
#include "seas/point_response.h"
#include "seas/wave_spectrum.h"

namespace hullopt::sk {

/// Ochi's (1964) threshold relative velocity for a bottom slam, as a fraction of √(g L) [-].
constexpr double kOchiThresholdVelocityFactor = 0.093;

/// H_r at one wave frequency ω [rad/s] from the complex RAOs at that frequency (heave X3/A [m/m], pitch
/// X5/(kA) [rad/rad]), x [m] forward of the CG, g [m/s²]. [m/m]
std::complex<double> RelativeMotionTransfer(std::complex<double> heave, std::complex<double> pitch_per_slope,
                                            double omega_rad_s, double x_from_cg_m, double g_m_s2);

/// Moments of the relative-motion spectrum at one station.
struct RelativeMotionMoments {
  double m0 = 0.0;  ///< [m²]     relative displacement variance
  double m2 = 0.0;  ///< [m²/s²]  relative velocity variance
  double truncated_wave_energy_fraction = 0.0;  ///< [-] wave variance outside the RAO table's range
  double rms_m() const;                 ///< √m0 [m]
  double zero_crossings_per_s() const;  ///< (1/2π) √(m2/m0) [1/s], 0 when m0 = 0
};

/// Relative motion at x forward of the CG in one sea. Throws std::invalid_argument for an invalid table or
/// options.
RelativeMotionMoments RelativeMotionAt(const RaoTable& rao, const WaveSpectrum& spectrum, double x_from_cg_m,
                                       const ResponseOptions& options = {});

/// P(amplitude > level) = exp(−level²/(2 m0)) of a narrow-band Gaussian process of variance m0 [-]; 0 when
/// m0 = 0 and level > 0. Throws std::invalid_argument for level < 0 or m0 < 0.
double RayleighExceedance(double level, double m0);

/// Deck wetness probability per encounter at a station of freeboard f [m] (> 0) [-].
double DeckWetnessProbability(double freeboard_m, const RelativeMotionMoments& r);
/// Ochi's slamming probability per encounter at a station of draught T [m] (> 0) with threshold relative
/// velocity v_th [m/s] (≥ 0) [-].
double SlammingProbability(double draught_m, double threshold_velocity_m_s, const RelativeMotionMoments& r);
/// Ochi's threshold velocity 0.093 √(g L) [m/s] for a waterline length L [m].
double OchiThresholdVelocity(double length_m, double g_m_s2);
/// Events per hour at probability p per encounter: 3600 (1/2π) √(m2/m0) p [1/h].
double EventsPerHour(double probability, const RelativeMotionMoments& r);

}  // namespace hullopt::sk
