#include "io/config/operability_config.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "io/config/config_path.h"
#include "io/formats/csv_fields.h"
#include "io/formats/input_error.h"

namespace hullopt::io {

sk::ScatterDiagram ReadScatterCsv(const std::string& path, double scale) {
  std::ifstream f(path);
  if (!f) throw InputError(path + ": cannot open the scatter diagram");
  sk::ScatterDiagram d;
  std::vector<double> periods;
  std::string line;
  int n = 0;
  bool header = false;
  while (std::getline(f, line)) {
    ++n;
    const std::string where = path + ":" + std::to_string(n);
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    const std::vector<std::string> c = SplitCsvTrimmed(line);
    if (!header) {
      const std::string h = c.empty() ? "" : c[0];
      if (h == "Hs_m\\Tz_s" || h == "Hs_m/Tz_s")
        d.period_is_tp = false;
      else if (h == "Hs_m\\Tp_s" || h == "Hs_m/Tp_s")
        d.period_is_tp = true;
      else
        throw InputError(where + ": the first row must start with Hs_m\\Tz_s or Hs_m\\Tp_s, not '" + h + "'");
      for (size_t j = 1; j < c.size(); ++j) {
        const double t = ParseCsvNumber(c[j], where, "column " + std::to_string(j + 1));
        if (!(t > 0.0)) throw InputError(where + ", column " + std::to_string(j + 1) + ": period must be > 0 s");
        periods.push_back(t);
      }
      if (periods.empty()) throw InputError(where + ": no period columns");
      header = true;
      continue;
    }
    if (c.size() > periods.size() + 1)
      throw InputError(where + ": " + std::to_string(c.size()) + " cells, more than the " +
                       std::to_string(periods.size() + 1) + " of the header");
    const double hs = ParseCsvNumber(c[0], where, "column 1 (Hs_m)");
    if (!(hs > 0.0)) throw InputError(where + ", column 1: Hs must be > 0 m");
    for (size_t j = 1; j < c.size(); ++j) {
      if (c[j].empty()) continue;
      const std::string cw = where + ", column " + std::to_string(j + 1);
      const double p = ParseCsvNumber(c[j], where, "column " + std::to_string(j + 1));
      if (p < 0.0) throw InputError(cw + ": probability " + c[j] + " must be >= 0");
      if (p > 0.0) d.cells.push_back({hs, periods[j - 1], p * scale});
    }
  }
  if (!header) throw InputError(path + ": no header row (Hs_m\\Tz_s, periods...)");
  if (d.cells.empty()) throw InputError(path + ": no cell with a probability > 0");
  return d;
}

OperabilityConfig ParseOperability(YamlMap& root, const std::vector<sk::PassengerPosition>& user_points) {
  OperabilityConfig c;
  if (!root.Has("operability")) return c;
  c.present = true;
  YamlMap m = root.Map("operability");
  c.scatter_csv = ConfigFilePath(m, "scatter_csv");
  const std::string unit =
      m.Choice("probabilities", {"fraction", "percent", "per_mille", "per_100000"}, "fraction");
  // per_100000: occurrences per 100 000 observations, the unit of IACS Rec. 34 and Global Wave Statistics tables.
  const double scale = unit == "fraction" ? 1.0 : unit == "percent" ? 0.01 : unit == "per_mille" ? 0.001 : 1e-5;
  const std::string spectrum = m.Choice("spectrum", {"jonswap", "bretschneider"}, "jonswap");
  const double gamma = m.Number("gamma", 3.3);
  if (spectrum == "bretschneider" && m.Has("gamma")) m.Fail("gamma", "only for spectrum: jonswap");
  if (!(gamma >= 1.0 && gamma <= 10.0)) m.Fail("gamma", "must be in [1, 10]");
  c.diagram = ReadScatterCsv(c.scatter_csv, scale);
  c.diagram.spectrum = spectrum == "jonswap" ? sk::SpectrumType::kJonswap : sk::SpectrumType::kBretschneider;
  c.diagram.gamma = spectrum == "jonswap" ? gamma : 1.0;
  std::string err;
  if (!c.diagram.IsValid(&err)) m.Fail("scatter_csv", c.scatter_csv + ": " + err);
  for (YamlMap& k : m.ListOfMaps("criteria")) {
    sk::OperabilityCriterion cr;
    cr.position = k.String("position", "mean");
    bool known = cr.position == "mean" || cr.position == "forward" || cr.position == "lcg" || cr.position == "transom";
    for (const auto& p : user_points) known = known || p.name == cr.position;
    if (!known) k.Fail("position", "'" + cr.position + "' is not forward, lcg, transom, mean or a positions.points name");
    const int kinds = int(k.Has("msi_max_pct")) + int(k.Has("rms_accel_max_g")) + int(k.Has("nordforsk"));
    if (kinds != 1) k.Fail("msi_max_pct", "give exactly one of msi_max_pct, rms_accel_max_g, nordforsk");
    if (k.Has("msi_max_pct")) {
      cr.is_msi = true;
      cr.limit = k.Number("msi_max_pct");
      if (!(cr.limit > 0.0 && cr.limit <= 100.0)) k.Fail("msi_max_pct", "must be in (0, 100] %");
      cr.name = "msi_max_" + std::to_string(cr.limit).substr(0, 5) + "pct_" + cr.position;
    } else if (k.Has("rms_accel_max_g")) {
      cr.is_msi = false;
      cr.limit = k.Number("rms_accel_max_g");
      if (!(cr.limit > 0.0 && cr.limit <= 2.0)) k.Fail("rms_accel_max_g", "must be in (0, 2] g");
      cr.name = "rms_accel_max_" + std::to_string(cr.limit).substr(0, 5) + "g_" + cr.position;
    } else {
      cr.is_msi = false;
      const std::string act = k.Choice("nordforsk", {"light_manual_work", "heavy_manual_work", "intellectual_work",
                                                     "transit_passengers", "cruise_liner"});
      sk::NordforskLimit(act, &cr.limit);
      cr.name = "nordforsk_" + act + "_" + cr.position;
    }
    cr.name = k.String("name", cr.name);
    k.Finish();
    c.criteria.push_back(cr);
  }
  m.Finish();
  return c;
}

}  // namespace hullopt::io
