#include "calibration/fit/synthetic_oscillator_rao.h"

#include <cmath>
#include <stdexcept>

#include "optimizer/tank_rao_frequency.h"

namespace hullopt::calib {
namespace {
std::complex<double> Oscillator(double omega_e, double omega_n, double zeta) {
  const double r = omega_e / omega_n;
  return 1.0 / std::complex<double>(1.0 - r * r, 2.0 * zeta * r);
}
}  // namespace

bool SyntheticOscillatorOptions::IsValid(std::string* error) const {
  auto positive = [&](double v, const char* name) {
    if (std::isfinite(v) && v > 0) return true;
    if (error) *error = std::string(name) + " = " + std::to_string(v) + ": must be a finite number > 0";
    return false;
  };
  auto nonneg = [&](double v, const char* name) {
    if (std::isfinite(v) && v >= 0) return true;
    if (error) *error = std::string(name) + " = " + std::to_string(v) + ": must be a finite number >= 0";
    return false;
  };
  return positive(heave_natural_rad_s, "heave_natural_rad_s") &&
         positive(pitch_natural_rad_s, "pitch_natural_rad_s") && positive(heave_zeta0, "heave_zeta0") &&
         positive(pitch_zeta0, "pitch_zeta0") && nonneg(heave_zeta_per_Cs, "heave_zeta_per_Cs") &&
         nonneg(pitch_zeta_per_Cs, "pitch_zeta_per_Cs") && positive(length_m, "length_m") &&
         positive(g_m_s2, "g_m_s2");
}

CsRaoModel MakeSyntheticOscillatorModel(const SyntheticOscillatorOptions& o,
                                        const std::vector<opt::CalibrationCase>& cases) {
  std::string error;
  if (!o.IsValid(&error)) throw std::invalid_argument("synthetic oscillator model: " + error);
  // Encounter frequencies once per case (the analogue of the Cs-independent strip kernels).
  std::vector<std::vector<double>> omega_e(cases.size());
  for (std::size_t c = 0; c < cases.size(); ++c)
    for (const auto& p : cases[c].points)
      omega_e[c].push_back(opt::PointEncounterFrequency(p, o.length_m, o.g_m_s2));
  return [o, omega_e](double Cs, int case_index) {
    RaoPrediction r;
    for (double w : omega_e.at(case_index)) {
      r.heave.push_back(Oscillator(w, o.heave_natural_rad_s, o.heave_zeta0 + o.heave_zeta_per_Cs * Cs));
      r.pitch.push_back(Oscillator(w, o.pitch_natural_rad_s, o.pitch_zeta0 + o.pitch_zeta_per_Cs * Cs));
    }
    return r;
  };
}

}  // namespace hullopt::calib
