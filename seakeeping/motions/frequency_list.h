#pragma once
// The frequencies of an RAO sweep, given as wave-length ratios λ/L, wave frequencies ω or encounter
// frequencies ω_e (lists or evenly spaced ranges), converted to the increasing wave frequencies the solvers
// take.
#include <string>
#include <vector>

namespace hullopt::sk {

struct FrequencySpec {
  enum class Quantity { kLambdaOverL, kOmega, kOmegaE };
  Quantity quantity = Quantity::kOmegaE;
  std::vector<double> values;  ///< λ/L [-], ω [rad/s] or ω_e [rad/s]

  /// count evenly spaced values from `from` to `to` inclusive (count >= 2; count == 1 gives {from}).
  static FrequencySpec Range(Quantity q, double from, double to, int count);
  /// Non-empty, every value finite and > 0.
  bool IsValid(std::string* error) const;
};

/// Name of the quantity as used in configs and messages: lambda_over_L, omega_rad_s, omega_e_rad_s.
std::string QuantityName(FrequencySpec::Quantity q);

/// Wave frequencies ω [rad/s] of the spec, increasing, duplicates removed. length_m [m] is the L of λ/L.
/// Throws std::invalid_argument if the spec is not valid or speed/g/length are not positive.
std::vector<double> WaveFrequencies(const FrequencySpec& spec, double speed_m_s, double g_m_s2,
                                    double length_m);

}  // namespace hullopt::sk
