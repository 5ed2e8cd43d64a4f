#pragma once
// operability.csv and operability.json of `hullopt evaluate` with an `operability:` block.
#include <string>
#include <vector>

#include "seas/operability.h"

namespace hullopt::io {

struct DesignOperability {
  std::string name;
  sk::OperabilityResult result;
};

/// operability.csv: design,Hs_m,<Tz_s|Tp_s>,probability,msi_mean_pct,msi_forward_pct,msi_lcg_pct,
/// msi_transom_pct,rms_accel_forward_g,rms_accel_lcg_g,rms_accel_transom_g, then one 0/1 column per criterion
/// (met_<name>). operability.json: per design the weighted mean MSI, the time each criterion is met [%] and
/// the time all are met [%], with the criteria and the scatter source. Returns the file names written.
/// Throws InputError if a value is not finite or a file cannot be written.
std::vector<std::string> WriteOperabilityOutputs(const std::string& dir, const std::vector<DesignOperability>& designs,
                                                 const sk::ScatterDiagram& diagram,
                                                 const std::vector<sk::OperabilityCriterion>& criteria,
                                                 const std::string& scatter_source);

}  // namespace hullopt::io
