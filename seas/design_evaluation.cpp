#include "seas/design_evaluation.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "seakeeping/motions/rao_interpolation.h"

namespace hullopt::sk {

bool EvaluationOptions::IsValid(std::string* error) const {
  std::string e;
  if (!msi.IsValid(&e)) {
    if (error) *error = "msi: " + e;
    return false;
  }
  if (!response.IsValid(&e)) {
    if (error) *error = "response: " + e;
    return false;
  }
  return true;
}

std::vector<WaveSpectrum> BuildSpectra(const std::vector<SeaState>& seas) {
  if (seas.empty()) throw std::invalid_argument("seas: the sea list is empty; give at least one sea state");
  std::vector<WaveSpectrum> spectra;
  spectra.reserve(seas.size());
  for (size_t i = 0; i < seas.size(); ++i) {
    std::string e;
    if (!seas[i].IsValid(&e)) throw std::invalid_argument("seas[" + std::to_string(i) + "]: " + e);
    spectra.emplace_back(seas[i]);
  }
  return spectra;
}

DesignEvaluation EvaluateDesign(const RaoTable& rao, const HullExtent& hull,
                                const std::vector<SeaState>& seas,
                                const std::vector<PassengerPosition>& user_points,
                                const EvaluationOptions& options) {
  return EvaluateDesign(rao, hull, BuildSpectra(seas), user_points, options);
}

DesignEvaluation EvaluateDesign(const RaoTable& rao, const HullExtent& hull,
                                const std::vector<WaveSpectrum>& spectra,
                                const std::vector<PassengerPosition>& user_points,
                                const EvaluationOptions& options) {
  std::string e;
  if (spectra.empty())
    throw std::invalid_argument("seas: the sea list is empty; give at least one sea state");
  if (!options.IsValid(&e)) throw std::invalid_argument(e);
  if (!hull.IsValid(&e)) throw std::invalid_argument(e);
  if (!IsValidRaoTable(rao, &e)) throw std::invalid_argument(e);
  for (const auto& p : user_points)
    if (!IsValidPassengerPosition(p, hull, &e)) throw std::invalid_argument(e);

  auto positions = StandardPassengerPositions(hull.cg_to_transom_m);
  positions.insert(positions.end(), user_points.begin(), user_points.end());
  const double g = rao.g_m_s2;

  DesignEvaluation out;
  out.seas.reserve(spectra.size());
  for (const auto& spectrum : spectra) {
    SeaEvaluation se;
    se.sea = spectrum.sea();
    se.Tz_s = spectrum.Tz_s();
    se.Tp_s = spectrum.Tp_s();
    se.peak_omega_e_rad_s = PeakEncounterFrequency(spectrum, rao.speed_m_s, g);
    const SeaResponse response(rao, spectrum, options.response);
    se.truncated_wave_energy_fraction = response.truncated_wave_energy_fraction();
    se.mean.position = "mean";
    se.mean.x_from_cg_m = std::numeric_limits<double>::quiet_NaN();
    for (size_t i = 0; i < positions.size(); ++i) {
      const PointMoments m = response.Moments(positions[i].x_from_cg_m);
      PositionResult r;
      r.position = positions[i].name;
      r.x_from_cg_m = positions[i].x_from_cg_m;
      r.rms_accel_m_s2 = m.rms_acceleration_m_s2();
      r.rms_accel_g = r.rms_accel_m_s2 / g;
      r.rms_displacement_m = m.rms_displacement_m();
      r.omega_char_rad_s = MsiCharacteristicFrequency(m, options.msi.frequency);
      r.msi_pct = MotionSicknessIncidence(m, options.msi, g);
      // Checked here, where they are computed: an overflow (RAOs far too large) must not become "MSI 0 %".
      for (const auto& [q, v] : {std::pair<const char*, double>{"rms acceleration", r.rms_accel_m_s2},
                                 {"rms displacement", r.rms_displacement_m},
                                 {"MSI characteristic frequency", r.omega_char_rad_s},
                                 {"MSI", r.msi_pct}}) {
        if (std::isfinite(v)) continue;
        std::ostringstream msg;
        msg << q << " at position '" << r.position << "' in the sea Hs " << se.sea.Hs_m << " m, Tz " << se.Tz_s
            << " s is not finite (the RAOs or the spectrum overflow)";
        throw std::domain_error(msg.str());
      }
      if (i < 3) {
        se.mean.rms_accel_m_s2 += r.rms_accel_m_s2 / 3.0;
        se.mean.rms_accel_g += r.rms_accel_g / 3.0;
        se.mean.rms_displacement_m += r.rms_displacement_m / 3.0;
        se.mean.omega_char_rad_s += r.omega_char_rad_s / 3.0;
        se.mean.msi_pct += r.msi_pct / 3.0;
      }
      se.positions.push_back(r);
    }
    out.seas.push_back(std::move(se));
  }
  return out;
}

}  // namespace hullopt::sk
