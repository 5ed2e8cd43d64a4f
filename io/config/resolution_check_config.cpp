#include "io/config/resolution_check_config.h"

#include <string>

namespace hullopt::io {

ResolutionCheckConfig ReadResolutionCheck(YamlMap& root) {
  ResolutionCheckConfig c;
  if (!root.Has("resolution_check")) return c;
  YamlMap m = root.Map("resolution_check");
  c.enabled = m.Boolean("enabled", false);
  c.factor = m.Integer("factor", 2, 2, 4, "the check refines sections and panels by this factor");
  c.options.msi_tolerance_pct = m.Number("msi_tolerance_pct", c.options.msi_tolerance_pct);
  if (!(c.options.msi_tolerance_pct > 0.0 && c.options.msi_tolerance_pct <= 100.0))
    m.Fail("msi_tolerance_pct", "must be in (0, 100] percentage points");
  const double peak_pct = m.Number("peak_tolerance_pct", 100.0 * c.options.peak_tolerance);
  if (!(peak_pct > 0.0 && peak_pct < 100.0)) m.Fail("peak_tolerance_pct", "must be in (0, 100) %");
  c.options.peak_tolerance = peak_pct / 100.0;
  m.Finish();
  return c;
}

}  // namespace hullopt::io
