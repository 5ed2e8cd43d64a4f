#include "seakeeping/memory_influence.h"

#include <cmath>

#include "seakeeping/gauss_legendre.h"
#include "seakeeping/transient_green.h"

namespace hullopt::sk {
namespace {

using cd = std::complex<double>;
constexpr double kInv2Pi = 0.5 / M_PI;
constexpr int kRulePoints = 8;  // per sub-segment; compared against the two halves for the error estimate
constexpr int kMaxDepth = 18;   // segment >= L/2^18: far below any panel feature

struct Integrand {
  const Panel& p;
  double y, z, s, g;
  double operator()(double u) const {  // u in [0, 1] along the panel
    const double qy = p.y1 + u * (p.y2 - p.y1), qz = p.z1 + u * (p.z2 - p.z1);
    return TransientGreenTimeIntegral(y - qy, z + qz, s, g).real();
  }
};

double Rule(const Integrand& f, double a, double b) {
  const auto& q = GaussLegendre01(kRulePoints);
  double sum = 0;
  for (int k = 0; k < kRulePoints; ++k) sum += q.weights[k] * f(a + q.nodes[k] * (b - a));
  return sum * (b - a);
}

double Adaptive(const Integrand& f, double a, double b, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b);
  const double left = Rule(f, a, m), right = Rule(f, m, b);
  if (depth >= kMaxDepth || std::fabs(left + right - whole) <= tol) return left + right;
  return Adaptive(f, a, m, left, 0.5 * tol, depth + 1) + Adaptive(f, m, b, right, 0.5 * tol, depth + 1);
}

}  // namespace

double MemoryNormalVelocityFromEnds(const Panel& p, cd dh1, cd dh2, double ny, double nz) {
  const double L = p.Length();
  const cd e_minus_ialpha((p.y2 - p.y1) / L, -(p.z2 - p.z1) / L);
  return kInv2Pi * (cd(nz, ny) * cd(0.0, 1.0) * e_minus_ialpha * (dh2 - dh1)).real();
}

double MemoryNormalVelocity(const Panel& p, double y, double z, double ny, double nz, double s1, double s2,
                            double g) {
  auto dh = [&](double qy, double qz) {
    return TransientGreenTimeIntegral(y - qy, z + qz, s2, g) -
           TransientGreenTimeIntegral(y - qy, z + qz, s1, g);
  };
  return MemoryNormalVelocityFromEnds(p, dh(p.y1, p.z1), dh(p.y2, p.z2), ny, nz);
}

double MemoryPotentialLevel(const Panel& p, double y, double z, double s, double g, double rel_tol) {
  if (s == 0.0) return 0.0;
  const Integrand f{p, y, z, s, g};
  const double L = p.Length();
  const double whole = Rule(f, 0.0, 1.0);
  // Absolute tolerance in u-units: the integrand is O(1) to O(10) (8Φ ~ 4 ln x), so rel_tol·max(1, |whole|).
  const double tol = rel_tol * std::fmax(1.0, std::fabs(whole));
  return L * Adaptive(f, 0.0, 1.0, whole, tol, 0);
}

double MemoryPotential(const Panel& p, double y, double z, double s1, double s2, double g) {
  return kInv2Pi * (MemoryPotentialLevel(p, y, z, s2, g) - MemoryPotentialLevel(p, y, z, s1, g));
}

}  // namespace hullopt::sk
