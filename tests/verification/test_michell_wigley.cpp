// Michell's integral on Wigley's parabolic hull (L/B = 10, L/T = 16): the amplitude function from the hull's
// stations against its analytic form, the wave resistance against an independent quadrature of the analytic
// amplitude (different substitution, rule and upper limit), resolution convergence, and the catamaran
// interference against the same independent reference and its two exact limits.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "resistance/calm_water_resistance.h"
#include "resistance/michell_integral.h"
#include "support/wigley_hull.h"

using namespace hullopt;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double L = 1.0, B = 0.1, T = 0.0625, g = 9.81, rho = 1000.0;

// Wave resistance from the analytic amplitude, independently of the code: λ = 1 + t² (the code uses
// λ = cosh u), composite Simpson on a uniform t grid fine enough for the highest oscillation (the code:
// Gauss–Legendre on a locally sized grid), up to λ = 200 (the code: 40). `spacing` > 0: a catamaran of two
// such hulls with centrelines `spacing` apart (interference factor 4 cos²(k0 (s/2) λ √(λ²-1))).
double ReferenceRw(double U, double spacing) {
  const double k0 = g / (U * U), lam_max = 200.0;
  const double t_max = std::sqrt(lam_max - 1.0);
  // highest phase rate in t: dφ/dλ · dλ/dt with dφ/dλ ≈ k0 (L + 2 s λ), dλ/dt = 2t
  const double rate = k0 * (L + 2.0 * spacing * lam_max) * 2.0 * t_max;
  int n = int(rate * t_max / (2.0 * kPi) * 24.0) + 2000;  // 24 intervals per period
  n += n % 2;
  const double h = t_max / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double t = i * h, lam = 1.0 + t * t;
    double amp2 = std::norm(test::WigleyAmplitude(L, B, T, k0, lam));
    if (spacing > 0.0) {
      const double c = std::cos(k0 * 0.5 * spacing * lam * std::sqrt(lam * lam - 1.0));
      amp2 *= 4.0 * c * c;
    }
    const double f = 2.0 * lam * lam * amp2 / std::sqrt(lam + 1.0);  // λ²/√(λ²-1) dλ = 2 λ²/√(λ+1) dt
    sum += f * ((i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0));
  }
  return 4.0 * rho * g * g / (kPi * U * U) * sum * h / 3.0;
}

double CodeRw(const hull::HullForm& h, double U, const res::MichellOptions& o) {
  return res::MichellWaveResistance(res::SampleCentrePlanes(h, o.depth_points), U, g, rho, o).R_W_N;
}

// Wetted surface of the Wigley hull, both sides: 2 ∫∫ √(1 + f_x² + f_d²) dx dd by 2D Gauss–Legendre (the
// code: quadrilaterals between stations).
double ReferenceSurface() {
  const double xg[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  const double wg[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891};
  const int nx = 400, nd = 100;
  double s = 0.0;
  for (int i = 0; i < nx; ++i)
    for (int a = 0; a < 5; ++a) {
      const double x = -0.5 * L + L * (i + 0.5 + 0.5 * xg[a]) / nx;
      for (int k = 0; k < nd; ++k)
        for (int c = 0; c < 5; ++c) {
          const double d = T * (k + 0.5 + 0.5 * xg[c]) / nd;
          const double wx = 1.0 - 4.0 * x * x / (L * L), wd = 1.0 - d * d / (T * T);
          const double fx = 0.5 * B * (-8.0 * x / (L * L)) * wd, fd = 0.5 * B * wx * (-2.0 * d / (T * T));
          s += wg[a] * wg[c] * std::sqrt(1.0 + fx * fx + fd * fd);
        }
    }
  return 2.0 * s * (L / nx / 2.0) * (T / nd / 2.0);
}
}  // namespace

TEST_CASE("amplitude function from the stations matches Wigley's analytic form", "[michell]") {
  // Piecewise-linear f errs by O(h²): 200 x-intervals and 100 depth intervals leave ~1e-4 of max |I|.
  constexpr double kAmplitudeTol = 2e-3;
  const hull::HullForm h = test::WigleyHull(L, B, T, 201, 201);
  const auto grids = res::SampleCentrePlanes(h, 101);
  for (double Fn : {0.3, 0.5, 1.0}) {
    const double U = Fn * std::sqrt(g * L), k0 = g / (U * U);
    double worst = 0.0, peak = 0.0;
    for (double lam = 1.0; lam < 20.0; lam += 0.037) {
      // the code's x is from AP = midships - L/2: shift the analytic phase accordingly
      const std::complex<double> an = test::WigleyAmplitude(L, B, T, k0, lam) * std::polar(1.0, k0 * lam * 0.5 * L);
      const std::complex<double> nu = res::AmplitudeFunction(grids[0], k0, lam);
      worst = std::max(worst, std::abs(nu - an));
      peak = std::max(peak, std::abs(an));
    }
    INFO("Fn " << Fn << " worst |dI| " << worst << " of max |I| " << peak);
    CHECK(worst < kAmplitudeTol * peak);
  }
}

