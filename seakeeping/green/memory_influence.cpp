#include "seakeeping/green/memory_influence.h"

#include <cmath>
#include <utility>

#include "seakeeping/green/transient_green.h"

namespace hullopt::sk {
namespace {

using cd = std::complex<double>;
constexpr double kInv2Pi = 0.5 / M_PI;
constexpr int kMaxDepth = 18;  // segment >= L/2^18: far below any panel feature

// Gauss–Kronrod 7/15 on [−1, 1] (QUADPACK qk15): Kronrod nodes (descending; the odd-indexed ones are the
// Gauss nodes), Kronrod weights and the 7-point Gauss weights (checked when written: the 15-point rule
// integrates x^k on [−1, 1] exactly for k <= 22, the 7-point rule for k <= 13).
constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                            0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                            0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                            0.207784955007898467600689403773245, 0.0};
constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                            0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                            0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                            0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

// 3- and 5-point Gauss–Legendre on [−1, 1] (nodes ±sqrt(3/5), 0 and ±x5, 0), weights halved for [0, 1].
const double kG3 = std::sqrt(0.6);
constexpr double kX5[2] = {0.906179845938663992797626878299392, 0.538469310105683091036314420700208};
constexpr double kW5[3] = {0.5 * 0.236926885056189087514264040719918,
                           0.5 * 0.478628670499366468041291514835639,
                           0.5 * 0.568888888888888888888888888888889};

struct Integrand {
  const Panel& p;
  double y, z, s, g;
  double operator()(double u) const {  // u in [0, 1] along the panel
    const double qy = p.y1 + u * (p.y2 - p.y1), qz = p.z1 + u * (p.z2 - p.z1);
    return TransientGreenTimeIntegral(y - qy, z + qz, s, g).real();
  }
};

// Kronrod 15-point estimate on [a, b] and its difference from the embedded 7-point Gauss rule.
std::pair<double, double> Kronrod(const Integrand& f, double a, double b) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  const double fc = f(c);
  double k = kWgk[7] * fc, gs = kWg[3] * fc;
  for (int i = 0; i < 7; ++i) {
    const double sum = f(c - h * kXgk[i]) + f(c + h * kXgk[i]);
    k += kWgk[i] * sum;
    if (i % 2 == 1) gs += kWg[i / 2] * sum;
  }
  return {k * h, std::fabs(k - gs) * h};
}

double Adaptive(const Integrand& f, double a, double b, double tol, int depth) {
  const auto [value, error] = Kronrod(f, a, b);
  if (depth >= kMaxDepth || error <= tol) return value;
  const double m = 0.5 * (a + b);
  return Adaptive(f, a, m, 0.5 * tol, depth + 1) + Adaptive(f, m, b, 0.5 * tol, depth + 1);
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

double MemoryPotentialLevelQuadrature(const Panel& p, double y, double z, double s, double g, double rel_tol) {
  if (s == 0.0) return 0.0;
  const Integrand f{p, y, z, s, g};
  // Cheap first try for the (many) smooth cases, e.g. far panels: 3- and 5-point Gauss agreeing to the
  // tolerance leave the 5-point value accurate far beyond it. Otherwise adaptive Gauss–Kronrod 7/15.
  // Absolute tolerance in u-units: the integrand is O(1) to O(10) (8Φ ~ 4 ln x), so rel_tol·max(1,
  // |estimate|).
  const double g3 = (5.0 * (f(0.5 - 0.5 * kG3) + f(0.5 + 0.5 * kG3)) + 8.0 * f(0.5)) / 18.0;
  const double g5 = kW5[0] * (f(0.5 - 0.5 * kX5[0]) + f(0.5 + 0.5 * kX5[0])) +
                    kW5[1] * (f(0.5 - 0.5 * kX5[1]) + f(0.5 + 0.5 * kX5[1])) + kW5[2] * f(0.5);
  const double tol = rel_tol * std::fmax(1.0, std::fabs(g5));
  if (std::fabs(g5 - g3) <= tol) return p.Length() * g5;
  const auto [first, error] = Kronrod(f, 0.0, 1.0);
  if (error <= tol) return p.Length() * first;
  return p.Length() * (Adaptive(f, 0.0, 0.5, 0.5 * tol, 1) + Adaptive(f, 0.5, 1.0, 0.5 * tol, 1));
}

double MemoryPotentialLevelFromEnds(const Panel& p, cd k1, cd k2) {
  const double L = p.Length();
  const cd e_minus_ialpha((p.y2 - p.y1) / L, -(p.z2 - p.z1) / L);
  return (cd(0.0, 1.0) * e_minus_ialpha * (k2 - k1)).real();
}

double MemoryPotentialLevel(const Panel& p, double y, double z, double s, double g) {
  if (s == 0.0) return 0.0;
  return MemoryPotentialLevelFromEnds(p, TransientGreenSpaceTimeIntegral(y - p.y1, z + p.z1, s, g),
                                      TransientGreenSpaceTimeIntegral(y - p.y2, z + p.z2, s, g));
}

double MemoryPotential(const Panel& p, double y, double z, double s1, double s2, double g) {
  return kInv2Pi * (MemoryPotentialLevel(p, y, z, s2, g) - MemoryPotentialLevel(p, y, z, s1, g));
}

}  // namespace hullopt::sk
