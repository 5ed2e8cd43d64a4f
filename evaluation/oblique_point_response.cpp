#include "evaluation/oblique_point_response.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "seas/iso2631_weighting.h"
#include "seas/motion_sickness.h"

namespace hullopt::eval {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

using Complex = std::complex<double>;

// The RAOs of one heading as functions of ω (rotations per kA, as stored), and ω_e.
struct HeadingRaos {
  std::vector<double> omega, omega_e;
  std::vector<std::array<Complex, 6>> rao;
};

// Linear interpolation of the real and imaginary parts at w (inside [omega.front(), omega.back()]).
sk::ObliqueWaveResult InterpolateAt(const HeadingRaos& h, double w) {
  const auto it = std::upper_bound(h.omega.begin(), h.omega.end(), w);
  std::size_t i = static_cast<std::size_t>(it - h.omega.begin());
  i = std::clamp<std::size_t>(i, 1, h.omega.size() - 1);
  const double t = (w - h.omega[i - 1]) / (h.omega[i] - h.omega[i - 1]);
  sk::ObliqueWaveResult out;
  out.omega_rad_s = w;
  out.omega_e_rad_s = h.omega_e[i - 1] + t * (h.omega_e[i] - h.omega_e[i - 1]);
  for (int d = 0; d < 6; ++d) out.rao[d] = h.rao[i - 1][d] + t * (h.rao[i][d] - h.rao[i - 1][d]);
  return out;
}

}  // namespace

PointTransfer PointTransferAt(const sk::ObliqueWaveResult& wave, const ShipPoint& p, double g) {
  const double k = wave.omega_rad_s * wave.omega_rad_s / g;
  const double we2 = wave.omega_e_rad_s * wave.omega_e_rad_s;
  const Complex x2 = wave.rao[1], x3 = wave.rao[2];
  const Complex x4 = k * wave.rao[3], x5 = k * wave.rao[4], x6 = k * wave.rao[5];
  PointTransfer t;
  t.vertical = x3 + p.y_m * x4 - p.x_m * x5;
  t.lateral = x2 - p.z_m * x4 + p.x_m * x6;
  t.vertical_acceleration = -we2 * t.vertical;
  t.lateral_acceleration = -we2 * t.lateral + g * x4;
  t.roll = x4;
  return t;
}

ObliqueSeaStatistics ObliqueStatisticsInSea(const sk::ObliqueStripResult& result, std::size_t heading,
                                            double g, const sk::WaveSpectrum& spectrum,
                                            const std::vector<ShipPoint>& points,
                                            const sk::EvaluationOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw std::invalid_argument(error);
  if (heading >= result.headings_deg.size())
    throw std::invalid_argument("heading index " + std::to_string(heading) + " out of range (" +
                                std::to_string(result.headings_deg.size()) + " headings)");
  const std::size_t nf = result.waves.size() / result.headings_deg.size();
  if (nf < 2) throw std::invalid_argument("oblique point statistics: need at least 2 frequencies");
  if (!(g > 0.0)) throw std::invalid_argument("g must be > 0");
  HeadingRaos h;
  for (std::size_t f = 0; f < nf; ++f) {
    const sk::ObliqueWaveResult& w = result.Wave(heading, f);
    if (!h.omega.empty() && !(w.omega_rad_s > h.omega.back()))
      throw std::invalid_argument("oblique point statistics: the wave frequencies must increase");
    h.omega.push_back(w.omega_rad_s);
    h.omega_e.push_back(w.omega_e_rad_s);
    h.rao.push_back(w.rao);
  }
  ObliqueSeaStatistics out;
  out.heading_deg = result.headings_deg[heading];
  out.points.resize(points.size());
  // The head-sea path's range and rule (seas/point_response.cpp).
  const double wp = spectrum.omega_peak();
  const double lo = std::max(h.omega.front(), 0.2 * wp), hi = std::min(h.omega.back(), 12.0 * wp);
  const double m0_wave = spectrum.Moment(0);
  if (!(hi > lo)) {
    out.truncated_wave_energy_fraction = 1.0;
    return out;
  }
  const int n = options.response.quadrature_intervals;
  const double step = (hi - lo) / n;
  double m0_inside = 0.0, roll_var = 0.0;
  std::vector<double> lateral_var(points.size(), 0.0);
  for (int i = 0; i <= n; ++i) {
    const double w = i == n ? hi : lo + i * step;
    const double simpson = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double weight = simpson * step / 3.0 * spectrum.Density(w);
    m0_inside += weight;
    if (weight == 0.0) continue;
    const sk::ObliqueWaveResult at = InterpolateAt(h, w);
    const double we = at.omega_e_rad_s, we2 = we * we, we4 = we2 * we2;
    const double wf = sk::Iso2631WfMagnitude(we / kTwoPi);
    for (std::size_t j = 0; j < points.size(); ++j) {
      const PointTransfer t = PointTransferAt(at, points[j], g);
      const double s2 = weight * std::norm(t.vertical);
      sk::PointMoments& m = out.points[j].vertical;
      m.m0 += s2;
      m.m2 += we2 * s2;
      m.m4 += we4 * s2;
      m.m6 += we4 * we2 * s2;
      m.m4_iso_wf += wf * wf * we4 * s2;
      lateral_var[j] += weight * std::norm(t.lateral_acceleration);
      if (j == 0) roll_var += weight * std::norm(t.roll);
    }
    if (points.empty()) roll_var += weight * std::norm(at.rao[3] * (w * w / g));
  }
  out.truncated_wave_energy_fraction = std::clamp(1.0 - m0_inside / m0_wave, 0.0, 1.0);
  out.rms_roll_rad = std::sqrt(roll_var);
  for (std::size_t j = 0; j < points.size(); ++j) {
    PointSeaStatistics& s = out.points[j];
    s.rms_vertical_accel_m_s2 = s.vertical.rms_acceleration_m_s2();
    s.rms_lateral_accel_m_s2 = std::sqrt(lateral_var[j]);
    s.msi_pct = sk::MotionSicknessIncidence(s.vertical, options.msi, g);
  }
  return out;
}

}  // namespace hullopt::eval
