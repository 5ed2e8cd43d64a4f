#pragma once
// Ursell's (1949) multipole solution for a heaving half-immersed circular cylinder in deep water: an outgoing
// source at the centre plus the wave-free multipoles (a/r)^{2m} [cos 2mθ + νr/(2m−1) cos(2m−1)θ], their
// strengths fitted in least squares to the body condition. A reference for the panel solvers, independent of
// them (F. Ursell, "On the heaving motion of a circular cylinder on the surface of a fluid", Q. J. Mech. Appl.
// Math. 2, 1949).
#include <Eigen/Dense>
#include <cmath>
#include <complex>

#include "seakeeping/green/frequency_domain_green.h"

namespace hullopt::testing {

/// Heave added mass a33/(ρπR²/2) and damping b33/(ρπR²ω/2) at ν R = ω²R/g (both independent of R, ρ, g).
struct UrsellCoefficients {
  double a33, b33;
};

// Unit heave velocity, time factor e^{iωt}. θ from the downward vertical, ζ = d + iy with depth d = −z:
// r^{−n} cos nθ = Re ζ^{−n}. R = 1 (the coefficients are dimensionless).
inline UrsellCoefficients UrsellSemicircleHeave(double nuR, int multipoles = 14, int collocation = 60) {
  using C = std::complex<double>;
  constexpr double kR = 1.0;
  const double nu = nuR / kR;
  const int nu_unknowns = multipoles + 1;
  // Basis function k at (y, z): value and ∂/∂r.
  auto basis = [&](int k, double y, double z, C* value, C* d_dr) {
    if (k == 0) {
      const auto g = hullopt::sk::PulsatingSourceGreen(nu, y, z, 0.0, 0.0);  // outgoing source at the origin (inside)
      *value = g.value;
      *d_dr = (y * g.dy + z * g.dz) / std::hypot(y, z);
      return;
    }
    const int m = k;
    const C zeta(-z, y);
    const double a2m = std::pow(kR, 2 * m);
    const double c = nu * a2m / (2 * m - 1);
    const C F = a2m * std::pow(zeta, -2 * m) + c * std::pow(zeta, -(2 * m - 1));
    const C dF = -2.0 * m * a2m * std::pow(zeta, -2 * m - 1) - (2.0 * m - 1) * c * std::pow(zeta, -2 * m);
    // Re F: ∂/∂d = Re F', ∂/∂y = −Im F'; ∂/∂z = −∂/∂d.
    const double ddd = dF.real(), ddy = -dF.imag();
    *value = F.real();
    const double r = std::hypot(y, z);
    *d_dr = (y * ddy + z * (-ddd)) / r;
  };
  Eigen::MatrixXcd A(collocation, nu_unknowns);
  Eigen::VectorXcd rhs(collocation);
  for (int i = 0; i < collocation; ++i) {
    const double th = 0.5 * M_PI * (i + 0.5) / collocation;
    const double y = kR * std::sin(th), z = -kR * std::cos(th);
    for (int k = 0; k < nu_unknowns; ++k) {
      C v, dr;
      basis(k, y, z, &v, &dr);
      A(i, k) = dr;
    }
    rhs(i) = -std::cos(th);  // ∂φ/∂r = n_z (normal into the fluid = radial)
  }
  const Eigen::VectorXcd c = A.colPivHouseholderQr().solve(rhs);
  // ∫ ψ n_z ds over the whole semicircle = 2 ∫_0^{π/2} ψ(R, θ)(−cos θ) R dθ (midpoint rule, 4000 points).
  C integral = 0.0;
  const int nq = 4000;
  for (int i = 0; i < nq; ++i) {
    const double th = 0.5 * M_PI * (i + 0.5) / nq;
    const double y = kR * std::sin(th), z = -kR * std::cos(th);
    C psi = 0.0;
    for (int k = 0; k < nu_unknowns; ++k) {
      C v, dr;
      basis(k, y, z, &v, &dr);
      psi += c(k) * v;
    }
    integral += 2.0 * psi * (-std::cos(th)) * kR * (0.5 * M_PI / nq);
  }
  const double m0 = M_PI * kR * kR / 2;
  return {-integral.real() / m0, integral.imag() / m0};
}

}  // namespace hullopt::testing
