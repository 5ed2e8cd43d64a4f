// The deep-water pulsating-source Green function against its integral definition (direct quadrature of the
// principal-value wavenumber integral), the free-surface condition, symmetry, the outgoing far field and
// finite differences of its gradient.
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>

#include "seakeeping/green/frequency_domain_green.h"

using C = std::complex<double>;
using hullopt::sk::PulsatingSourceGreen;

namespace {

// PV∫₀^∞ e^{kZ} cos(kY)/(k − ν) dk by subtracting the pole on [0, 2ν] and composite 4-point Gauss–Legendre on
// many short intervals up to k = 60/|Z| (e^{−60} tail).
double PvIntegral(double nu, double Y, double Z) {
  auto h = [&](double k) { return std::exp(k * Z) * std::cos(k * Y); };
  const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  auto quad = [&](double a, double b, int n, auto f) {
    double s = 0;
    for (int i = 0; i < n; ++i) {
      const double lo = a + (b - a) * i / n, hi = a + (b - a) * (i + 1) / n;
      for (int q = 0; q < 4; ++q) s += 0.5 * (hi - lo) * w[q] * f(0.5 * (lo + hi) + 0.5 * (hi - lo) * x[q]);
    }
    return s;
  };
  const double hnu = h(nu);
  const double near = quad(0.0, 2 * nu, 2000, [&](double k) { return (h(k) - hnu) / (k - nu); });
  const double kmax = 2 * nu + 60.0 / std::fabs(Z);
  const double far = quad(2 * nu, kmax, 200000, [&](double k) { return h(k) / (k - nu); });
  return near + far;
}

C GreenByQuadrature(double nu, double y, double z, double eta, double zeta) {
  const double Y = y - eta, Z = z + zeta;
  const double r = std::hypot(Y, z - zeta), rp = std::hypot(Y, Z);
  return std::log(r) - std::log(rp) - 2.0 * PvIntegral(nu, Y, Z) +
         C(0.0, 2 * M_PI) * std::exp(nu * Z) * std::cos(nu * Y);
}

// Quadrature above converges to ~1e-11 relative (checked by doubling the intervals); 1e-8 tests the closed
// form.
constexpr double kTolQuadrature = 1e-8;
// Central differences with step 1e-5 m: truncation ~1e-10, rounding ~1e-11/1e-5; 1e-6 relative is safe.
constexpr double kTolFiniteDifference = 1e-6;

}  // namespace

TEST_CASE("pulsating source Green function equals its wavenumber-integral definition", "[green_fd]") {
  struct P {
    double nu, y, z, eta, zeta;
  };
  for (const P& p :
       {P{1.0, 0.3, -0.5, -0.2, -0.4}, P{0.5, 2.0, -1.0, 0.0, -0.3}, P{2.0, -0.7, -0.05, 0.4, -0.1},
        P{1.0, 0.0, -0.8, 0.0, -0.2}, P{3.0, 5.0, -0.3, 0.0, -0.2}, P{0.1, 1.0, -2.0, -1.0, -1.5},
        P{1.0, 0.5, 0.0, -0.5, -0.3}}) {
    const C g = PulsatingSourceGreen(p.nu, p.y, p.z, p.eta, p.zeta).value;
    const C q = GreenByQuadrature(p.nu, p.y, p.z, p.eta, p.zeta);
    INFO("nu " << p.nu << " p (" << p.y << ", " << p.z << ") q (" << p.eta << ", " << p.zeta << ") G " << g
               << " quad " << q);
    CHECK(std::abs(g - q) <= kTolQuadrature * std::abs(q));
  }
}

namespace {

// Si(x) = ∫₀ˣ sin t/t dt and Ci(x) = γ + ln x + ∫₀ˣ (cos t − 1)/t dt by composite 4-point Gauss–Legendre
// (smooth integrands; 400 intervals on [0, x ≤ 10] give ~1e-15).
double GaussIntegral(double x, double (*f)(double)) {
  const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const double gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  const int n = 400;
  double s = 0;
  for (int i = 0; i < n; ++i) {
    const double lo = x * i / n, hi = x * (i + 1) / n;
    for (int q = 0; q < 4; ++q) s += 0.5 * (hi - lo) * gw[q] * f(0.5 * (lo + hi) + 0.5 * (hi - lo) * gx[q]);
  }
  return s;
}
double Si(double x) {
  return GaussIntegral(x, [](double t) { return std::sin(t) / t; });
}
double Ci(double x) {
  return 0.57721566490153286061 + std::log(x) +
         GaussIntegral(x, [](double t) { return (std::cos(t) - 1) / t; });
}

}  // namespace

