#include "seakeeping/motions/weighted_average_newmark.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {

bool WeightedAverageParameters::IsValid(std::string* error) const {
  std::ostringstream os;
  if (!(hydrodynamic_fraction > 0.0) || !(hydrodynamic_fraction <= 1.0)) {
    os << "hydrodynamic_fraction = " << hydrodynamic_fraction << ": must satisfy 0 < fraction <= 1";
  } else if (max_passes < 1) {
    os << "max_passes = " << max_passes << ": must be >= 1";
  } else if (!(pass_tolerance > 0.0)) {
    os << "pass_tolerance = " << pass_tolerance << ": must be > 0";
  }
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

WeightedAverageNewmark::WeightedAverageNewmark(const WeightedAverageParameters& parameters) : p_(parameters) {
  std::string err;
  if (!p_.IsValid(&err)) throw std::invalid_argument("weighted-average Newmark scheme: " + err);
}

void WeightedAverageNewmark::Restart() { a_scale_ = {0.0, 0.0}; }

void WeightedAverageNewmark::Step(double dt, const TrialAcceleration& hull_acceleration, MarchingState* s) {
  const double w = p_.hydrodynamic_fraction;
  const DofPair x0 = s->x, v0 = s->v;
  DofPair guess;
  for (int i = 0; i < 2; ++i) guess[i] = s->steps >= 1 ? 2.0 * s->a[i] - s->a_previous[i] : s->a[i];
  DofPair next{0.0, 0.0};
  for (int pass = 0; pass < p_.max_passes; ++pass) {
    for (int i = 0; i < 2; ++i) {
      const double a_mean = 0.5 * (s->a[i] + guess[i]);
      s->x[i] = x0[i] + dt * v0[i] + 0.5 * dt * dt * a_mean;
      s->v[i] = v0[i] + dt * a_mean;
    }
    const DofPair a_hydro = hull_acceleration(s->x, s->v, pass);
    bool settled = true;
    for (int i = 0; i < 2; ++i) {
      next[i] = w * a_hydro[i] + (1.0 - w) * guess[i];
      a_scale_[i] = std::max(a_scale_[i], std::fabs(next[i]));
      if (std::fabs(next[i] - guess[i]) > p_.pass_tolerance * a_scale_[i]) settled = false;
    }
    if (!std::isfinite(next[0]) || !std::isfinite(next[1])) break;
    if (settled || pass + 1 == p_.max_passes) break;
    guess = next;
  }
  // x and v stay the state the force model was last evaluated with, so that its history and the motion agree.
  s->a_previous = s->a;
  s->a = next;
  ++s->steps;
}

}  // namespace hullopt::sk
