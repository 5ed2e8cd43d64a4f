#pragma once
// Motion sickness incidence (MSI) [%] from vertical acceleration (docs/evaluate.md, 'Method').
//
// Default: O'Hanlon & McCauley in Lloyd's form (Lloyd 1989, as coded in the MSS toolbox HMmsi.m, pre-2025):
//   MSI = 100 Φ((log10(|a|/g) − μ)/0.4),  μ = −0.819 + 2.32 (log10 ω_e)²,  ω_e in rad/s, 2-hour exposure,
//   |a| = mean absolute acceleration = √(2/π) σ_a for a Gaussian process, ω_e = √(m4/m2) of the displacement
//   spectrum at the point.
// Options: the 1974 fit (O'Hanlon & McCauley, 2 h, f in Hz), McCauley et al. 1976 time-dependent form, and
// the ISO 2631-1 motion sickness dose value with vomiting incidence VI = K_m·MSDV. The 1974/1976 coefficients
// and K_m are taken from secondary summaries (docs/evaluate.md, 'Method'; not verified against the original
// reports).
#include <string>

#include "seas/point_response.h"

namespace hullopt::sk {

enum class MsiModel {
  kLloyd,                ///< O'Hanlon & McCauley, Lloyd form, 2 h (default)
  kOHanlonMcCauley1974,  ///< 1974 fit, 2 h
  kMcCauley1976,         ///< time-dependent form, exposure_h
  kIso2631Msdv           ///< ISO 2631-1 W_f weighting, MSDV, VI = K_m·MSDV, exposure_h
};
/// "lloyd", "ohanlon_mccauley_1974", "mccauley_1976", "iso_2631".
std::string MsiModelName(MsiModel model);

/// Characteristic frequency of the motion used in the MSI formula.
enum class MsiFrequency {
  kDisplacementM4M2,         ///< √(m4/m2) of the displacement spectrum (default, docs/evaluate.md, 'Method')
  kAccelerationZeroCrossing  ///< √(m6/m4): zero-crossing frequency of the acceleration
};
std::string MsiFrequencyName(MsiFrequency f);  ///< "displacement_m4_m2", "acceleration_zero_crossing"

/// Acceleration statistic fed to the O'Hanlon–McCauley forms.
enum class AccelerationStatistic {
  kMeanAbsolute,  ///< √(2/π) σ_a (default; Lloyd's convention)
  kRms            ///< σ_a
};
std::string AccelerationStatisticName(AccelerationStatistic s);  ///< "mean_absolute", "rms"

struct MsiOptions {
  MsiModel model = MsiModel::kLloyd;
  double exposure_h = 2.0;  ///< [h] exposure; the Lloyd and 1974 fits are for 2 h only
  MsiFrequency frequency = MsiFrequency::kDisplacementM4M2;
  AccelerationStatistic statistic = AccelerationStatistic::kMeanAbsolute;
  double iso_km = 1.0 / 3.0;  ///< [% per m s^-1.5] ISO 2631-1 K_m (1/3: mixed adult population)

  /// exposure 0.1–24 h and exactly 2 h for the Lloyd and 1974 fits; 0 < K_m ≤ 1.
  bool IsValid(std::string* error) const;
};

/// Standard normal CDF Φ(z).
double StandardNormalCdf(double z);
/// Lloyd form [%]: mean absolute acceleration [g], characteristic encounter frequency [rad/s].
double MsiLloyd(double mean_abs_accel_g, double omega_rad_s);
/// 1974 fit [%]: acceleration [g], frequency [Hz]. z = 2.128 log10 a − 9.277 log10 f − 5.809 (log10 f)²
/// − 1.851.
double MsiOHanlonMcCauley1974(double accel_g, double f_hz);
/// McCauley et al. 1976 [%]: 100 Φ(z_a) Φ(z_t), z_t = 1.134 z_a + 1.989 log10 t − 2.904, t [min].
double MsiMcCauley1976(double accel_g, double f_hz, double exposure_min);
/// ISO 2631-1 motion sickness dose value [m/s^1.5] of a stationary W_f-weighted rms acceleration [m/s²].
double IsoMotionSicknessDoseValue(double weighted_rms_m_s2, double exposure_s);

/// MSI [%] at a point from its displacement-spectrum moments (0 when there is no motion). Capped at 100 for
/// the ISO vomiting incidence, which is linear in MSDV. Throws std::invalid_argument for invalid options.
double MotionSicknessIncidence(const PointMoments& moments, const MsiOptions& options, double g_m_s2);

/// Characteristic encounter frequency [rad/s] used by MotionSicknessIncidence (0 when m2 or m4 is 0).
double MsiCharacteristicFrequency(const PointMoments& moments, MsiFrequency which);

}  // namespace hullopt::sk
