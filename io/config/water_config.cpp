#include "io/config/water_config.h"

namespace hullopt::io {

WaterOptions ParseWater(YamlMap& root) {
  WaterOptions w;
  YamlMap m = root.MapOrEmpty("water");
  w.rho_kg_m3 = m.Number("rho_kg_m3", w.rho_kg_m3);
  if (!(w.rho_kg_m3 >= 500.0 && w.rho_kg_m3 <= 2000.0)) m.Fail("rho_kg_m3", "must lie in [500, 2000] kg/m^3");
  w.g_m_s2 = m.Number("g_m_s2", w.g_m_s2);
  if (!(w.g_m_s2 > 0.0 && w.g_m_s2 < 100.0)) m.Fail("g_m_s2", "must lie in (0, 100) m/s^2");
  m.Finish();
  return w;
}

}  // namespace hullopt::io
