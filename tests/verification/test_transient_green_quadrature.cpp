// Verification of the transient kernel (docs/theory.md, 'Transient Green function: closed form' to
// 'Transient Green function: panel and time integrals'):
//  - H, H_t, H' against direct numerical quadrature of the integral definition at 60+ points, including
//    points within 1e−3 of the free surface and t·sqrt(g/r') up to 200 (long-double quadrature, below);
//  - the free-surface identity H_tt + gH' = 0 by a 6th-order finite difference in t;
//  - the limits G~ → 4/t (late time) and G~ → 2gt|Z|/r'² (early time);
//  - the panel and time-interval identities ('Transient Green function: panel and time integrals') and the
//    panel memory influences against brute-force quadrature.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <vector>

#include "seakeeping/green/gauss_legendre.h"
#include "seakeeping/green/memory_influence.h"
#include "seakeeping/green/transient_green.h"

namespace {
using cd = std::complex<double>;
using ld = long double;
constexpr double kG = 9.81;

// Direct quadrature of the definition after k = s² (docs/theory.md, 'Transient Green function: closed form'):
//   G~   = 4√g ∫ e^{−cs²} cos(Ys²) sin(bs) ds,      G~_t = 4g ∫ s e^{−cs²} cos(Ys²) cos(bs) ds,
//   G~_z = 4√g ∫ s² e^{−cs²} cos(Ys²) sin(bs) ds,   G~_y = −4√g ∫ s² e^{−cs²} sin(Ys²) sin(bs) ds,
// c = |Z| > 0, b = √g t. The integrand decays like a Gaussian, so no series acceleration is needed: the range
// [0, sqrt(75/c)] (e^{−75} ~ 3e−33) is cut into sub-intervals no longer than half the shortest local
// oscillation period (phase rate b + 2|Y|s) or of the Gaussian width, each integrated with 16-point
// Gauss–Legendre in long double. Also returns Σ|lobe| to judge cancellation.
struct Quad {
  ld g0 = 0, gt = 0, gz = 0, gy = 0, abs0 = 0, abst = 0, absz = 0, absy = 0;
};
Quad QuadratureOfDefinition(double Y, double Z, double t) {
  const ld c = std::fabs(Z), b = std::sqrt(static_cast<ld>(kG)) * t, y = Y;
  const ld s_max = std::sqrt(75.0L / c);
  const auto& q = hullopt::sk::GaussLegendre01(16);
  Quad out;
  ld s = 0;
  while (s < s_max) {
    // Half a period at the END of the sub-interval (the phase rate grows with s): h (b + 2|Y|(s + h)) <= π.
    const ld two_y = 2 * std::fabs(y), rate = b + two_y * s;
    ld h = two_y > 0 ? (-rate + std::sqrt(rate * rate + 4 * two_y * M_PI)) / (2 * two_y)
                     : M_PI / (rate + 1e-30L);
    h = std::fmin(h, 0.5L / std::sqrt(c));
    if (s + h > s_max) h = s_max - s;
    ld a0 = 0, at = 0, az = 0, ay = 0;
    for (int k = 0; k < 16; ++k) {
      const ld u = s + q.nodes[k] * h, w = q.weights[k] * h;
      const ld e = std::exp(-c * u * u), cy = std::cos(y * u * u), sy = std::sin(y * u * u);
      const ld sb = std::sin(b * u), cb = std::cos(b * u);
      a0 += w * e * cy * sb;
      at += w * u * e * cy * cb;
      az += w * u * u * e * cy * sb;
      ay += w * u * u * e * sy * sb;
    }
    out.g0 += a0, out.gt += at, out.gz += az, out.gy += ay;
    out.abs0 += std::fabs(a0), out.abst += std::fabs(at), out.absz += std::fabs(az),
        out.absy += std::fabs(ay);
    s += h;
  }
  const ld k4 = 4 * std::sqrt(static_cast<ld>(kG));
  out.g0 *= k4, out.abs0 *= k4, out.gt *= 4 * kG, out.abst *= 4 * kG;
  out.gz *= k4, out.absz *= k4, out.gy *= -k4, out.absy *= k4;
  return out;
}

// Required accuracy of the closed form: 1e−8 relative, where the quadrature converges. The
// quadrature "converges" for a component when its lobe sum cancels by less than 1e6 (long double keeps >= 12
// digits then).
constexpr double kTolRelative = 1e-8;
constexpr double kMaxCancellation = 1e6;

// Composite Gauss–Legendre of f over [a, b] with n sub-intervals (brute force for the §1.6 identities).
template <class T, class F>
T Composite(F f, double a, double b, int n) {
  const auto& q = hullopt::sk::GaussLegendre01(10);
  T sum{};
  const double h = (b - a) / n;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 10; ++k) sum += q.weights[k] * h * f(a + (i + q.nodes[k]) * h);
  return sum;
}
}  // namespace

