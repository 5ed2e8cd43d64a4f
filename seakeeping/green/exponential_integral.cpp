#include "seakeeping/green/exponential_integral.h"

#include <cmath>
#include <limits>

namespace hullopt::sk {
namespace {

constexpr double kEulerGamma = 0.57721566490153286061;
constexpr double kEps = 1e-16;

// S(z) = Σ_{k>=1} (−1)^{k+1} z^k / (k·k!), so that E1(z) = −γ − ln z + S(z) (DLMF 6.6.2).
std::complex<double> SeriesTail(std::complex<double> z) {
  std::complex<double> term = z;  // (−1)^{k+1} z^k / k!
  std::complex<double> sum = z;
  for (int k = 2; k < 500; ++k) {
    term *= -z / static_cast<double>(k);
    const std::complex<double> add = term / static_cast<double>(k);
    sum += add;
    if (std::abs(add) <= kEps * std::abs(sum)) break;
  }
  return sum;
}

// Where the power series is used: |z| <= 5, or close to the negative real axis (Re z < −2|Im z|) for |z| <
// 40, where the continued fraction converges slowly and the series has no cancellation.
bool UseSeries(std::complex<double> z) {
  const double a = std::abs(z);
  return a <= 5.0 || (z.real() < -2.0 * std::fabs(z.imag()) && a < 40.0);
}

bool UseAsymptotic(std::complex<double> z) {
  return z.real() < -2.0 * std::fabs(z.imag()) && std::abs(z) >= 40.0;
}

// e^z E1(z) by the Laguerre-type J-fraction 1/(z+1− 1²/(z+3− 2²/(z+5− …))) (DLMF 6.9.1 contracted), evaluated
// with the modified Lentz algorithm.
std::complex<double> ContinuedFraction(std::complex<double> z) {
  const double tiny = 1e-300;
  std::complex<double> b = z + 1.0;
  std::complex<double> c = 1.0 / tiny;
  std::complex<double> d = 1.0 / b;
  std::complex<double> h = d;
  for (int i = 1; i < 20000; ++i) {
    const double an = -static_cast<double>(i) * i;
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const std::complex<double> del = c * d;
    h *= del;
    if (std::abs(del - 1.0) < kEps) break;
  }
  return h;
}

// e^z E1(z) ~ Σ (−1)^n n!/z^{n+1} for large |z| near the negative real axis, plus the term −iπ e^z (sign of
// Im z) that the cut adds there (exponentially small, e^{Re z} < e^{−35}).
std::complex<double> Asymptotic(std::complex<double> z) {
  std::complex<double> term = 1.0 / z;
  std::complex<double> sum = term;
  double last = std::abs(term);
  for (int n = 1; n < 200; ++n) {
    term *= -static_cast<double>(n) / z;
    const double mag = std::abs(term);
    if (mag > last) break;  // optimal truncation
    sum += term;
    last = mag;
    if (mag <= kEps * std::abs(sum)) break;
  }
  const double side = std::signbit(z.imag()) ? -1.0 : 1.0;
  return sum - std::complex<double>(0.0, side * M_PI) * std::exp(z);
}

}  // namespace

std::complex<double> ScaledExpIntE1(std::complex<double> z) {
  if (z == std::complex<double>(0.0, 0.0)) return {std::numeric_limits<double>::infinity(), 0.0};
  if (UseSeries(z)) return std::exp(z) * (-kEulerGamma - std::log(z) + SeriesTail(z));
  if (UseAsymptotic(z)) return Asymptotic(z);
  return ContinuedFraction(z);
}

std::complex<double> ExpIntE1(std::complex<double> z) {
  if (z == std::complex<double>(0.0, 0.0)) return {std::numeric_limits<double>::infinity(), 0.0};
  if (UseSeries(z)) return -kEulerGamma - std::log(z) + SeriesTail(z);
  return std::exp(-z) * ScaledExpIntE1(z);
}

std::complex<double> ScaledExpIntE1PlusLog(std::complex<double> z) {
  if (std::abs(z) < 1e-300) return {-kEulerGamma, 0.0};
  if (UseSeries(z)) {
    // e^z(−γ − ln z + S) + ln z = e^z(−γ + S) + (1 − e^z) ln z, with 1 − e^z = −expm1(z) accurate near 0.
    const std::complex<double> ez = std::exp(z);
    std::complex<double> one_minus_ez;
    if (std::abs(z) < 0.5) {
      // −expm1(z) by its series: no cancellation for small |z|.
      std::complex<double> t = z, s = z;
      for (int k = 2; k < 40; ++k) {
        t *= z / static_cast<double>(k);
        s += t;
        if (std::abs(t) <= kEps * std::abs(s)) break;
      }
      one_minus_ez = -s;
    } else {
      one_minus_ez = 1.0 - ez;
    }
    return ez * (-kEulerGamma + SeriesTail(z)) + one_minus_ez * std::log(z);
  }
  return ScaledExpIntE1(z) + std::log(z);
}

}  // namespace hullopt::sk
