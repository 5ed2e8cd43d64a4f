#pragma once
// A time-marching scheme for the two rigid-body degrees of freedom (heave, pitch), kept apart from the force
// model: the scheme only proposes trial states at t_{K+1} and asks a callable for the hull's acceleration
// there. The force model behind the callable (strip forces, hydrostatics, wave) never sees the scheme.
// Concrete schemes are chosen by name (time_scheme_registry.h).
#include <array>
#include <functional>

namespace hullopt::sk {

/// One value per degree of freedom: [0] heave (m, m/s, m/s², up), [1] pitch (rad, rad/s, rad/s², bow-down).
using DofPair = std::array<double, 2>;

/// The marched state at t_K, and what a multistep scheme needs from t_{K−1}.
struct MarchingState {
  DofPair x{};           ///< displacement
  DofPair v{};           ///< velocity
  DofPair a{};           ///< acceleration
  DofPair a_previous{};  ///< acceleration at t_{K−1} (0 before the first step)
  long steps = 0;        ///< K, steps taken since rest
};

/// The hull's acceleration F/M at t_{K+1} for the trial state (x, v) there. trial = 0 is the step's first
/// evaluation (the force model moves on one step); trial > 0 re-solves the same step with a revised state.
using TrialAcceleration = std::function<DofPair(const DofPair& x, const DofPair& v, int trial)>;

class TimeScheme {
 public:
  virtual ~TimeScheme() = default;
  /// A new run from rest: forget whatever the scheme keeps between steps.
  virtual void Restart() = 0;
  /// Advances *state from t_K to t_K + dt_s. On return x and v are the state the force model was last
  /// evaluated with (so the force history and the motion agree) and a the scheme's acceleration at t_{K+1}.
  /// Non-finite values are returned as they are; the caller decides what divergence means.
  virtual void Step(double dt_s, const TrialAcceleration& hull_acceleration, MarchingState* state) = 0;
};

}  // namespace hullopt::sk
