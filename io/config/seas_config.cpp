#include "io/config/seas_config.h"

#include <set>
#include <sstream>
#include <string>

#include "evaluation/validity_envelope.h"
#include "seas/sea_state_line.h"

namespace hullopt::io {
namespace {

// "file:line: key 'seas[0]'" for the mapping itself.
std::string WhereMap(const YamlMap& map) {
  std::string w = map.Where("");
  const size_t dot = w.rfind(".'");
  if (dot != std::string::npos && dot + 2 == w.size()) w.erase(dot, 1);
  return w;
}

// The options structs name the offending field first ("Hs_m = 0: ..."); point the error at that key.
[[noreturn]] void FailWithRule(const YamlMap& map, const std::string& error) {
  const std::string key = error.substr(0, error.find_first_of(" :"));
  if (map.Has(key)) throw InputError(map.Where(key) + ": " + error);
  throw InputError(WhereMap(map) + ": " + error);
}

std::string FourDigits(double v) {
  std::ostringstream os;
  os.precision(4);
  os << v;
  return os.str();
}

// Standard gravity: a sea's steepness is a property of the sea, read before the water block.
constexpr double kStandardGravity = 9.80665;

// The steepness Hs/lambda_p beyond the envelope's hard limit (breaking) is refused as the sea is read; a steep
// sea within it is flagged with the evaluation's results (eval::ResponseEnvelopeWarnings).
std::string SteepnessRefusal(const sk::SeaState& s) {
  const double lambda_p = eval::PeakWaveLength(s, kStandardGravity);
  for (const auto& f : eval::CheckEnvelopeValue(eval::EnvelopeQuantity::kWaveSteepness, s.Hs_m / lambda_p, "Hs_m",
                                                "Hs " + FourDigits(s.Hs_m) + " m, peak wave length " + FourDigits(lambda_p) + " m"))
    if (f.refuse) return f.message;
  return "";
}

}  // namespace

sk::SeaState ReadSeaState(YamlMap& m) {
  sk::SeaState s;
  const std::string type = m.Choice("spectrum", {"jonswap", "bretschneider"}, "jonswap");
  s.spectrum = type == "jonswap" ? sk::SpectrumType::kJonswap : sk::SpectrumType::kBretschneider;
  s.Hs_m = m.Number("Hs_m");
  const bool tz = m.Has("Tz_s"), tp = m.Has("Tp_s");
  if (tz == tp) throw InputError(WhereMap(m) + ": give exactly one of Tz_s and Tp_s");
  if (tz) s.Tz_s = m.Number("Tz_s");
  if (tp) s.Tp_s = m.Number("Tp_s");
  s.gamma = m.Number("gamma", s.spectrum == sk::SpectrumType::kJonswap ? 3.3 : 1.0);
  m.Finish();
  std::string error;
  if (!s.IsValid(&error)) FailWithRule(m, error);
  const std::string steep = SteepnessRefusal(s);
  if (!steep.empty()) m.Fail("Hs_m", steep);
  return s;
}

std::vector<sk::SeaState> ReadSeas(YamlMap& root) {
  std::vector<sk::SeaState> seas;
  for (YamlMap& entry : root.ListOfMaps("seas")) {
    if (!entry.Has("sea_state_line")) {
      seas.push_back(ReadSeaState(entry));
      continue;
    }
    YamlMap line = entry.Map("sea_state_line");
    entry.Finish();
    const std::vector<double> heights = line.Numbers("Hs_m");
    const double gamma = line.Number("gamma", 3.3);
    line.Finish();
    for (size_t i = 0; i < heights.size(); ++i) {
      const sk::SeaState s = sk::SeaState::JonswapTz(heights[i], sk::SeaStateLineTz(heights[i]), gamma);
      std::string error;
      if (!s.IsValid(&error))
        throw InputError(line.Where(error.rfind("gamma", 0) == 0 ? "gamma" : "Hs_m") + ": element " +
                         std::to_string(i + 1) + ": " + error);
      const std::string steep = SteepnessRefusal(s);
      if (!steep.empty()) throw InputError(line.Where("Hs_m") + ": element " + std::to_string(i + 1) + ": " + steep);
      seas.push_back(s);
    }
  }
  return seas;
}

sk::MsiOptions ReadMsiOptions(YamlMap& root) {
  sk::MsiOptions o;
  YamlMap m = root.MapOrEmpty("msi");
  const std::string model =
      m.Choice("model", {"lloyd", "ohanlon_mccauley_1974", "mccauley_1976", "iso_2631"}, "lloyd");
  o.model = model == "lloyd"                   ? sk::MsiModel::kLloyd
            : model == "ohanlon_mccauley_1974" ? sk::MsiModel::kOHanlonMcCauley1974
            : model == "mccauley_1976"         ? sk::MsiModel::kMcCauley1976
                                               : sk::MsiModel::kIso2631Msdv;
  o.exposure_h = m.Number("exposure_h", 2.0);
  o.frequency = m.Choice("frequency", {"displacement_m4_m2", "acceleration_zero_crossing"},
                         "displacement_m4_m2") == "displacement_m4_m2"
                    ? sk::MsiFrequency::kDisplacementM4M2
                    : sk::MsiFrequency::kAccelerationZeroCrossing;
  o.statistic = m.Choice("acceleration", {"mean_absolute", "rms"}, "mean_absolute") == "mean_absolute"
                    ? sk::AccelerationStatistic::kMeanAbsolute
                    : sk::AccelerationStatistic::kRms;
  o.iso_km = m.Number("iso_km", 1.0 / 3.0);
  m.Finish();
  std::string error;
  if (!o.IsValid(&error)) FailWithRule(m, error);
  return o;
}

std::vector<sk::PassengerPosition> ReadPassengerPoints(YamlMap& positions, const sk::HullExtent* hull) {
  std::vector<sk::PassengerPosition> points;
  if (!positions.Has("points")) return points;
  std::set<std::string> names;
  for (YamlMap& p : positions.ListOfMaps("points")) {
    sk::PassengerPosition pos;
    pos.name = p.String("name");
    pos.x_from_cg_m = p.Number("x_from_cg_m");
    p.Finish();
    if (!names.insert(pos.name).second) p.Fail("name", "passenger point names must be unique");
    std::string error;
    const sk::HullExtent any{1e300, 1e300};  // name checks only, when the hull is not known yet
    if (!sk::IsValidPassengerPosition(pos, hull ? *hull : any, &error))
      throw InputError(p.Where(error.find("outside") != std::string::npos ? "x_from_cg_m" : "name") + ": " +
                       error);
    points.push_back(pos);
  }
  return points;
}

}  // namespace hullopt::io
