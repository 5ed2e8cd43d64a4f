#pragma once
// The sea-state line of the reference paper (Davis & Holloway 2003, §4): the average period grows with wave
// height (after Darbyshire & Draper 1963), 5 s in a 0.5 m sea to 7.5 s in a 3 m sea, linear between:
// Tz = 4.5 s + 1.0 s/m · Hs (so 5.5 s at 1 m, as the paper quotes). "Average period" is read as the
// zero-crossing period Tz (docs/evaluate.md, 'Verification (tests)': it reproduces the paper's
// Fig. 7 modal encounter frequencies).
#include <vector>

#include "seas/wave_spectrum.h"

namespace hullopt::sk {

/// Tz [s] of the paper's sea-state line at significant wave height Hs [m].
inline double SeaStateLineTz(double Hs_m) { return 4.5 + 1.0 * Hs_m; }

/// JONSWAP (γ = gamma) sea states on the line at the given heights, in the given order.
inline std::vector<SeaState> SeaStateLine(const std::vector<double>& Hs_m, double gamma = 3.3) {
  std::vector<SeaState> seas;
  seas.reserve(Hs_m.size());
  for (double h : Hs_m) seas.push_back(SeaState::JonswapTz(h, SeaStateLineTz(h), gamma));
  return seas;
}

}  // namespace hullopt::sk
