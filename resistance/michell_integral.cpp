#include "resistance/michell_integral.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::res {
namespace {

constexpr double kPi = 3.14159265358979323846;

// t below which the element weights use their Taylor series: the closed forms lose ~ (1e-16 / t²) relative
// accuracy to cancellation, the series truncated after t^5 errs by < t^6 / 5040 < 2e-10 at t = 0.1.
constexpr double kSeriesBelow = 0.1;

// A(t) = (1 - e^-t)/t and B(t) = (1 - (1 + t) e^-t)/t²: for an element [d0, d0 + h] and t = b h,
//   ∫ e^{-b d} (d1 - d)/h dd = e^{-b d0} h (A - B),   ∫ e^{-b d} (d - d0)/h dd = e^{-b d0} h B.
void ElementWeights(double t, double* A, double* B) {
  if (t < kSeriesBelow) {
    *A = 1.0 - t / 2.0 + t * t / 6.0 - t * t * t / 24.0 + t * t * t * t / 120.0 - t * t * t * t * t / 720.0;
    *B = 0.5 - t / 3.0 + t * t / 8.0 - t * t * t / 30.0 + t * t * t * t / 144.0 - t * t * t * t * t / 840.0;
  } else {
    const double e = std::exp(-t);
    *A = -std::expm1(-t) / t;
    *B = (-std::expm1(-t) - t * e) / (t * t);
  }
}

// Depth weights w_k with Σ_k w_k f_k = ∫ f(d) e^{-b d} dd for f linear between equally spaced nodes.
void DepthWeights(int n, double h, double b, std::vector<double>* w) {
  w->assign(n, 0.0);
  if (h <= 0.0) return;
  double A, B;
  ElementWeights(b * h, &A, &B);
  const double step = std::exp(-b * h);
  double e0 = 1.0;
  for (int k = 0; k + 1 < n; ++k) {
    (*w)[k] += e0 * h * (A - B);
    (*w)[k + 1] += e0 * h * B;
    e0 *= step;
  }
}

double Sinc(double x) { return std::fabs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

std::complex<double> Amplitude(const CentrePlaneGrid& g, double k0, double lambda, std::vector<double>* w,
                               std::vector<double>* F) {
  const double a = k0 * lambda, b = k0 * lambda * lambda;
  DepthWeights(g.depth_points, g.depth_step_m, b, w);
  const size_t nx = g.x_m.size();
  F->assign(nx, 0.0);
  for (size_t i = 0; i < nx; ++i) {
    double s = 0.0;
    const double* f = &g.f_m[i * g.depth_points];
    for (int k = 0; k < g.depth_points; ++k) s += (*w)[k] * f[k];
    (*F)[i] = s;
  }
  std::complex<double> I(0.0, 0.0);
  for (size_t i = 0; i + 1 < nx; ++i) {
    const double dx = g.x_m[i + 1] - g.x_m[i];
    const double xm = 0.5 * (g.x_m[i + 1] + g.x_m[i]);
    I += ((*F)[i + 1] - (*F)[i]) * Sinc(0.5 * a * dx) * std::polar(1.0, a * xm);
  }
  // The bow closes the body: f falls from its last-station value to 0 (a step, if that value is not 0).
  I -= (*F)[nx - 1] * std::polar(1.0, a * g.x_m[nx - 1]);
  return I;
}

// 4-point Gauss–Legendre nodes and weights on [-1, 1].
constexpr double kGaussX[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
constexpr double kGaussW[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};

}  // namespace

bool MichellOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  if (depth_points < 2 || depth_points > 1000)
    os << "depth_points = " << depth_points << ": must be in [2, 1000]";
  else if (!(intervals_per_wave >= 1.0 && intervals_per_wave <= 100.0))
    os << "intervals_per_wave = " << intervals_per_wave << ": must be in [1, 100]";
  else if (!(max_du > 0.0 && max_du <= 0.5))
    os << "max_du = " << max_du << ": must be in (0, 0.5]";
  else if (!(lambda_max >= 5.0 && lambda_max <= 1000.0))
    os << "lambda_max = " << lambda_max << ": must be in [5, 1000]";
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

std::complex<double> AmplitudeFunction(const CentrePlaneGrid& body, double k0, double lambda) {
  std::vector<double> w, F;
  return Amplitude(body, k0, lambda, &w, &F);
}

WaveResistanceResult MichellWaveResistance(const std::vector<CentrePlaneGrid>& bodies, double U, double g,
                                           double rho, const MichellOptions& opt) {
  std::string err;
  if (!opt.IsValid(&err)) throw std::invalid_argument("Michell integral: " + err);
  if (!(U > 0.0) || !(g > 0.0) || !(rho > 0.0))
    throw std::invalid_argument("Michell integral: speed, gravity and density must be > 0");
  if (bodies.empty()) throw std::invalid_argument("Michell integral: no bodies");
  const double k0 = g / (U * U);
  double x_lo = bodies[0].x_m.front(), x_hi = bodies[0].x_m.back(), y_hi = 0.0;
  for (const auto& b : bodies) {
    x_lo = std::min(x_lo, b.x_m.front());
    x_hi = std::max(x_hi, b.x_m.back());
    y_hi = std::max(y_hi, b.y_centre_m);
  }
  const double X = x_hi - x_lo;
  std::vector<double> w, F;
  auto integrand = [&](double u) {  // |A(λ)|² cosh² u with λ = cosh u
    const double lam = std::cosh(u);
    const double q = lam * std::sqrt(std::max(0.0, lam * lam - 1.0));
    std::complex<double> A(0.0, 0.0);
    for (const auto& b : bodies) {
      const std::complex<double> I = Amplitude(b, k0, lam, &w, &F);
      A += b.mirrored ? 2.0 * std::cos(k0 * b.y_centre_m * q) * I
                      : (b.y_centre_m != 0.0 ? std::polar(1.0, k0 * b.y_centre_m * q) * I : I);
    }
    return std::norm(A) * lam * lam;
  };
  const double u_max = std::acosh(opt.lambda_max), u_half = std::acosh(0.5 * opt.lambda_max);
  WaveResistanceResult res;
  double sum = 0.0, last_half = 0.0;
  for (double u0 = 0.0; u0 < u_max;) {
    const double lam = std::cosh(u0);
    const double rate = k0 * (X + 2.0 * y_hi * 2.0 * lam) * std::sinh(u0);  // phase rate dφ/du
    double du = rate > 0.0 ? 2.0 * kPi / (opt.intervals_per_wave * rate) : opt.max_du;
    du = std::min(du, opt.max_du);
    const double u1 = std::min(u_max, u0 + du);
    double part = 0.0;
    for (int j = 0; j < 4; ++j) part += kGaussW[j] * integrand(0.5 * (u0 + u1) + 0.5 * (u1 - u0) * kGaussX[j]);
    part *= 0.5 * (u1 - u0);
    sum += part;
    if (u0 >= u_half) last_half += part;
    res.evaluations += 4;
    u0 = u1;
  }
  const double c = 4.0 * rho * g * g / (kPi * U * U);
  res.R_W_N = c * sum;
  res.tail_bound_N = c * last_half;
  return res;
}

}  // namespace hullopt::res
