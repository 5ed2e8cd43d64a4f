#pragma once
// The `resistance:` block: model options (form factor, viscosity, Michell resolution) and the speeds of
// `hullopt resistance`.
#include <string>
#include <vector>

#include "io/config/yaml_map.h"
#include "resistance/calm_water_resistance.h"

namespace hullopt::io {

struct ResistanceConfig {
  res::ResistanceOptions options;
  /// The speeds to tabulate, as given: knots or Froude numbers (one of them is empty).
  std::vector<double> speeds_kn;
  std::vector<double> speeds_Fn;
  /// Speeds [m/s] for main-body length L_m and gravity g_m_s2, in the order given.
  std::vector<double> MetresPerSecond(double L_m, double g_m_s2) const;
};

/// Reads `resistance:` (optional; defaults when absent). Model keys: form_factor (1 + k, default 1),
/// kinematic_viscosity_m2_s (default: 15 °C fresh or sea water by water.rho_kg_m3), surface_points,
/// michell: {depth_points, intervals_per_wave, max_du, lambda_max}. Speed keys, at most one (only when
/// `speeds_allowed`): speeds_kn: [..], speeds_Fn: [..], speed_range_kn: {from, to, step}. Throws InputError
/// naming the key for unknown keys, ranges, non-positive or non-increasing speeds, a range of fewer than 1
/// or more than 1000 speeds.
ResistanceConfig ParseResistanceConfig(YamlMap& root, bool speeds_allowed);

}  // namespace hullopt::io
