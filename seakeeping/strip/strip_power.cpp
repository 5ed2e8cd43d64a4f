#include "seakeeping/strip/strip_power.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "seakeeping/green/gauss_legendre.h"
#include "seakeeping/green/memory_influence.h"
#include "seakeeping/green/rankine_panel.h"

namespace hullopt::sk {

std::vector<double> MarchPotential(const StripOperators& ops, const std::vector<Eigen::VectorXd>& sources, int m,
                                   const std::vector<double>& y, const std::vector<double>& z) {
  if (m < 0 || m >= static_cast<int>(sources.size()) || m >= ops.Steps())
    throw std::invalid_argument("MarchPotential: step " + std::to_string(m) + " is not a step of the march");
  if (y.size() != z.size()) throw std::invalid_argument("MarchPotential: y and z differ in size");
  for (double zi : z)
    if (!(zi < 0.0)) throw std::invalid_argument("MarchPotential: field points must lie below z = 0");
  const double dt = ops.Dt(), g = ops.G(), tm = m * dt;
  std::vector<double> phi(y.size(), 0.0);
  for (int k = 0; k <= m; ++k) {
    const std::vector<Panel>& full = ops.FullPanelsAt(k);
    if (full.empty()) continue;
    const std::vector<int>& index = ops.ReducedIndex(k);
    // Interval of step k's sources, [max(0, t_k − dt/2), t_k + dt/2], cut at t_m: lags s1 < s2 at t_m.
    const double tk = k * dt, a = std::max(0.0, tk - 0.5 * dt), b = k < m ? tk + 0.5 * dt : tm;
    const double s1 = tm - b, s2 = tm - a;
    for (std::size_t j = 0; j < full.size(); ++j) {
      const double sigma = sources[k](index[j]);
      if (sigma == 0.0) continue;
      for (std::size_t i = 0; i < y.size(); ++i) {
        double v = 0.0;
        if (s2 > s1) v -= MemoryPotential(full[j], y[i], z[i], s1, s2, g);
        if (k == m) v += RankinePanelInfluence(full[j], y[i], z[i]).phi - ImagePanelInfluence(full[j], y[i], z[i]).phi;
        phi[i] += sigma * v;
      }
    }
  }
  return phi;
}

std::vector<double> StripPower(const StripOperators& ops, const std::vector<Eigen::VectorXd>& sources,
                               const std::vector<ContourMotion>& motions) {
  const int steps = static_cast<int>(sources.size());
  if (steps != ops.Steps() || static_cast<int>(motions.size()) != steps)
    throw std::invalid_argument("StripPower: needs a completed march and one contour motion per step");
  const double dt = ops.Dt(), rho = ops.Rho();
  const auto& rule = GaussLegendre01(2);
  std::vector<double> power(steps, 0.0);
  for (int n = 0; n < steps; ++n) {
    const std::vector<Panel>& full = ops.FullPanelsAt(n);
    if (full.empty()) continue;
    if (motions[n].normal_speed_m_s.size() != full.size())
      throw std::invalid_argument("StripPower: the contour motion of step " + std::to_string(n) +
                                  " does not match its panels");
    // One representative full panel per reduced panel (mirror partners carry the same W and φ), and how many
    // full panels it stands for.
    const std::vector<int>& index = ops.ReducedIndex(n);
    const int reduced = ops.PanelCount(n);
    std::vector<int> rep(reduced, -1), count(reduced, 0);
    for (std::size_t p = 0; p < full.size(); ++p) {
      if (rep[index[p]] < 0) rep[index[p]] = static_cast<int>(p);
      ++count[index[p]];
    }
    // Field points, split by the side φ_t is taken from: the earlier steps (section growing here) or the later.
    struct Side {
      std::vector<double> y, z, weight;  // weight: multiplicity · Gauss weight · length · W_n
    } back, fwd;
    for (int r = 0; r < reduced; ++r) {
      const Panel& p = full[rep[r]];
      const double W = motions[n].normal_speed_m_s[rep[r]];
      if (W == 0.0) continue;
      // At the last step no later state exists (the strip's water after the hull is not marched): backward.
      Side& s = (W > 0.0 || n == steps - 1) ? back : fwd;
      for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
        const double u = rule.nodes[q];
        s.y.push_back(p.y1 + u * (p.y2 - p.y1));
        s.z.push_back(p.z1 + u * (p.z2 - p.z1));
        s.weight.push_back(count[r] * rule.weights[q] * p.Length() * W);
      }
    }
    double P = 0.0;
    // Σ weight · φ_m at the side's points; the water is at rest before the bow enters (φ = 0 before step 0).
    auto weighted = [&](const Side& s, int m) {
      if (m < 0 || s.y.empty()) return 0.0;
      const std::vector<double> phi = MarchPotential(ops, sources, m, s.y, s.z);
      double sum = 0.0;
      for (std::size_t i = 0; i < phi.size(); ++i) sum += s.weight[i] * phi[i];
      return sum;
    };
    if (!back.y.empty()) {  // φ_t = (3φ_n − 4φ_{n−1} + φ_{n−2}) / (2 dt)
      const double phi_t = (3.0 * weighted(back, n) - 4.0 * weighted(back, n - 1) + weighted(back, n - 2)) / (2.0 * dt);
      P -= rho * phi_t;
    }
    if (!fwd.y.empty()) {  // φ_t = (−3φ_n + 4φ_{n+1} − φ_{n+2}) / (2 dt), first order next to the last step
      const double phi_t =
          n + 2 < steps
              ? (-3.0 * weighted(fwd, n) + 4.0 * weighted(fwd, n + 1) - weighted(fwd, n + 2)) / (2.0 * dt)
              : (weighted(fwd, n + 1) - weighted(fwd, n)) / dt;
      P -= rho * phi_t;
    }
    power[n] = P;
  }
  return power;
}

}  // namespace hullopt::sk