TEST_CASE("kernel against direct quadrature of its integral definition", "[green][verification]") {
  // Points (r', μ = |Z|/r', β = t sqrt(g/r')): deep to 1e−4 below the surface, early to late time.
  int compared = 0, near_surface = 0, late = 0;
  double worst = 0;
  for (double rp : {0.15, 1.0, 4.0}) {
    for (double mu : {1.0, 0.6, 0.2, 0.04}) {
      for (double beta : {0.02, 1.0, 6.0, 30.0, 200.0}) {
        const double Z = -mu * rp, Y = rp * std::sqrt(1 - mu * mu) * (beta > 10 ? -1.0 : 1.0);
        const double t = beta / std::sqrt(kG / rp);
        const auto v = hullopt::sk::TransientGreen(Y, Z, t, kG);
        const Quad q = QuadratureOfDefinition(Y, Z, t);
        INFO("r' = " << rp << " mu = " << mu << " beta = " << beta);
        struct C {
          double got;
          ld want, abs;
        };
        for (const C& c : {C{v.h.real(), q.g0, q.abs0}, C{v.h_t.real(), q.gt, q.abst},
                           C{v.h_z.real(), q.gz, q.absz}, C{-v.h_z.imag(), q.gy, q.absy}}) {
          // Skip components that vanish by symmetry (G~_y at Y = 0) or where the quadrature cancels too much.
          if (c.want == 0 || !(c.abs <= kMaxCancellation * std::fabs(c.want))) continue;
          const double err =
              std::fabs(c.got - static_cast<double>(c.want)) / std::fabs(static_cast<double>(c.want));
          worst = std::fmax(worst, err);
          CHECK(err <= kTolRelative);
          ++compared;
        }
        if (beta == 200.0) ++late;
      }
    }
  }
  // Within 1e−3 of the free surface: Z = −4e−4 and −9.5e−4, several Y and t (the Cauchy–Poisson regime).
  for (double Z : {-4e-4, -9.5e-4}) {
    for (double Y : {0.05, 0.2, -0.5}) {
      for (double beta : {0.5, 5.0, 40.0}) {
        const double rp = std::hypot(Y, Z), t = beta / std::sqrt(kG / rp);
        const auto v = hullopt::sk::TransientGreen(Y, Z, t, kG);
        const Quad q = QuadratureOfDefinition(Y, Z, t);
        INFO("near surface Y = " << Y << " Z = " << Z << " beta = " << beta);
        if (q.abs0 <= kMaxCancellation * std::fabs(q.g0)) {
          const double err =
              std::fabs(v.h.real() - static_cast<double>(q.g0)) / std::fabs(static_cast<double>(q.g0));
          worst = std::fmax(worst, err);
          CHECK(err <= kTolRelative);
          ++compared, ++near_surface;
        }
        if (q.abst <= kMaxCancellation * std::fabs(q.gt)) {
          CHECK(std::fabs(v.h_t.real() - static_cast<double>(q.gt)) <=
                kTolRelative * std::fabs(static_cast<double>(q.gt)));
          ++compared, ++near_surface;
        }
      }
    }
  }
  WARN("kernel vs quadrature: " << compared << " values compared (" << near_surface
                                << " within 1e-3 of z = 0), worst relative error " << worst);
  CHECK(compared >= 150);
  CHECK(near_surface >= 20);
  CHECK(late == 12);
}

