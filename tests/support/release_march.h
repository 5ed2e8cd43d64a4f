#pragma once
// Free decay of a 2D section released from rest, shared by the release tests: d/dt(m v + I) =
// −C x with the strip's momentum I (all hydrodynamic force on the left, as in the reference paper), BDF2 in time
// and implicit in v (the force is affine in the current velocity).
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/strip/strip_marcher.h"
#include "seakeeping/strip/strip_operators.h"

namespace hullopt::testing {

/// Vertical normal components n_z of the panels (the heave input per unit velocity).
inline Eigen::VectorXd PanelNz(const std::vector<sk::Panel>& panels) {
  Eigen::VectorXd n(panels.size());
  for (std::size_t j = 0; j < panels.size(); ++j) n(j) = panels[j].Normal()[1];
  return n;
}

/// x/x0 at steps 0..N−1 after release from rest at x0 = 1, mass m [kg/m], restoring C [N/m²], time step
/// ops.Dt() (ops must hold >= N steps).
inline std::vector<double> ReleaseHistory(const sk::StripOperators& ops, const std::vector<sk::Panel>& panels,
                                          double m, double C, int N) {
  const double dt = ops.Dt();
  sk::StripMarcher marcher(ops);
  const Eigen::VectorXd nz = PanelNz(panels);
  std::vector<double> x(N), v(N);
  x[0] = 1.0, v[0] = 0;
  marcher.Advance(0.0 * nz);
  for (int n = 1; n < N; ++n) {
    const double xm1 = x[n - 1], xm2 = n >= 2 ? x[n - 2] : 1.0, vm1 = v[n - 1], vm2 = n >= 2 ? v[n - 2] : 0.0;
    const double f0 = marcher.Peek(0.0 * nz), f1 = marcher.Peek(nz) - f0;  // f_n = f0 + f1 v_n
    // m (3v − 4v_{n−1} + v_{n−2})/(2dt) = f0 + f1 v − C x,   x = (4x_{n−1} − x_{n−2} + 2dt v)/3
    const double lhs = 3 * m / (2 * dt) - f1 + C * 2 * dt / 3;
    const double rhs = m * (4 * vm1 - vm2) / (2 * dt) + f0 - C * (4 * xm1 - xm2) / 3;
    v[n] = rhs / lhs;
    x[n] = (4 * xm1 - xm2 + 2 * dt * v[n]) / 3;
    marcher.Advance(v[n] * nz);
  }
  return x;
}

/// Times n·dt [s], n = 0..N−1.
inline std::vector<double> Times(int N, double dt) {
  std::vector<double> t(N);
  for (int n = 0; n < N; ++n) t[n] = n * dt;
  return t;
}

struct DecayMeasures {
  double period, logdec, logdec_second;
};
/// Period between alternate zero crossings (second full cycle); log decrement between successive positive
/// peaks: the release value x0 and the first positive peak (first cycle), the first and second positive
/// peaks (second cycle). h is x/x0 at steps of dt [s].
inline DecayMeasures MeasureDecay(const std::vector<double>& h, double dt) {
  const int N = static_cast<int>(h.size());
  std::vector<double> zero, extreme;
  for (int n = 1; n < N; ++n)
    if ((h[n - 1] > 0) != (h[n] > 0)) zero.push_back((n - 1 + h[n - 1] / (h[n - 1] - h[n])) * dt);
  for (int n = 1; n + 1 < N; ++n)
    if ((h[n] - h[n - 1]) * (h[n + 1] - h[n]) < 0) extreme.push_back(h[n]);
  REQUIRE(zero.size() >= 5);
  REQUIRE(extreme.size() >= 4);
  return {zero[4] - zero[2], std::log(h[0] / extreme[1]), std::log(extreme[1] / extreme[3])};
}

}  // namespace hullopt::testing
