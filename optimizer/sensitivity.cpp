#include "optimizer/sensitivity.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace hullopt::opt {

SensitivityResult ComputeSensitivity(const std::vector<std::vector<double>>& x, const std::vector<double>& y,
                                     const std::vector<std::string>& names) {
  const int n = static_cast<int>(y.size());
  const int d = static_cast<int>(names.size());
  if (static_cast<int>(x.size()) != n) throw std::invalid_argument("sensitivity: x and y sizes differ");
  if (n < d + 2) {
    throw std::invalid_argument("sensitivity: needs at least " + std::to_string(d + 2) +
                                " feasible samples for " + std::to_string(d) + " variables, got " +
                                std::to_string(n));
  }
  Eigen::MatrixXd X(n, d);
  Eigen::VectorXd Y(n);
  for (int i = 0; i < n; ++i) {
    Y(i) = y[i];
    for (int j = 0; j < d; ++j) X(i, j) = x[i][j];
  }
  auto standardise = [n](Eigen::Ref<Eigen::VectorXd> c) {
    const double mean = c.mean();
    c.array() -= mean;
    const double sd = std::sqrt(c.squaredNorm() / (n - 1));
    if (!(sd > 0.0)) return false;
    c /= sd;
    return true;
  };
  for (int j = 0; j < d; ++j) {
    if (!standardise(X.col(j))) {
      throw std::invalid_argument("sensitivity: variable '" + names[j] + "' does not vary over the samples");
    }
  }
  if (!standardise(Y))
    throw std::invalid_argument("sensitivity: the objective does not vary over the samples");

  SensitivityResult out;
  out.samples = n;
  const Eigen::VectorXd b = X.colPivHouseholderQr().solve(Y);
  out.src.assign(b.data(), b.data() + d);
  const Eigen::VectorXd resid = Y - X * b;
  out.r_squared = 1.0 - resid.squaredNorm() / Y.squaredNorm();

  // Correlation ratio per variable: sort by x_i, split into equal-count bins, variance of the bin means.
  const int bins = std::max(2, static_cast<int>(std::floor(std::sqrt(static_cast<double>(n)))));
  std::vector<int> order(n);
  for (int j = 0; j < d; ++j) {
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int c) { return X(a, j) < X(c, j); });
    double between = 0.0;
    for (int b_i = 0; b_i < bins; ++b_i) {
      const int lo = static_cast<int>(static_cast<long long>(b_i) * n / bins);
      const int hi = static_cast<int>(static_cast<long long>(b_i + 1) * n / bins);
      double mean = 0.0;
      for (int k = lo; k < hi; ++k) mean += Y(order[k]);
      mean /= std::max(1, hi - lo);
      between += (hi - lo) * mean * mean;  // Y has mean 0
    }
    out.first_order.push_back(between / Y.squaredNorm());
  }
  return out;
}

}  // namespace hullopt::opt