TEST_CASE("free-surface identity H_tt + g H' = 0", "[green][verification]") {
  // 6th-order central difference of H_t with step 0.02/ω_local: truncation (hω)⁶/140 ~ 5e−13, round-off
  // ~ε/(hω).
  constexpr double kTolIdentity = 1e-10;
  for (double Y : {0.0, 0.4, -1.3}) {
    for (double Z : {-0.001, -0.1, -2.0}) {
      for (double t : {0.05, 1.0, 8.0, 40.0}) {
        const double rp = std::hypot(Y, Z);
        const double w = std::fmax(std::sqrt(kG / rp), kG * t / (2 * rp));
        const double h = 0.02 / w;
        auto Ht = [&](double s) { return hullopt::sk::TransientGreen(Y, Z, s, kG).h_t; };
        const cd d = (Ht(t + 3 * h) - 9.0 * Ht(t + 2 * h) + 45.0 * Ht(t + h) - 45.0 * Ht(t - h) +
                      9.0 * Ht(t - 2 * h) - Ht(t - 3 * h)) /
                     (60 * h);
        const cd gHz = kG * hullopt::sk::TransientGreen(Y, Z, t, kG).h_z;
        INFO("Y = " << Y << " Z = " << Z << " t = " << t);
        CHECK(std::abs(d + gHz) <= kTolIdentity * std::fmax(std::abs(gHz), w * std::abs(Ht(t))));
      }
    }
  }
}

TEST_CASE("late- and early-time limits", "[green][verification]") {
  for (double Y : {0.0, 0.5, -2.0}) {
    for (double Z : {-0.2, -1.0}) {
      const double rp2 = Y * Y + Z * Z;
      // Late: G~ = 4/t + 8|Z|/(g t³) + O(t⁻⁵) (F ~ 1/(2x) + 1/(4x³)); at β ~ 300 the O(t⁻⁵) term is ~1e−9 of
      // 4/t.
      const double t_late = 300 / std::sqrt(kG / std::sqrt(rp2));
      const double late = hullopt::sk::TransientGreen(Y, Z, t_late, kG).h.real();
      CHECK(late * t_late / 4 == Approx(1.0).epsilon(3 * std::fabs(Z) / (kG * t_late * t_late)));
      CHECK(late == Approx(4 / t_late + 8 * std::fabs(Z) / (kG * std::pow(t_late, 3))).epsilon(1e-8));
      // Early: G~ = 2gt|Z|/r'² − g²t³ Re(1/(3a²)) + O(t⁵), a = |Z| − iY.
      const double t_early = 1e-3 / std::sqrt(kG / std::sqrt(rp2));
      const double early = hullopt::sk::TransientGreen(Y, Z, t_early, kG).h.real();
      const cd a(std::fabs(Z), -Y);
      const double two_terms =
          2 * kG * t_early * std::fabs(Z) / rp2 - (kG * kG * std::pow(t_early, 3) / (3.0 * a * a)).real();
      CHECK(early == Approx(2 * kG * t_early * std::fabs(Z) / rp2).epsilon(1e-5));
      CHECK(early == Approx(two_terms).epsilon(1e-11));
    }
  }
}