TEST_CASE("Green function with source and field point on the free surface (Z = 0)", "[green_fd]") {
  // At Z = 0 the wavenumber integral converges only conditionally, so the quadrature above does not apply; in
  // closed form (a = |Y|, x = νa; the limit Z → 0−): PV∫₀^∞ cos(ka)/(k − ν) dk = −cos x Ci(x) − sin x (π/2 +
  // Si(x)) (the PV part over [0, 2ν] of cos(ua)/u cancels, the rest is Si/Ci), so with ln r − ln r' = 0
  //   G = 2[cos x Ci(x) + sin x (π/2 + Si(x))] + 2πi cos x.
  // This is the lid-on-lid interaction of the panel solver. Si, Ci by quadrature to ~1e-15: 1e-11 relative.
  constexpr double kTolFreeSurface = 1e-11;
  for (double nu : {0.25, 1.0, 3.0}) {
    for (double Y : {0.05, 0.3, 1.0, -2.5}) {
      const double x = nu * std::fabs(Y);
      const C expect =
          2.0 * (std::cos(x) * Ci(x) + std::sin(x) * (M_PI / 2 + Si(x))) + C(0.0, 2 * M_PI) * std::cos(x);
      const auto g = PulsatingSourceGreen(nu, Y, 0.0, 0.0, 0.0);
      INFO("nu " << nu << " Y " << Y << " G " << g.value << " closed form " << expect);
      CHECK(std::abs(g.value - expect) <= kTolFreeSurface * std::abs(expect));
      // Free-surface condition for a source on the free surface too (Y ≠ 0).
      CHECK(std::abs(g.dz - nu * g.value) <= kTolFreeSurface * (1 + std::abs(g.value)));
    }
  }
}

TEST_CASE("gradient matches finite differences", "[green_fd]") {
  const double nu = 1.3, eta = 0.2, zeta = -0.4, h = 1e-5;
  for (auto [y, z] : {std::pair{0.9, -0.3}, {-1.5, -0.05}, {0.2, -1.2}, {4.0, -0.6}}) {
    const auto g = PulsatingSourceGreen(nu, y, z, eta, zeta);
    const C dy = (PulsatingSourceGreen(nu, y + h, z, eta, zeta).value -
                  PulsatingSourceGreen(nu, y - h, z, eta, zeta).value) /
                 (2 * h);
    const C dz = (PulsatingSourceGreen(nu, y, z + h, eta, zeta).value -
                  PulsatingSourceGreen(nu, y, z - h, eta, zeta).value) /
                 (2 * h);
    CHECK(std::abs(g.dy - dy) <= kTolFiniteDifference * (1 + std::abs(dy)));
    CHECK(std::abs(g.dz - dz) <= kTolFiniteDifference * (1 + std::abs(dz)));
  }
}

TEST_CASE("free-surface condition G_z − νG = 0 on z = 0, reciprocity, outgoing far field", "[green_fd]") {
  // Closed forms only: the identities hold to rounding (values are O(1)–O(10)).
  constexpr double kTolIdentity = 1e-11;
  for (double nu : {0.2, 1.0, 4.0}) {
    for (double y : {-3.0, -0.4, 0.0, 0.7, 6.0}) {
      const auto g = PulsatingSourceGreen(nu, y, 0.0, 0.3, -0.6);
      CHECK(std::abs(g.dz - nu * g.value) <= kTolIdentity * (1 + std::abs(g.value)));
    }
  }
  const C a = PulsatingSourceGreen(0.8, 0.4, -0.3, -1.1, -0.9).value;
  const C b = PulsatingSourceGreen(0.8, -1.1, -0.9, 0.4, -0.3).value;
  CHECK(std::abs(a - b) <= kTolIdentity * std::abs(a));
  // Far away the local terms decay like 1/(ν r'): at ν|Y| = 2000 what is left is 2πi e^{νZ} e^{−iν|Y|}.
  constexpr double kTolFar = 1e-3;
  const double nu = 1.0, Z = -0.5;
  for (double Y : {2000.0, -2000.0}) {
    const C g = PulsatingSourceGreen(nu, Y, -0.2, 0.0, -0.3).value;
    const C expect = C(0.0, 2 * M_PI) * std::exp(C(nu * Z, -nu * std::fabs(Y)));
    CHECK(std::abs(g - expect) <= kTolFar * std::abs(expect));
  }
}
