#pragma once
// Measured head-sea RAOs (towing tank or trials) grouped into calibration cases: the input of the Cs fit.
// Conventions as in seakeeping/rao_table.h: heave |x3|/A [m/m], pitch |x5|/(kA) [rad/rad], k = ω²/g, phases
// in degrees relative to the wave crest at the CG, lead positive.
#include <string>
#include <vector>

namespace hullopt::opt {

/// One measured row of a tank RAO file.
struct TankRaoPoint {
  double Fn = 0.0;                 ///< [-] Froude number U/sqrt(gL) of the run
  bool has_omega_e = false;        ///< the file gives the encounter frequency
  double omega_e_rad_s = 0.0;      ///< [rad/s] encounter frequency (when has_omega_e)
  bool has_lambda_over_L = false;  ///< the file gives the wave length ratio
  double lambda_over_L = 0.0;      ///< [-] wave length over ship length (when has_lambda_over_L)
  double heave_amp = 0.0;          ///< [m/m] |x3|/A
  double pitch_amp = 0.0;          ///< [rad/rad] |x5|/(kA)
  bool has_heave_phase = false;
  double heave_phase_deg = 0.0;  ///< [deg] phase of x3, lead positive
  bool has_pitch_phase = false;
  double pitch_phase_deg = 0.0;  ///< [deg] phase of x5, lead positive
  std::string source;            ///< "file:line" of the row, for messages and residual tables
};

/// The measured points of one hull at one speed. The RAO model of the fit predicts the RAOs of a case at
/// exactly these points, in this order.
struct CalibrationCase {
  std::string label;                 ///< e.g. "Fn 0.75" or "hullA Fn 0.75"
  std::string hull;                  ///< hull name ("" for the config's single hull)
  double Fn = 0.0;                   ///< [-] Froude number of the case
  double hull_parameter = 0.0;       ///< p of Cs = a + b·p (mode linear_in_parameter), e.g. B/T
  std::vector<TankRaoPoint> points;  ///< at least one
};

}  // namespace hullopt::opt