TEST_CASE("panel and time-interval integrals of the kernel match brute-force quadrature",
          "[green][verification]") {
  constexpr double kTolIdentity = 1e-10;  // brute-force composite Gauss–Legendre converges to ~1e−13 here
  const hullopt::sk::Panel panel{0.9, -0.02, 0.5, -0.6};
  const double L = panel.Length();
  const cd e_ia((panel.y2 - panel.y1) / L, (panel.z2 - panel.z1) / L);
  for (const auto& point : {std::pair{-0.7, -0.3}, {1.2, -0.01}, {0.2, -1.5}}) {
    const double y = point.first, z = point.second;  // named, not a structured binding: the lambda captures them
    for (double t : {0.3, 2.0, 9.0}) {
      INFO("field (" << y << ", " << z << ") t = " << t);
      // Space: ∫_panel H' ds = i e^{−iα}[H(q2) − H(q1)].
      auto Hz = [&](double u) {
        const double qy = panel.y1 + u / L * (panel.y2 - panel.y1),
                     qz = panel.z1 + u / L * (panel.z2 - panel.z1);
        return hullopt::sk::TransientGreen(y - qy, z + qz, t, kG).h_z;
      };
      const cd brute = Composite<cd>(Hz, 0.0, L, 400);
      const cd exact = cd(0, 1) / e_ia *
                       (hullopt::sk::TransientGreen(y - panel.y2, z + panel.z2, t, kG).h -
                        hullopt::sk::TransientGreen(y - panel.y1, z + panel.z1, t, kG).h);
      CHECK(std::abs(brute - exact) <= kTolIdentity * std::abs(exact));
      // Time: ∫_{t1}^{t2} H' dt = −(1/g)[H_t(t2) − H_t(t1)] and ∫ H dt = H⁽⁻¹⁾(t2) − H⁽⁻¹⁾(t1).
      const double t1 = 0.5 * t;
      auto Hz_t = [&](double s) { return hullopt::sk::TransientGreen(y - 0.7, z - 0.3, s, kG).h_z; };
      auto H_t = [&](double s) { return hullopt::sk::TransientGreen(y - 0.7, z - 0.3, s, kG).h; };
      const cd brute_hz = Composite<cd>(Hz_t, t1, t, 400);
      const cd exact_hz = -(hullopt::sk::TransientGreen(y - 0.7, z - 0.3, t, kG).h_t -
                            hullopt::sk::TransientGreen(y - 0.7, z - 0.3, t1, kG).h_t) /
                          kG;
      CHECK(std::abs(brute_hz - exact_hz) <= kTolIdentity * std::abs(exact_hz));
      const cd brute_h = Composite<cd>(H_t, t1, t, 400);
      const cd exact_h = hullopt::sk::TransientGreenTimeIntegral(y - 0.7, z - 0.3, t, kG) -
                         hullopt::sk::TransientGreenTimeIntegral(y - 0.7, z - 0.3, t1, kG);
      CHECK(std::abs(brute_h - exact_h) <= kTolIdentity * std::abs(exact_h));
    }
  }
}

TEST_CASE("panel memory influences against double quadrature", "[green][verification]") {
  // Memory normal velocity (exact) and potential (adaptive) against space × time composite Gauss–Legendre of
  // ∂G~/∂n and G~, including a waterline panel seen from a point 0.01 below the surface.
  constexpr double kTolNormal = 1e-9;  // brute force (40 × 6 sub-intervals of 10 points) converges to ~1e−12
  constexpr double kTolPotential = 1e-8;  // adaptive rule tolerance 1e−10 of O(1) values
  const hullopt::sk::Panel panel{0.8, 0.0, 0.6, -0.25};
  const double L = panel.Length();
  // Named values, not structured bindings, throughout: the lambdas capture them.
  for (const auto& field : {std::array<double, 4>{0.5, -0.01, 0.0, 1.0}, {-0.8, -0.5, 0.6, -0.8}}) {
    const double y = field[0], z = field[1], ny = field[2], nz = field[3];
    for (const auto& lags : {std::pair{0.0, 0.05}, {1.0, 1.1}, {4.0, 4.1}}) {
      const double s1 = lags.first, s2 = lags.second;
      INFO("field (" << y << ", " << z << ") lags " << s1 << ".." << s2);
      auto point = [&](double u) {
        return std::pair{panel.y1 + u / L * (panel.y2 - panel.y1), panel.z1 + u / L * (panel.z2 - panel.z1)};
      };
      auto dGdn = [&](double u) {
        const auto q = point(u);
        const double qy = q.first, qz = q.second;
        return Composite<double>(
            [&](double s) {
              const cd hz = hullopt::sk::TransientGreen(y - qy, z + qz, s, kG).h_z;
              return nz * hz.real() - ny * hz.imag();
            },
            s1, s2, 6);
      };
      auto Gt = [&](double u) {
        const auto q = point(u);
        const double qy = q.first, qz = q.second;
        return Composite<double>(
            [&](double s) { return hullopt::sk::TransientGreen(y - qy, z + qz, s, kG).h.real(); }, s1, s2, 6);
      };
      const double brute_n = Composite<double>(dGdn, 0.0, L, 40) / (2 * M_PI);
      const double brute_p = Composite<double>(Gt, 0.0, L, 40) / (2 * M_PI);
      const double exact_n = hullopt::sk::MemoryNormalVelocity(panel, y, z, ny, nz, s1, s2, kG);
      const double adapt_p = hullopt::sk::MemoryPotential(panel, y, z, s1, s2, kG);
      CHECK(exact_n == Approx(brute_n).margin(kTolNormal));
      CHECK(adapt_p == Approx(brute_p).margin(kTolPotential));
    }
  }
}

