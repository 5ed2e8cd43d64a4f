#pragma once
// The 2D transient free-surface Green function of deep water in closed form (theory notes §1.1–1.5).
//
// Memory kernel of a source at q = (η, ζ) seen at p = (y, z), both in the fluid (z, ζ <= 0), a lag t after an
// impulsive unit source:
//   G~(Y, Z, t) = 2 ∫_0^∞ sqrt(g/k) e^{kZ} cos(kY) sin(sqrt(gk) t) dk,   Y = y − η, Z = z + ζ <= 0,
// and G~ = Re H with the analytic function of the image coordinate ζc = Z + iY
//   H(ζc, t) = 4 sqrt(g) a^{−1/2} F(x),   a = −ζc = |Z| − iY,   x = sqrt(g) t / (2 sqrt(a)),
// F the complex Dawson function (libcerf cdawson). Derivatives:
//   H_t = ∂H/∂t = (2g/a)(1 − 2xF),   H' = dH/dζc = (2 sqrt(g)/a^{3/2}) (x + (1 − 2x²)F),
//   ∂G~/∂t = Re H_t,  ∂G~/∂z = Re H',  ∂G~/∂y = −Im H',  and H_tt = −g H' (the free-surface condition).
// Time integral (used for the exact integration over a time step with piecewise-constant source strength):
//   H⁽⁻¹⁾(ζc, t) = ∫_0^t H dt' = 8 Φ(x),   Φ(x) = ∫_0^x F(u) du = (x²/2) ₂F₂(1, 1; 3/2, 2; −x²).
// Evaluation: Y >= 0 directly (then 0 <= arg x <= π/4) and Y < 0 by conjugate symmetry; for |x| >= 6 the
// algebraic asymptotic series plus the exact exponential part replaces the cancelling forms of H_t and H'
// (pitfall 2 of §1.5). a = 0 (both points on the free surface at the same y) has no finite value and throws.
#include <complex>

namespace hullopt::sk {

/// H [1/s], H_t [1/s²] and H' = dH/dζc [1/(m s)] at one image coordinate and lag.
struct TransientGreenValues {
  std::complex<double> h;
  std::complex<double> h_t;
  std::complex<double> h_z;  ///< dH/dζc: ∂G~/∂z = Re, ∂G~/∂y = −Im
};

/// Kernel at Y = y − η [m], Z = z + ζ <= 0 [m], lag t >= 0 [s], gravity g > 0 [m/s²]. Throws
/// std::domain_error for Y = Z = 0 and std::invalid_argument for Z > 0, t < 0 or g <= 0 (or non-finite
/// input).
TransientGreenValues TransientGreen(double Y, double Z, double t, double g);

/// H⁽⁻¹⁾ = ∫_0^t H(ζc, t') dt' [-] (its real part is ∫_0^t G~ dt'). Same arguments and errors as
/// TransientGreen.
std::complex<double> TransientGreenTimeIntegral(double Y, double Z, double t, double g);

/// K(ζc, t) with dK/dζc = H⁽⁻¹⁾ [m]: the space integral of the time integral, so that along a straight
/// source panel with dζc/ds = −i e^{iα}, ∫_panel H⁽⁻¹⁾ ds = i e^{−iα} [K(q2) − K(q1)] exactly. Closed form
/// (F' = 1 − 2xF): K = −8a(Φ + xF) + 2gt²(ln x − 2Φ + (γ + ln 4)/2), defined up to a function of t only, which
/// cancels in the panel difference. Same arguments and errors as TransientGreen; K = 0 at t = 0.
std::complex<double> TransientGreenSpaceTimeIntegral(double Y, double Z, double t, double g);

/// Complex Dawson function F(x) = e^{−x²} ∫_0^x e^{u²} du (libcerf).
std::complex<double> Dawson(std::complex<double> x);

/// Φ(x) = ∫_0^x F(u) du for |arg(±x)| <= π/4 or |x| < 6. For |x| < 6: Taylor expansion (through the
/// derivative recurrence of F) about the nearest node of a 0.1-spaced table of Φ and F, the table built once
/// from the Taylor series at 0 (|x| <= 2.5) and Gauss–Legendre of F along the ray (beyond); for |x| >= 6 the
/// asymptotic series Φ = (γ + ln 4)/4 + ½ ln x − Σ c_n/(2n x^{2n}) − i(π/4) erfc(x). Φ is even and
/// Φ(conj x) = conj Φ(x). Throws std::domain_error outside that domain.
std::complex<double> DawsonIntegral(std::complex<double> x);

}  // namespace hullopt::sk
