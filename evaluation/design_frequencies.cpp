#include "evaluation/design_frequencies.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hullopt::eval {
namespace {

// Deep-water dispersion: ω at wavelength ratio λ/L.
double OmegaAt(double lambda_over_L, double length_m, double g) {
  return std::sqrt(2.0 * M_PI * g / (lambda_over_L * length_m));
}

}  // namespace

sk::FrequencySpec DesignFrequencyGrid(double length_m, double speed_m_s, double g_m_s2) {
  if (!(length_m > 0.0) || !(g_m_s2 > 0.0) || !(speed_m_s >= 0.0) || !std::isfinite(length_m + speed_m_s + g_m_s2))
    throw std::invalid_argument("design frequency grid: needs L > 0, U >= 0, g > 0");
  const double lo = std::min(0.2, OmegaAt(8.0, length_m, g_m_s2));
  const double hi = std::max(3.0, OmegaAt(0.25, length_m, g_m_s2));
  const double w2 = OmegaAt(2.0, length_m, g_m_s2);
  const double step = 0.25 * std::sqrt(g_m_s2 / length_m) / (1.0 + 2.0 * w2 * speed_m_s / g_m_s2);
  const int count = std::clamp(static_cast<int>(std::ceil((hi - lo) / step)) + 1, kDesignGridMinCount,
                               kDesignGridMaxCount);
  return sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmega, lo, hi, count);
}

}  // namespace hullopt::eval