// The closed-form panel potential ∫_panel Re H⁽⁻¹⁾ ds = Re[i e^{−iα}(K(q2) − K(q1))] against adaptive
// Gauss–Kronrod quadrature of Re H⁽⁻¹⁾ along the panel (an independent route: it uses H⁽⁻¹⁾ = 8Φ only, not K).
// Field points: deep, within 1e-3 of the free surface, on the panel itself and at a panel end; lags from
// t·sqrt(g/r′) ~ 0.05 to ~200 so both the table and the asymptotic branch of K are crossed.
TEST_CASE("closed-form panel memory potential against adaptive quadrature", "[green][verification]") {
  // The quadrature is run to 1e-13 relative; the closed form loses at most ~2–3 digits to cancellation
  // between its terms (gt² <= 144|a| on the table branch, panel difference of O(|a|)-sized values), so 1e-9
  // of L·max(1, |H⁽⁻¹⁾|) separates a correct formula from a wrong one by many orders.
  constexpr double kTolClosedForm = 1e-9;
  const std::vector<hullopt::sk::Panel> panels = {
      {0.3, -0.02, 0.5, -0.3}, {0.5, -0.3, 0.2, -0.7}, {-0.4, -1.0, 0.4, -1.0}, {1.0, 0.0, 1.2, -0.25}};
  int checked = 0;
  double worst = 0.0;
  for (const auto& panel : panels) {
    std::vector<std::array<double, 2>> fields = {{0.0, -0.5}, {0.6, -0.001}, {-1.5, -0.0005}, {3.0, -2.0}};
    fields.push_back({panel.MidY(), panel.MidZ()});                                             // on the panel
    fields.push_back({panel.y1 + 0.2 * (panel.y2 - panel.y1), panel.z1 + 0.2 * (panel.z2 - panel.z1)});
    for (auto [y, z] : fields) {
      const double r = std::hypot(y - panel.MidY(), z + panel.MidZ());
      for (double tau : {0.05, 0.7, 3.0, 11.0, 40.0, 200.0}) {
        const double s = tau / std::sqrt(kG / std::fmax(r, 1e-3));
        const double closed = hullopt::sk::MemoryPotentialLevel(panel, y, z, s, kG);
        const double quad = hullopt::sk::MemoryPotentialLevelQuadrature(panel, y, z, s, kG, 1e-13);
        const double h_scale = std::abs(hullopt::sk::TransientGreenTimeIntegral(y - panel.MidY(),
                                                                                 z + panel.MidZ(), s, kG));
        INFO("panel (" << panel.y1 << "," << panel.z1 << ")-(" << panel.y2 << "," << panel.z2 << ") field (" << y
                       << "," << z << ") s " << s);
        const double scale = panel.Length() * std::fmax(1.0, h_scale);
        CHECK(closed == Approx(quad).margin(kTolClosedForm * scale));
        worst = std::fmax(worst, std::fabs(closed - quad) / scale);
        ++checked;
      }
    }
  }
  WARN("closed-form panel potential: " << checked << " values, worst error " << worst
                                       << " of L·max(1, |H⁽⁻¹⁾|)");
  CHECK(checked >= 100);
}
