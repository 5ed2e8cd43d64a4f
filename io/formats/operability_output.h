#pragma once
// operability.csv and operability.json of `hullopt evaluate` with an `operability:` block, and
// operability_polar.csv with its `polar:`.
#include <string>
#include <vector>

#include "evaluation/operability_polar.h"
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

/// operability_polar.csv: speed_kn,wave_direction_deg (the heading β, as rao.csv),operability ([-] share of the scatter diagram's probability with
/// every criterion met), then share_<name> per criterion and a note; a cell not computed has empty values and
/// its reason in the note; a computed cell's note holds the roll damping's flags raised at its speed
/// ("warning: ...", "; " separated), empty when there are none. Written atomically; throws InputError if it cannot be written.
void WriteOperabilityPolarCsv(const std::string& path, const eval::OperabilityPolar& polar,
                              const std::vector<eval::PolarCriterion>& criteria);

}  // namespace hullopt::io
