#include "io/config/water_config.h"

#include "evaluation/validity_envelope.h"

namespace hullopt::io {

void RefuseOutsideEnvelope(const YamlMap& map, const std::string& key, eval::EnvelopeQuantity q, double value) {
  for (const auto& f : eval::CheckEnvelopeValue(q, value, key))
    if (f.refuse) map.Fail(key, f.message);
}

WaterOptions ParseWater(YamlMap& root) {
  WaterOptions w;
  YamlMap m = root.MapOrEmpty("water");
  w.rho_kg_m3 = m.Number("rho_kg_m3", w.rho_kg_m3);
  RefuseOutsideEnvelope(m, "rho_kg_m3", eval::EnvelopeQuantity::kWaterDensity, w.rho_kg_m3);
  w.g_m_s2 = m.Number("g_m_s2", w.g_m_s2);
  RefuseOutsideEnvelope(m, "g_m_s2", eval::EnvelopeQuantity::kGravity, w.g_m_s2);
  m.Finish();
  return w;
}

}  // namespace hullopt::io
