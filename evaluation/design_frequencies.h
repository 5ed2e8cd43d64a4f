#pragma once
// The default wave-frequency grid of a single design (`hullopt design`, `hullopt evaluate` on a hull config
// without solver.frequencies), chosen from the hull's length L and the speed U:
//   range  ω from min(0.2 rad/s, ω at λ/L = 8) to max(3.0 rad/s, ω at λ/L = 0.25): the sea grid of
//          EvaluationFrequencies() widened, for a short hull, to the wavelengths of its motion response;
//   step   Δω = 0.25 √(g/L) / (1 + 2 ω₂ U / g), ω₂ = ω at λ/L = 2: a quarter of the length's natural
//          frequency unit, in encounter frequency where high-speed head-sea heave and pitch peak
//          (λ/L 1.5 to 3), divided by dω_e/dω there, so that the peak in ω_e is sampled ~10 times across (an undamped SWATH peak, Cs 0, is not);
//   count  (range / step) + 1, within [60, 400].
// With solver.adaptive_grid on (the default) this is the starting grid that evaluation/adaptive_frequency_grid.h
// refines until the RAO peaks (a Cs-0 SWATH's too) and the MSI converge.
#include "seakeeping/motions/frequency_list.h"

namespace hullopt::eval {

/// Bounds of the count of the default grid.
constexpr int kDesignGridMinCount = 60;
constexpr int kDesignGridMaxCount = 400;

/// The grid as a range in ω (recorded in config.resolved.yaml as solver.frequencies.range). length_m, g_m_s2
/// > 0, speed_m_s >= 0; std::invalid_argument otherwise.
sk::FrequencySpec DesignFrequencyGrid(double length_m, double speed_m_s, double g_m_s2);

}  // namespace hullopt::eval
