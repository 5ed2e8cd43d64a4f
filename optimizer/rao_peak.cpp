#include "optimizer/rao_peak.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace hullopt::opt {

RaoPeak InterpolatedPeak(std::vector<double> x, std::vector<double> y) {
  if (x.size() != y.size() || x.empty()) {
    throw std::invalid_argument("InterpolatedPeak: x (" + std::to_string(x.size()) + ") and y (" +
                                std::to_string(y.size()) + ") must have the same non-zero size");
  }
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  // Distinct abscissas; repeat runs at the same x are averaged (they are repeat measurements).
  std::vector<double> xs, ys;
  std::vector<int> count;
  for (std::size_t k : order) {
    if (!xs.empty() && x[k] == xs.back()) {
      ys.back() += y[k];
      ++count.back();
    } else {
      xs.push_back(x[k]);
      ys.push_back(y[k]);
      count.push_back(1);
    }
  }
  for (std::size_t i = 0; i < ys.size(); ++i) ys[i] /= count[i];

  const std::size_t n = xs.size();
  const std::size_t i = static_cast<std::size_t>(std::max_element(ys.begin(), ys.end()) - ys.begin());
  RaoPeak peak{xs[i], ys[i], n > 1 && (i == 0 || i + 1 == n)};
  if (n < 3 || peak.at_edge) return peak;

  // Lagrange parabola through (x0,y0), (x1,y1), (x2,y2), written as y = y1 + c1 (x − x1) + c2 (x − x1)².
  const double x0 = xs[i - 1], x1 = xs[i], x2 = xs[i + 1];
  const double y0 = ys[i - 1], y1 = ys[i], y2 = ys[i + 1];
  const double d0 = (y0 - y1) / (x0 - x1), d2 = (y2 - y1) / (x2 - x1);
  const double c2 = (d2 - d0) / (x2 - x0);
  const double c1 = d0 - c2 * (x0 - x1);
  if (!(c2 < 0.0)) return peak;
  const double dx = -c1 / (2.0 * c2);
  if (x1 + dx < x0 || x1 + dx > x2) return peak;
  peak.x = x1 + dx;
  peak.value = y1 + c1 * dx + c2 * dx * dx;
  return peak;
}

}  // namespace hullopt::opt
