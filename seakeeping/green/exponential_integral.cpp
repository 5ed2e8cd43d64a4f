#include "seakeeping/green/exponential_integral.h"

#include <cmath>
#include <limits>

#include "seakeeping/green/complex_log.h"

namespace hullopt::sk {
namespace {

constexpr double kEulerGamma = 0.57721566490153286061;
constexpr double kEps = 1e-16;
// The convergence tests compare squared magnitudes: std::abs of a complex number is a hypot call, which
// took most of the strip-theory comparator's time.
constexpr double kEps2 = kEps * kEps;

// Complex product by its four real products (std::complex's operator* adds a NaN check and a library call
// for the infinite cases, which finite arguments never reach).
inline std::complex<double> Mul(std::complex<double> a, std::complex<double> b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

// Series coefficients e1[k] = (−1)^{k+1}/(k·k!) of S below for k = 1..kSeriesTerms − 1 (k = 0 unused). The
// series is used only for |z| < 40, where the term of k = 159 is below e^{−70} (and the sum, near the
// negative real axis, above 1), so 160 entries are never exhausted.
constexpr int kSeriesTerms = 160;
struct SeriesCoefficients {
  double e1[kSeriesTerms];
  constexpr SeriesCoefficients() : e1() {
    double factorial = 1.0;
    for (int k = 1; k < kSeriesTerms; ++k) {
      factorial *= k;
      e1[k] = (k % 2 ? 1.0 : -1.0) / (static_cast<double>(k) * factorial);
    }
  }
};
constexpr SeriesCoefficients kSeries{};

// S(z) = Σ_{k>=1} (−1)^{k+1} z^k / (k·k!), so that E1(z) = −γ − ln z + S(z) (DLMF 6.6.2). Two terms per step
// (z^k and z^{k+1} advanced by z², two independent product chains, no divisions), until both terms of a
// pair are below kEps of the sum. Written in real and imaginary parts: GCC keeps std::complex sums in
// memory across the loop, and the stores and partial reloads stall it.
std::complex<double> SeriesTail(std::complex<double> z) {
  const double* c = kSeries.e1;
  const double x = z.real(), y = z.imag();
  const double x2 = x * x - y * y, y2 = 2.0 * x * y;  // z²
  double ar = x, ai = y, br = x2, bi = y2;             // z^k, z^{k+1}
  double sr = c[1] * ar + c[2] * br, si = c[1] * ai + c[2] * bi;
  for (int k = 3; k + 1 < kSeriesTerms; k += 2) {
    const double nar = ar * x2 - ai * y2, nai = ar * y2 + ai * x2;
    const double nbr = br * x2 - bi * y2, nbi = br * y2 + bi * x2;
    ar = nar;
    ai = nai;
    br = nbr;
    bi = nbi;
    const double tar = c[k] * ar, tai = c[k] * ai, tbr = c[k + 1] * br, tbi = c[k + 1] * bi;
    sr += tar + tbr;
    si += tai + tbi;
    if ((tar * tar + tai * tai) + (tbr * tbr + tbi * tbi) <= kEps2 * (sr * sr + si * si)) break;
  }
  return {sr, si};
}

// 1/v as conj(v)/|v|² (one real division instead of std::complex's scaled division), which needs |v|² in
// range: std::complex's division where it is not (the continued fraction's start value 1/tiny, its tiny
// guards).
std::complex<double> Recip(std::complex<double> v) {
  const double n = std::norm(v);
  if (!(n > 1e-290 && n < 1e290)) return 1.0 / v;
  const double inv = 1.0 / n;
  return {v.real() * inv, -v.imag() * inv};
}

// Where the power series is used: |z| <= 5, or close to the negative real axis (Re z < −2|Im z|) for |z| <
// 40, where the continued fraction converges slowly and the series has no cancellation.
bool UseSeries(std::complex<double> z) {
  const double a2 = std::norm(z);
  return a2 <= 25.0 || (z.real() < -2.0 * std::fabs(z.imag()) && a2 < 1600.0);
}

bool UseAsymptotic(std::complex<double> z) {
  return z.real() < -2.0 * std::fabs(z.imag()) && std::norm(z) >= 1600.0;
}

// |v| < tiny without a hypot (tiny² would underflow): the larger component decides within a factor √2.
bool Negligible(std::complex<double> v, double tiny) {
  return std::fabs(v.real()) < tiny && std::fabs(v.imag()) < tiny;  // (std::fmax is a library call)
}

// e^z E1(z) by the Laguerre-type J-fraction 1/(z+1− 1²/(z+3− 2²/(z+5− …))) (DLMF 6.9.1 contracted), evaluated
// with the modified Lentz algorithm.
std::complex<double> ContinuedFraction(std::complex<double> z) {
  const double tiny = 1e-300;
  std::complex<double> b = z + 1.0;
  std::complex<double> c = 1.0 / tiny;
  std::complex<double> d = Recip(b);
  std::complex<double> h = d;
  for (int i = 1; i < 20000; ++i) {
    const double an = -static_cast<double>(i) * i;
    b += 2.0;
    d = an * d + b;
    if (Negligible(d, tiny)) d = tiny;
    c = b + an * Recip(c);
    if (Negligible(c, tiny)) c = tiny;
    d = Recip(d);
    const std::complex<double> del = Mul(c, d);
    h = Mul(h, del);
    if (std::norm(del - 1.0) < kEps2) break;
  }
  return h;
}

// e^z E1(z) ~ Σ (−1)^n n!/z^{n+1} for large |z| near the negative real axis, plus the term −iπ e^z (sign of
// Im z) that the cut adds there (exponentially small, e^{Re z} < e^{−35}).
std::complex<double> Asymptotic(std::complex<double> z) {
  std::complex<double> term = 1.0 / z;
  std::complex<double> sum = term;
  double last = std::norm(term);
  for (int n = 1; n < 200; ++n) {
    term *= -static_cast<double>(n) / z;
    const double mag2 = std::norm(term);
    if (mag2 > last) break;  // optimal truncation
    sum += term;
    last = mag2;
    if (mag2 <= kEps2 * std::norm(sum)) break;
  }
  const double side = std::signbit(z.imag()) ? -1.0 : 1.0;
  return sum - std::complex<double>(0.0, side * M_PI) * std::exp(z);
}

}  // namespace

std::complex<double> ScaledExpIntE1(std::complex<double> z) {
  if (z == std::complex<double>(0.0, 0.0)) return {std::numeric_limits<double>::infinity(), 0.0};
  if (UseSeries(z)) return Mul(std::exp(z), -kEulerGamma - LogWithoutHypot(z) + SeriesTail(z));
  if (UseAsymptotic(z)) return Asymptotic(z);
  return ContinuedFraction(z);
}

std::complex<double> ExpIntE1(std::complex<double> z) {
  if (z == std::complex<double>(0.0, 0.0)) return {std::numeric_limits<double>::infinity(), 0.0};
  if (UseSeries(z)) return -kEulerGamma - LogWithoutHypot(z) + SeriesTail(z);
  return std::exp(-z) * ScaledExpIntE1(z);
}

ScaledExpIntE1Pair ScaledExpIntE1AndPlusLog(std::complex<double> z, std::complex<double> exp_z) {
  if (z == std::complex<double>(0.0, 0.0)) return {{std::numeric_limits<double>::infinity(), 0.0}, {-kEulerGamma, 0.0}};
  if (Negligible(z, 1e-300)) return {ScaledExpIntE1(z), {-kEulerGamma, 0.0}};
  if (UseSeries(z)) {
    // One exponential, one logarithm and one series for both (the two functions differ by ln z).
    const std::complex<double> tail = SeriesTail(z), log_z = LogWithoutHypot(z);
    const std::complex<double> g = -kEulerGamma + tail;
    // (1 − e^z) ln z → 0 like z ln z; formed directly, its absolute error is ~1e-16 |ln z| (1e-15 at |z| =
    // 1e-7), negligible against the O(1) sum it is added to.
    return {Mul(exp_z, g - log_z), Mul(exp_z, g) + Mul(1.0 - exp_z, log_z)};
  }
  const std::complex<double> scaled = UseAsymptotic(z) ? Asymptotic(z) : ContinuedFraction(z);
  return {scaled, scaled + LogWithoutHypot(z)};
}

ScaledExpIntE1Pair ScaledExpIntE1AndPlusLog(std::complex<double> z) { return ScaledExpIntE1AndPlusLog(z, std::exp(z)); }

std::complex<double> ScaledExpIntE1PlusLog(std::complex<double> z) { return ScaledExpIntE1AndPlusLog(z).plus_log; }

}  // namespace hullopt::sk
