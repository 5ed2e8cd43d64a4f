#include "support/free_decay.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace hullopt::sk {

std::vector<double> FreeDecayFromCoefficients(const FreeDecayInput& in, const std::vector<double>& times) {
  const auto& w = in.omega_rad_s;
  const std::size_t n = w.size();
  if (n < 2 || in.a33_kg_per_m.size() != n || in.b33_kg_per_m_s.size() != n)
    throw std::invalid_argument("free decay: need >= 2 frequencies with a33 and b33 at each");
  for (std::size_t i = 0; i < n; ++i)
    if (!(w[i] > 0) || (i > 0 && !(w[i] > w[i - 1])))
      throw std::invalid_argument("free decay: frequencies must be > 0 and ascending");
  if (!(in.mass_kg_per_m > 0) || !(in.restoring_n_per_m2 > 0))
    throw std::invalid_argument("free decay: mass and restoring must be > 0");
  const double C = in.restoring_n_per_m2, m = in.mass_kg_per_m;
  auto ReH = [&](double om) {
    double a, b;
    if (om >= w.back()) {
      a = in.a33_infinite_kg_per_m, b = 0.0;
    } else if (om <= w.front()) {  // held below the first frequency (ω²a33 → 0 and H → 1/C as ω → 0)
      a = in.a33_kg_per_m.front(), b = in.b33_kg_per_m_s.front();
    } else {
      const std::size_t k = std::upper_bound(w.begin(), w.end(), om) - w.begin();  // w[k−1] <= om < w[k]
      const double f = (om - w[k - 1]) / (w[k] - w[k - 1]);
      a = in.a33_kg_per_m[k - 1] + f * (in.a33_kg_per_m[k] - in.a33_kg_per_m[k - 1]);
      b = in.b33_kg_per_m_s[k - 1] + f * (in.b33_kg_per_m_s[k] - in.b33_kg_per_m_s[k - 1]);
    }
    return (1.0 / std::complex<double>(C - om * om * (m + a), om * b)).real();
  };
  const double t_max = times.empty() ? 0.0 : *std::max_element(times.begin(), times.end());
  const double w_top = 4.0 * w.back();
  const double dw = std::min(w.front() / 8, 2 * M_PI / (64.0 * std::max(t_max, 1e-9)));
  const int steps = static_cast<int>(std::ceil(w_top / dw));
  std::vector<double> out;
  for (double t : times) {
    // ∫ Re H sin(ωt)/ω dω by the midpoint rule on a uniform grid (the integrand is smooth, sin(ωt)/ω → t at
    // 0).
    double sum = 0;
    for (int i = 0; i < steps; ++i) {
      const double om = (i + 0.5) * w_top / steps;
      sum += ReH(om) * std::sin(om * t) / om;
    }
    out.push_back(1.0 - 2.0 * C / M_PI * sum * (w_top / steps));
  }
  return out;
}

}  // namespace hullopt::sk
