#include "seas/wave_spectrum.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Unnormalised DNV-RP-C205 JONSWAP density for Hs = 1 m at peak frequency wp [rad/s].
double DnvShape(double w, double wp, double gamma) {
  if (w <= 0.0) return 0.0;
  const double a_gamma = 1.0 - 0.287 * std::log(gamma);
  const double sigma = w <= wp ? 0.07 : 0.09;
  const double r = wp / w;
  const double r4 = r * r * r * r;
  const double peak = std::exp(-(w - wp) * (w - wp) / (2.0 * sigma * sigma * wp * wp));
  return a_gamma * (5.0 / 16.0) * wp * wp * wp * wp / std::pow(w, 5) * std::exp(-1.25 * r4) *
         std::pow(gamma, peak);
}

// ∫_0^∞ ωⁿ DnvShape dω, n < 4: composite Simpson on [0.2 ωp, 12 ωp] (the density is < 1e-300 below 0.2 ωp)
// plus the analytic ω⁻⁵ tail beyond 12 ωp, where exp(−1.25 (ωp/ω)⁴) = 1 − 6e−5 and the γ factor is 1.
double ShapeMoment(int n, double wp, double gamma) {
  constexpr int kIntervals = 3000;  // even; step 0.004 ωp resolves the σ = 0.07 ωp peak to ~1e-9
  const double a = 0.2 * wp, b = 12.0 * wp, h = (b - a) / kIntervals;
  double sum = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double w = a + i * h;
    const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += weight * std::pow(w, n) * DnvShape(w, wp, gamma);
  }
  const double body = sum * h / 3.0;
  const double c = (1.0 - 0.287 * std::log(gamma)) * (5.0 / 16.0) * std::pow(wp, 4) *
                   std::exp(-1.25 * std::pow(wp / b, 4));
  const double tail = c * std::pow(b, n - 4) / (4.0 - n);
  return body + tail;
}

std::string Num(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

}  // namespace

std::string SpectrumName(SpectrumType type) {
  return type == SpectrumType::kJonswap ? "jonswap" : "bretschneider";
}

SeaState::SeaState() : Tz_s(kNaN), Tp_s(kNaN) {}

SeaState SeaState::JonswapTz(double Hs_m, double Tz_s, double gamma) {
  SeaState s;
  s.Hs_m = Hs_m, s.Tz_s = Tz_s, s.gamma = gamma;
  return s;
}
SeaState SeaState::JonswapTp(double Hs_m, double Tp_s, double gamma) {
  SeaState s;
  s.Hs_m = Hs_m, s.Tp_s = Tp_s, s.gamma = gamma;
  return s;
}
SeaState SeaState::BretschneiderTz(double Hs_m, double Tz_s) {
  SeaState s;
  s.spectrum = SpectrumType::kBretschneider;
  s.Hs_m = Hs_m, s.Tz_s = Tz_s, s.gamma = 1.0;
  return s;
}

bool SeaState::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (!(Hs_m > 0.0) || !(Hs_m <= 30.0))
    return fail("Hs_m = " + Num(Hs_m) + ": significant wave height must be > 0 and <= 30 m");
  if (!std::isfinite(gamma) || gamma < 1.0 || gamma > 10.0)
    return fail("gamma = " + Num(gamma) + ": JONSWAP peak enhancement must be within 1..10");
  if (spectrum == SpectrumType::kBretschneider && gamma != 1.0)
    return fail("gamma = " + Num(gamma) + ": the Bretschneider spectrum has no peak enhancement (gamma 1)");
  const bool has_tz = !std::isnan(Tz_s), has_tp = !std::isnan(Tp_s);
  if (has_tz == has_tp) return fail("give exactly one of Tz_s and Tp_s");
  if (has_tz && !(Tz_s >= 2.0 && Tz_s <= 25.0))
    return fail("Tz_s = " + Num(Tz_s) + ": zero-crossing period must be within 2..25 s");
  if (has_tp) {
    if (!std::isfinite(Tp_s) || !(Tp_s > 0.0)) return fail("Tp_s = " + Num(Tp_s) + ": must be > 0");
    const double tz = Tp_s * ZeroCrossingToPeakPeriodRatio(gamma);
    if (!(tz >= 2.0 && tz <= 25.0))
      return fail("Tp_s = " + Num(Tp_s) + ": implies Tz = " + Num(tz) +
                  " s, zero-crossing period must be within 2..25 s");
  }
  return true;
}

double ZeroCrossingToPeakPeriodRatio(double gamma) {
  const double wp = 2.0 * kPi;  // Tp = 1 s
  return 2.0 * kPi * std::sqrt(ShapeMoment(0, wp, gamma) / ShapeMoment(2, wp, gamma));
}

WaveSpectrum::WaveSpectrum(const SeaState& sea) : sea_(sea) {
  std::string error;
  if (!sea.IsValid(&error)) throw std::invalid_argument("sea state: " + error);
  if (std::isnan(sea.Tp_s)) {
    tz_s_ = sea.Tz_s;
    tp_s_ = tz_s_ / ZeroCrossingToPeakPeriodRatio(sea.gamma);
  } else {
    tp_s_ = sea.Tp_s;
    tz_s_ = tp_s_ * ZeroCrossingToPeakPeriodRatio(sea.gamma);
  }
  omega_p_ = 2.0 * kPi / tp_s_;
  scale_ = 1.0;
  // Renormalise: m0 of the shape for Hs = 1 m must be 1/16.
  scale_ = (1.0 / 16.0) / ShapeMoment(0, omega_p_, sea.gamma);
}

double WaveSpectrum::Shape(double omega) const { return DnvShape(omega, omega_p_, sea_.gamma); }

double WaveSpectrum::Density(double omega_rad_s) const {
  return scale_ * sea_.Hs_m * sea_.Hs_m * Shape(omega_rad_s);
}

double WaveSpectrum::Moment(int n) const {
  if (n < 0 || n > 2) throw std::invalid_argument("WaveSpectrum::Moment: n must be 0, 1 or 2 (m4 diverges)");
  return scale_ * sea_.Hs_m * sea_.Hs_m * ShapeMoment(n, omega_p_, sea_.gamma);
}

}  // namespace hullopt::sk
