#pragma once
// The optional `resolution_check:` section of evaluate (and campaign) configs: each computed design is
// re-run at a finer strip resolution and flagged when its result moves (seas/resolution_check.h).
//
//   resolution_check:
//     enabled: true              # default false (the check costs about 15x the design's own evaluation)
//     factor: 2                  # sections and panels of the check = factor x those of the design (2 to 4)
//     msi_tolerance_pct: 1.0     # [points] largest change of the mean MSI in any sea (default 1)
//     peak_tolerance_pct: 3.0    # [%] largest relative change of the heave or pitch RAO peak (default 3)
#include "io/config/yaml_map.h"
#include "seas/resolution_check.h"

namespace hullopt::io {

struct ResolutionCheckConfig {
  bool enabled = false;
  int factor = 2;
  sk::ResolutionCheckOptions options;
};

/// Reads the optional `resolution_check` mapping of root (disabled when absent). io::InputError naming the
/// key and the rule for a value out of range.
ResolutionCheckConfig ReadResolutionCheck(YamlMap& root);

}  // namespace hullopt::io
