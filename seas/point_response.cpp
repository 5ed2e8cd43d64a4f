#include "seas/point_response.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "seakeeping/motions/encounter_frequency.h"
#include "seas/iso2631_weighting.h"
#include "seakeeping/motions/rao_interpolation.h"

namespace hullopt::sk {
namespace {
constexpr double kTwoPiRad = 6.28318530717958647692;
}

bool ResponseOptions::IsValid(std::string* error) const {
  if (quadrature_intervals < 20 || quadrature_intervals % 2 != 0 || quadrature_intervals > 1000000) {
    if (error)
      *error = "quadrature_intervals = " + std::to_string(quadrature_intervals) +
               ": must be even and within 20..1000000";
    return false;
  }
  return true;
}

double PointMoments::rms_displacement_m() const { return std::sqrt(std::max(m0, 0.0)); }
double PointMoments::rms_acceleration_m_s2() const { return std::sqrt(std::max(m4, 0.0)); }

SeaResponse::SeaResponse(const RaoTable& rao, const WaveSpectrum& spectrum, const ResponseOptions& options) {
  std::string error;
  if (!IsValidRaoTable(rao, &error)) throw std::invalid_argument(error);
  if (!options.IsValid(&error)) throw std::invalid_argument("response options: " + error);
  const double wp = spectrum.omega_peak();
  omega_lo_ = std::max(rao.omega_rad_s.front(), 0.2 * wp);
  omega_hi_ = std::min(rao.omega_rad_s.back(), 12.0 * wp);
  const double m0_wave = spectrum.Moment(0);
  if (!(omega_hi_ > omega_lo_)) {  // the table misses the spectrum entirely
    truncated_fraction_ = 1.0;
    omega_hi_ = omega_lo_;
    return;
  }
  const int n = options.quadrature_intervals;
  const double h = (omega_hi_ - omega_lo_) / n;
  const double U = rao.speed_m_s, g = rao.g_m_s2;
  double m0_inside = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = i == n ? omega_hi_ : omega_lo_ + i * h;
    const double simpson = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double weight = simpson * h / 3.0 * spectrum.Density(w);
    m0_inside += weight;
    if (weight == 0.0) continue;
    // Clamp against round-off at the table ends.
    const double we =
        std::clamp(HeadSeaEncounterFrequency(w, U, g), rao.omega_e_rad_s.front(), rao.omega_e_rad_s.back());
    const ComplexRao r = InterpolateRao(rao, we);
    const std::complex<double> x3 = r.heave;
    const std::complex<double> x5 = (w * w / g) * r.pitch;  // X5/A = k · X5/(kA)
    const double aa = std::norm(x3), bb = std::real(x3 * std::conj(x5)), cc = std::norm(x5);
    const double we2 = we * we, we4 = we2 * we2;
    const double wf = Iso2631WfMagnitude(we / kTwoPiRad);
    const double pw[kMoments] = {1.0, we2, we4, we4 * we2, wf * wf * we4};
    for (int k = 0; k < kMoments; ++k) {
      a_[k] += weight * pw[k] * aa;
      b_[k] += weight * pw[k] * bb;
      c_[k] += weight * pw[k] * cc;
    }
  }
  truncated_fraction_ = std::clamp(1.0 - m0_inside / m0_wave, 0.0, 1.0);
}

PointMoments SeaResponse::Moments(double x) const {
  double m[kMoments];
  for (int k = 0; k < kMoments; ++k) m[k] = std::max(a_[k] - 2.0 * x * b_[k] + x * x * c_[k], 0.0);
  PointMoments p;
  p.m0 = m[0], p.m2 = m[1], p.m4 = m[2], p.m6 = m[3], p.m4_iso_wf = m[4];
  return p;
}

std::vector<EncounterSpectrumSample> HeadSeaEncounterSpectrum(const WaveSpectrum& spectrum, double U,
                                                              double g, double we_min, double we_max, int n) {
  std::vector<EncounterSpectrumSample> out;
  n = std::max(n, 2);
  for (int i = 0; i < n; ++i) {
    EncounterSpectrumSample s;
    s.omega_e = we_min + (we_max - we_min) * i / (n - 1);
    const double w = HeadSeaWaveFrequency(s.omega_e, U, g);
    s.wave = spectrum.Density(w) / HeadSeaEncounterJacobian(w, U, g);
    out.push_back(s);
  }
  return out;
}

std::vector<EncounterSpectrumSample> PointResponseSpectrum(const RaoTable& rao, const WaveSpectrum& spectrum,
                                                           double x, int n) {
  std::string error;
  if (!IsValidRaoTable(rao, &error)) throw std::invalid_argument(error);
  auto out = HeadSeaEncounterSpectrum(spectrum, rao.speed_m_s, rao.g_m_s2, rao.omega_e_rad_s.front(),
                                      rao.omega_e_rad_s.back(), n);
  for (auto& s : out) {
    const double w = HeadSeaWaveFrequency(s.omega_e, rao.speed_m_s, rao.g_m_s2);
    const double we = std::clamp(s.omega_e, rao.omega_e_rad_s.front(), rao.omega_e_rad_s.back());
    const ComplexRao r = InterpolateRao(rao, we);
    const std::complex<double> h = r.heave - x * (w * w / rao.g_m_s2) * r.pitch;
    s.displacement = std::norm(h) * s.wave;
    s.acceleration = std::pow(s.omega_e, 4) * s.displacement;
  }
  return out;
}

double PeakEncounterFrequency(const WaveSpectrum& spectrum, double U, double g) {
  // S_ζ(ω_e(ω)) as a function of ω is unimodal near ωp: scan, then golden-section refine.
  auto f = [&](double w) { return spectrum.Density(w) / HeadSeaEncounterJacobian(w, U, g); };
  const double wp = spectrum.omega_peak();
  double best_w = wp, best = -1.0;
  constexpr int kScan = 400;
  for (int i = 0; i <= kScan; ++i) {
    const double w = wp * (0.5 + 1.0 * i / kScan);
    const double v = f(w);
    if (v > best) best = v, best_w = w;
  }
  double a = best_w - wp / kScan, b = best_w + wp / kScan;
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - r * (b - a), d = a + r * (b - a);
  for (int it = 0; it < 60; ++it) {
    if (f(c) > f(d))
      b = d;
    else
      a = c;
    c = b - r * (b - a), d = a + r * (b - a);
  }
  return HeadSeaEncounterFrequency(0.5 * (a + b), U, g);
}

}  // namespace hullopt::sk
