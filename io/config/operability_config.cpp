#include "io/config/operability_config.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

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

namespace {

constexpr double kKnot = 1852.0 / 3600.0;  // [m/s]

bool KnownPosition(const std::string& name, const std::vector<sk::PassengerPosition>& user_points) {
  bool known = name == "mean" || name == "forward" || name == "lcg" || name == "transom";
  for (const auto& p : user_points) known = known || p.name == name;
  return known;
}

std::string Short(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

OperabilityPolarConfig ParsePolar(YamlMap& m, const std::vector<sk::PassengerPosition>& user_points) {
  OperabilityPolarConfig c;
  c.present = true;
  c.speeds_kn = m.Numbers("speeds_kn");
  for (double v : c.speeds_kn) {
    if (!(v >= 0.0)) m.Fail("speeds_kn", "speed " + Short(v) + " kn must be >= 0");
    c.options.speeds_m_s.push_back(v * kKnot);
  }
  c.options.headings_deg = m.Numbers("headings_deg");
  for (std::size_t i = 0; i < c.options.headings_deg.size(); ++i) {
    const double h = c.options.headings_deg[i];
    if (!(h >= 0.0 && h < 360.0))
      m.Fail("headings_deg", "heading " + Short(h) +
                                 " deg must lie in [0, 360) (180 head seas, 90 beam seas from starboard; "
                                 "docs/conventions.md)");
    for (std::size_t j = 0; j < i; ++j)
      if (c.options.headings_deg[j] == h) m.Fail("headings_deg", "heading " + Short(h) + " deg is given twice");
  }
  struct Kind {
    const char* key;
    eval::PolarQuantity quantity;
    double max;
    const char* unit;
  };
  static const Kind kKinds[] = {
      {"rms_vertical_accel_max_g", eval::PolarQuantity::kRmsVerticalAcceleration, 2.0, "g"},
      {"rms_lateral_accel_max_g", eval::PolarQuantity::kRmsLateralAcceleration, 2.0, "g"},
      {"roll_rms_max_deg", eval::PolarQuantity::kRmsRoll, 45.0, "deg"},
      {"msi_max_pct", eval::PolarQuantity::kMsi, 100.0, "%"}};
  for (YamlMap& k : m.ListOfMaps("criteria")) {
    eval::PolarCriterion cr;
    const Kind* kind = nullptr;
    int kinds = 0;
    for (const auto& q : kKinds)
      if (k.Has(q.key)) ++kinds, kind = &q;
    if (kinds != 1)
      k.Fail("rms_vertical_accel_max_g",
             "give exactly one of rms_vertical_accel_max_g, rms_lateral_accel_max_g, roll_rms_max_deg, msi_max_pct");
    cr.quantity = kind->quantity;
    cr.limit = k.Number(kind->key);
    if (!(cr.limit > 0.0 && cr.limit <= kind->max))
      k.Fail(kind->key, "must be in (0, " + Short(kind->max) + "] " + kind->unit);
    if (cr.quantity == eval::PolarQuantity::kRmsRoll) {
      for (const char* key : {"position", "y_m", "z_m"})
        if (k.Has(key)) k.Fail(key, "roll has no position (a rotation of the whole hull)");
      cr.position = "";
      cr.name = "rms_roll";
    } else {
      cr.position = k.String("position", "mean");
      if (!KnownPosition(cr.position, user_points))
        k.Fail("position", "'" + cr.position + "' is not forward, lcg, transom, mean or a positions.points name");
      cr.y_m = k.Number("y_m", 0.0);
      cr.z_m = k.Number("z_m", 0.0);
      cr.name = eval::PolarQuantityName(cr.quantity) + "_" + cr.position;
    }
    cr.name = k.String("name", cr.name);
    cr.source = k.String("source", "");
    k.Finish();
    c.criteria.push_back(cr);
  }
  return c;
}

}  // namespace

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
    if (!KnownPosition(cr.position, user_points)) k.Fail("position", "'" + cr.position + "' is not forward, lcg, transom, mean or a positions.points name");
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
  if (m.Has("polar")) {
    YamlMap p = m.Map("polar");
    c.polar = ParsePolar(p, user_points);
    c.polar.where = m.Where("polar");
    p.Finish();
  }
  m.Finish();
  return c;
}

}  // namespace hullopt::io
