#include "seakeeping/motions/frequency_list.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "seakeeping/motions/head_sea_wave.h"

namespace hullopt::sk {

FrequencySpec FrequencySpec::Range(Quantity q, double from, double to, int count) {
  FrequencySpec s;
  s.quantity = q;
  if (count == 1) s.values = {from};
  for (int i = 0; count >= 2 && i < count; ++i) s.values.push_back(from + (to - from) * i / (count - 1.0));
  return s;
}

bool FrequencySpec::IsValid(std::string* error) const {
  if (values.empty()) {
    if (error) *error = "frequency list (" + QuantityName(quantity) + ") is empty: give at least one value";
    return false;
  }
  for (double v : values) {
    if (!std::isfinite(v) || v <= 0.0) {
      std::ostringstream os;
      os << "frequency list (" << QuantityName(quantity) << ") holds " << v << ": every value must be > 0";
      if (error) *error = os.str();
      return false;
    }
  }
  return true;
}

std::string QuantityName(FrequencySpec::Quantity q) {
  switch (q) {
    case FrequencySpec::Quantity::kLambdaOverL:
      return "lambda_over_L";
    case FrequencySpec::Quantity::kOmega:
      return "omega_rad_s";
    case FrequencySpec::Quantity::kOmegaE:
      return "omega_e_rad_s";
  }
  return "?";
}

std::vector<double> WaveFrequencies(const FrequencySpec& spec, double speed_m_s, double g_m_s2,
                                    double length_m) {
  std::string err;
  if (!spec.IsValid(&err)) throw std::invalid_argument(err);
  if (!(speed_m_s >= 0.0) || !(g_m_s2 > 0.0) || !(length_m > 0.0))
    throw std::invalid_argument("WaveFrequencies: speed must be >= 0 and g, L > 0");
  std::vector<double> w;
  for (double v : spec.values) {
    switch (spec.quantity) {
      case FrequencySpec::Quantity::kLambdaOverL:
        w.push_back(WaveFrequencyFromLength(v * length_m, g_m_s2));
        break;
      case FrequencySpec::Quantity::kOmega:
        w.push_back(v);
        break;
      case FrequencySpec::Quantity::kOmegaE:
        w.push_back(HeadSeaWaveFrequency(v, speed_m_s, g_m_s2));
        break;
    }
  }
  std::sort(w.begin(), w.end());
  // Values that map to the same ω to rounding (e.g. 1.0 and 1.0000000000001) would give duplicate rows.
  w.erase(std::unique(w.begin(), w.end(), [](double a, double b) { return std::fabs(a - b) <= 1e-12 * b; }),
          w.end());
  return w;
}

}  // namespace hullopt::sk