TEST_CASE("Wigley wave resistance: code against an independent quadrature, and two resolutions", "[michell]") {
  // Acceptance: a second quadrature/resolution of the same integral agrees to 1 %.
  constexpr double kQuadratureTol = 0.01;
  const hull::HullForm fine = test::WigleyHull(L, B, T, 81, 81);
  const hull::HullForm coarse = test::WigleyHull(L, B, T, 41, 41);
  res::MichellOptions o;  // defaults: 24 depth points, 2 intervals per wave, lambda_max 40
  res::MichellOptions o2 = o;
  o2.depth_points = 48;
  o2.intervals_per_wave = 4.0;
  o2.lambda_max = 80.0;
  o2.max_du = 0.01;
  const double S = ReferenceSurface();
  std::printf("Wigley L/B 10, L/T 16: S/L^2 = %.5f\n  Fn    Cw_ref*1e3  Cw_code(41st)  Cw_code(81st,fine)\n", S / (L * L));
  for (double Fn : {0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.6, 0.7, 0.8, 1.0}) {
    const double U = Fn * std::sqrt(g * L), q = 0.5 * rho * U * U * S;
    const double ref = ReferenceRw(U, 0.0);
    const double c1 = CodeRw(coarse, U, o), c2 = CodeRw(fine, U, o2);
    std::printf("  %.2f  %10.4f  %12.4f  %12.4f\n", Fn, 1e3 * ref / q, 1e3 * c1 / q, 1e3 * c2 / q);
    INFO("Fn " << Fn);
    CHECK(std::fabs(c1 / ref - 1.0) < kQuadratureTol);
    CHECK(std::fabs(c2 / ref - 1.0) < kQuadratureTol);
  }
}

TEST_CASE("Wigley catamaran interference against the independent reference and its limits", "[michell]") {
  constexpr double kQuadratureTol = 0.01;
  const res::MichellOptions o;
  std::printf("Wigley catamaran: interference factor R_cat / (2 R_mono)\n  Fn   s/L=0.2  0.3  0.4  (ref 0.2 0.3 0.4)\n");
  for (double Fn : {0.3, 0.4, 0.5, 0.6, 0.8, 1.0}) {
    const double U = Fn * std::sqrt(g * L);
    const double mono = CodeRw(test::WigleyHull(L, B, T, 41, 41), U, o);
    double f[3], fr[3];
    int j = 0;
    for (double s : {0.2, 0.3, 0.4}) {
      const double cat = CodeRw(test::WigleyCatamaran(L, B, T, s * L, 41, 41), U, o);
      const double ref = ReferenceRw(U, s * L);
      f[j] = cat / (2.0 * mono);
      fr[j] = ref / (2.0 * ReferenceRw(U, 0.0));
      INFO("Fn " << Fn << " s/L " << s);
      CHECK(std::fabs(cat / ref - 1.0) < kQuadratureTol);
      ++j;
    }
    std::printf("  %.1f  %.3f %.3f %.3f  (%.3f %.3f %.3f)\n", Fn, f[0], f[1], f[2], fr[0], fr[1], fr[2]);
  }
  // Exact limits: hulls on top of each other are one hull of twice the breadth (Michell is quadratic in f):
  // factor 2; far apart the interference averages out: factor 1 (checked at Fn 0.5, s = 20 L, within the
  // residual oscillation of cos² over the finite λ range, a few per mille).
  constexpr double kLimitTol = 0.02;
  const double U = 0.5 * std::sqrt(g * L);
  const double mono = CodeRw(test::WigleyHull(L, B, T, 41, 41), U, o);
  CHECK(CodeRw(test::WigleyCatamaran(L, B, T, 1e-9, 41, 41), U, o) / (2.0 * mono) == Approx(2.0).epsilon(1e-6));
  res::MichellOptions wide = o;
  wide.lambda_max = 10.0;
  const double mono10 = CodeRw(test::WigleyHull(L, B, T, 41, 41), U, wide);
  CHECK(CodeRw(test::WigleyCatamaran(L, B, T, 20.0 * L, 41, 41), U, wide) / (2.0 * mono10) ==
        Approx(1.0).epsilon(kLimitTol));
}

TEST_CASE("Wigley wetted surface against 2D quadrature of the analytic surface", "[surface]") {
  // 81 stations x 81 points: chords of the parabolic waterlines and sections underestimate by O(h²) ~ 1e-4.
  constexpr double kSurfaceTol = 1e-3;
  const double S = ReferenceSurface();
  const hull::HullForm h = test::WigleyHull(L, B, T, 81, 81);
  res::ResistanceOptions ro;
  const res::CalmWaterResistance model(h, ro);
  CHECK(model.WettedSurface_m2() == Approx(S).epsilon(kSurfaceTol));
}
