#pragma once
// A test and demonstration RAO model for the Cs fit: heave and pitch each respond as a linear damped
// oscillator in the encounter frequency, with a damping ratio that grows linearly with Cs,
//   X/A = 1 / (1 − r² + 2iζr),  r = ω_e/ω_n,  ζ = ζ0 + ζ_Cs·Cs,
// so that |X/A| → 1 as ω_e → 0 (like heave x3/A and pitch x5/(kA) of a ship) and the peak 1/(2ζ·sqrt(1 − ζ²))
// falls as Cs grows. It is NOT a ship-motion model; it stands in for one in tests, the benchmark and the demo
// config until the strip solver is wired to `hullopt calibrate`.
#include <string>
#include <vector>

#include "calibration/fit/cs_calibration.h"

namespace hullopt::calib {

struct SyntheticOscillatorOptions {
  double heave_natural_rad_s = 8.0;  ///< [rad/s] ω_n of heave (in encounter frequency)
  double pitch_natural_rad_s = 8.5;  ///< [rad/s] ω_n of pitch
  double heave_zeta0 = 0.10;         ///< [-] heave damping ratio at Cs = 0
  double pitch_zeta0 = 0.12;         ///< [-] pitch damping ratio at Cs = 0
  double heave_zeta_per_Cs = 2.0;    ///< [-] dζ/dCs of heave
  double pitch_zeta_per_Cs = 1.5;    ///< [-] dζ/dCs of pitch
  double length_m = 3.0;  ///< [m] ship length L: converts λ/L and Fn to ω_e for rows without ω_e
  double g_m_s2 = 9.81;   ///< [m/s²]

  bool IsValid(std::string* error) const;
};

/// The model for the given cases (copied). Throws std::invalid_argument for invalid options.
CsRaoModel MakeSyntheticOscillatorModel(const SyntheticOscillatorOptions& options,
                                        const std::vector<opt::CalibrationCase>& cases);

}  // namespace hullopt::calib
