#pragma once
// The 2D transient free-surface Green function of deep water in closed form (docs/theory.md,
// 'Transient Green function: definition and properties' to 'Transient Green function: numerical pitfalls').
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
// (docs/theory.md, 'Transient Green function: numerical pitfalls', item 2). a = 0 (both points on the free
// surface at the same y) has no finite value and throws.
#include <cmath>
#include <complex>

#include "seakeeping/green/positive_logarithm.h"
#include "seakeeping/green/unit_arctangent.h"

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
/// cancels in the panel difference. With gt² = 4ax² this is K = 8a(G(x) + x² ln x), G = −Φ − xF + 2x²(C − Φ)
/// (C = (γ + ln 4)/4) an entire function of x alone, tabulated (dawson_integral_table.h) and evaluated below
/// |x| = 6. Same arguments and errors as TransientGreen; K = 0 at t = 0.
std::complex<double> TransientGreenSpaceTimeIntegral(double Y, double Z, double t, double g);

/// The lag-independent part of the kernel at one image offset (Y, Z): the square roots, the division and the
/// logarithm of the geometric argument, computed once per (field point, source point) pair and reused for
/// every lag, since x(t) = t·w with w = √g/(2√a) (a = |Z| − i|Y|).
struct TransientGreenPair {
  std::complex<double> a;      ///< |Z| − i|Y| [m]
  std::complex<double> w;      ///< x per unit lag [1/s], 0 <= arg w <= π/4
  std::complex<double> log_w;  ///< ln w
  bool conj = false;           ///< Y < 0: every result is the conjugate of the |Y| one
};

/// The pair of (Y, Z) [m] with gravity g [m/s²]. Same errors as TransientGreen (without the lag). Without
/// `with_log`, log_w is left zero: enough for H⁽⁻¹⁾ (TransientGreenTimeIntegral), which does not use it, and
/// saves the logarithm and arctangent; K needs it.
TransientGreenPair MakeTransientGreenPair(double Y, double Z, double g, bool with_log = true);

/// The same without argument checks, with half_sqrt_g = √g/2 [m^½/s] computed once by the caller: the strip
/// kernel's hot path, whose field points lie strictly in the fluid (Z < 0, finite: checked with the panels).
/// Inline, so that a loop over many pairs overlaps their square roots, division and arctangent.
inline TransientGreenPair MakeTransientGreenPairInFluid(double Y, double Z, double half_sqrt_g, bool with_log = true) {
  // Principal √a of a = |Z| − i|Y| with real arithmetic only (√a = (sqrt((r + |Z|)/2), −sqrt((r − |Z|)/2)),
  // r = |a| = |√a|²), and w = √g/(2√a) = √g conj(√a)/(2r).
  const double p = -Z, Yabs = std::fabs(Y), r = std::sqrt(p * p + Yabs * Yabs);
  const double scale = half_sqrt_g / r;
  const double r_minus_p = r - p;  // >= 0 up to rounding
  TransientGreenPair out;
  out.a = std::complex<double>(p, -Yabs);
  out.w = std::complex<double>(scale * std::sqrt(0.5 * (r + p)), scale * std::sqrt(0.5 * (r_minus_p > 0.0 ? r_minus_p : 0.0)));
  // ln w: arg w = ½ arg(conj a) in [0, π/4], whose tangent is the half-angle |Y|/(r + |Z|) (no cancellation).
  if (with_log) out.log_w = std::complex<double>(0.5 * PositiveLogarithm(std::norm(out.w)), UnitArctangent(Yabs / (r + p)));
  out.conj = Y < 0;
  return out;
}

/// MakeTransientGreenPairInFluid for n offsets (Y[k], Z[k]) at once into out[0..n): four at a time in AVX
/// arithmetic where the processor has it, with the same operations per lane, so bitwise the same pairs.
void MakeTransientGreenPairsInFluid(const double* Y, const double* Z, int n, double half_sqrt_g, bool with_log,
                                    TransientGreenPair* out);

/// H⁽⁻¹⁾ at lag t >= 0 [s] for a prepared pair (no argument checks: the strip kernel's hot path).
std::complex<double> TransientGreenTimeIntegral(const TransientGreenPair& pair, double t);

/// K at lag t > 0 [s] for a prepared pair, with log_t = ln t (shared by all pairs at one lag) and g [m/s²]
/// (which enters through pair.w). K = 0 for t = 0 is the caller's case (ln 0 is not finite).
std::complex<double> TransientGreenSpaceTimeIntegral(const TransientGreenPair& pair, double t, double log_t,
                                                     double g);

/// The two functions above at two lags t[0], t[1] > 0 of one pair, the table evaluations interleaved (the
/// strip kernel needs both ends of each time interval): out[n] is the value at t[n].
void TransientGreenTimeIntegrals2(const TransientGreenPair& pair, const double t[2], std::complex<double> out[2]);
void TransientGreenSpaceTimeIntegrals2(const TransientGreenPair& pair, const double t[2], const double log_t[2],
                                       double g, std::complex<double> out[2]);

/// The same for two pairs at once (four interleaved table evaluations): out[2p + n] is pair[p] at t[n].
void TransientGreenTimeIntegrals2x2(const TransientGreenPair pair[2], const double t[2], std::complex<double> out[4]);
void TransientGreenSpaceTimeIntegrals2x2(const TransientGreenPair pair[2], const double t[2], const double log_t[2],
                                         double g, std::complex<double> out[4]);

/// The same for four pairs (eight table evaluations): out[2p + n] is pair[p] at t[n].
void TransientGreenTimeIntegrals4x2(const TransientGreenPair pair[4], const double t[2], std::complex<double> out[8]);
void TransientGreenSpaceTimeIntegrals4x2(const TransientGreenPair pair[4], const double t[2], const double log_t[2],
                                         double g, std::complex<double> out[8]);

/// Complex Dawson function F(x) = e^{−x²} ∫_0^x e^{u²} du (libcerf).
std::complex<double> Dawson(std::complex<double> x);

/// Φ(x) = ∫_0^x F(u) du for |arg(±x)| <= π/4 or |x| < 6. For |x| < 6: Taylor expansion (through the
/// derivative recurrence of F) about the nearest node of a 0.05-spaced table (dawson_integral_table.h); for |x| >= 6 the
/// asymptotic series Φ = (γ + ln 4)/4 + ½ ln x − Σ c_n/(2n x^{2n}) − i(π/4) erfc(x). Φ is even and
/// Φ(conj x) = conj Φ(x). Throws std::domain_error outside that domain.
std::complex<double> DawsonIntegral(std::complex<double> x);

}  // namespace hullopt::sk
