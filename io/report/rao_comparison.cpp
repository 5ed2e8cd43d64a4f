#include "io/report/rao_comparison.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>

#include "io/config/config_path.h"
#include "io/formats/input_error.h"
#include "io/formats/tank_rao_reader.h"
#include "optimizer/tank_rao_frequency.h"

namespace hullopt::io {

std::optional<RaoComparisonSource> ParseRaoComparison(YamlMap& root) {
  if (!root.Has("compare")) return std::nullopt;
  YamlMap c = root.Map("compare");
  RaoComparisonSource s;
  s.file = ConfigFilePath(c, "tank_rao_csv");
  s.label = c.String("label", "measured (" + std::filesystem::path(s.file).filename().string() + ")");
  s.where = c.Where("tank_rao_csv");
  c.Finish();
  return s;
}

MeasuredRao ReadRaoComparison(const RaoComparisonSource& source, double Fn, double length_m, double g_m_s2) {
  const std::string& file = source.file;
  MeasuredRao m;
  m.label = source.label;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::set<double> speeds;
  for (const auto& p : ReadTankRaoCsv(file)) {
    speeds.insert(p.Fn);
    if (std::abs(p.Fn - Fn) > kCompareFnTolerance) continue;
    const double omega = opt::PointWaveFrequency(p, length_m, g_m_s2);
    m.omega_e_rad_s.push_back(opt::PointEncounterFrequency(p, length_m, g_m_s2));
    m.lambda_over_L.push_back(2.0 * M_PI * g_m_s2 / (omega * omega) / length_m);
    m.heave_amp.push_back(p.heave_amp);
    m.pitch_amp.push_back(p.pitch_amp);
    m.heave_phase_deg.push_back(p.has_heave_phase ? p.heave_phase_deg : nan);
    m.pitch_phase_deg.push_back(p.has_pitch_phase ? p.pitch_phase_deg : nan);
  }
  if (m.heave_amp.empty()) {
    std::string list;
    for (double s : speeds) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%s%g", list.empty() ? "" : ", ", s);
      list += buf;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", Fn);
    throw InputError(source.where + ": " + file + " has no row at the run's Fn " + buf + " (rows at Fn " +
                     list + ")");
  }
  return m;
}

std::optional<MeasuredRao> ReadRaoComparison(YamlMap& root, double Fn, double length_m, double g_m_s2) {
  const std::optional<RaoComparisonSource> source = ParseRaoComparison(root);
  if (!source) return std::nullopt;
  return ReadRaoComparison(*source, Fn, length_m, g_m_s2);
}

}  // namespace hullopt::io
