#pragma once
// Motions at a point of the ship in oblique seas, from the oblique-sea strip theory's complex RAOs
// (seakeeping/motions/oblique_strip_theory.h), and their statistics in a long-crested irregular sea at the
// result's heading: rms vertical and lateral accelerations, MSI and rms roll.
//
// Conventions (docs/conventions.md, "Oblique seas"): x forward, y to port, z up, point (x, y, z) relative to
// the CG; ξ2 sway (+ port), ξ3 heave (+ up), ξ4 roll (right-handed about x: + starboard down, so a point at
// y > 0 rises by y ξ4), ξ5 pitch (+ bow down), ξ6 yaw (+ bow to port). Small rotations move the point by
//   vertical:  s_z = ξ3 + y ξ4 − x ξ5
//   lateral:   s_y = ξ2 − z ξ4 + x ξ6
// and the accelerations at the encounter frequency are −ω_e² s. The lateral acceleration a person or an
// accelerometer on deck feels is the specific force along the ship's own y axis: the kinematic acceleration
// minus gravity's component, f_y = −ω_e² s_y + g ξ4 (a roll of + ξ4 lifts the port side, the deck's y axis
// gains the upward component ξ4, and the support force g along earth's z projects g ξ4 onto it). With this
// sign a ship that follows a long beam wave (sway acceleration −ω²A sin(ωt − ky), roll kA sin(ωt − ky), ω² = gk) feels no lateral force,
// as it must. (Written with roll + port down, the same term reads − g ξ4.)
// The vertical acceleration keeps the kinematic −ω_e² s_z (the gravity term is second order), as the head-sea
// path does, so that at β = 180° these are today's head-sea values.
//
// Irregular sea: long-crested, all energy travelling at the result's heading (no spreading), wave spectrum
// S_ζ(ω). Moments are integrated in wave frequency, m_n = ∫ ω_eⁿ |H(ω)|² S_ζ(ω) dω, composite Simpson over the
// RAO range ∩ [0.2 ωp, 12 ωp] with the RAOs interpolated linearly (real and imaginary parts) in ω, exactly the
// head-sea path's range and rule (seas/point_response.h) except that the head-sea path interpolates on ω_e.
// The MSI is the head-sea path's (seas/motion_sickness.h) from the vertical displacement's moments.
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

#include "seakeeping/motions/oblique_strip_theory.h"
#include "seas/design_evaluation.h"
#include "seas/wave_spectrum.h"

namespace hullopt::eval {

/// A point of the ship relative to the CG [m]: x forward, y to port, z up.
struct ShipPoint {
  std::string name;
  double x_m = 0.0, y_m = 0.0, z_m = 0.0;
};

/// Complex motions of a point per unit wave amplitude A at one (heading, frequency) of a result.
struct PointTransfer {
  std::complex<double> vertical;              ///< s_z/A [m/m]
  std::complex<double> lateral;               ///< s_y/A [m/m]
  std::complex<double> vertical_acceleration; ///< −ω_e² s_z/A [m/s² per m]
  std::complex<double> lateral_acceleration;  ///< (−ω_e² s_y + g ξ4)/A [m/s² per m], the specific force
  std::complex<double> roll;                  ///< ξ4/A [rad/m]
};

/// The point's motions at one wave result: k = ω²/g of its wave frequency turns the rotation RAOs (per kA)
/// into rotations per A.
PointTransfer PointTransferAt(const sk::ObliqueWaveResult& wave, const ShipPoint& point, double g_m_s2);

/// Statistics of one point in one sea.
struct PointSeaStatistics {
  sk::PointMoments vertical;        ///< moments of the vertical displacement spectrum (m0, m2, m4, m6, ISO m4)
  double rms_vertical_accel_m_s2 = 0.0;
  double rms_lateral_accel_m_s2 = 0.0;  ///< of the specific force f_y
  double msi_pct = 0.0;                 ///< MSI of the vertical motion (options.msi)
};

struct ObliqueSeaStatistics {
  double heading_deg = 0.0;
  double rms_roll_rad = 0.0;
  double truncated_wave_energy_fraction = 0.0;  ///< [-] wave variance outside the integrated range
  std::vector<PointSeaStatistics> points;       ///< in the order given
};

/// The points' statistics at heading index `heading` of `result` (solved at wave frequencies shared by every
/// heading) in the long-crested sea `spectrum` travelling at that heading. Throws std::invalid_argument for a
/// heading index out of range, fewer than 2 frequencies, or invalid options.
ObliqueSeaStatistics ObliqueStatisticsInSea(const sk::ObliqueStripResult& result, std::size_t heading,
                                            double g_m_s2, const sk::WaveSpectrum& spectrum,
                                            const std::vector<ShipPoint>& points,
                                            const sk::EvaluationOptions& options = {});

}  // namespace hullopt::eval
