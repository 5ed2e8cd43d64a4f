#include "io/config/speed_config.h"

namespace hullopt::io {

SpeedOptions ParseSpeed(YamlMap& root, bool required, bool* present) {
  SpeedOptions s;
  if (present) *present = root.Has("speed");
  if (!root.Has("speed")) {
    if (required) root.Map("speed");  // throws "missing required key 'speed'"
    root.Skip("speed");
    return s;
  }
  YamlMap m = root.Map("speed");
  const int n = int(m.Has("Fn")) + int(m.Has("kn")) + int(m.Has("m_s"));
  if (n != 1) {
    throw InputError(root.Where("speed") + ": give exactly one of Fn, kn, m_s (found " + std::to_string(n) +
                     ")");
  }
  std::string key;
  if (m.Has("Fn")) {
    s.unit = SpeedOptions::Unit::kFroude;
    key = "Fn";
  } else if (m.Has("kn")) {
    s.unit = SpeedOptions::Unit::kKnots;
    key = "kn";
  } else {
    s.unit = SpeedOptions::Unit::kMetresPerSecond;
    key = "m_s";
  }
  s.value = m.Number(key);
  std::string error;
  if (!s.IsValid(&error))
    m.Fail(key, s.unit == SpeedOptions::Unit::kFroude ? "must lie in (0, 5]" : "must lie in (0, 200]");
  m.Finish();
  return s;
}

}  // namespace hullopt::io
