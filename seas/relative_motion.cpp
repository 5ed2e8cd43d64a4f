#include "seas/relative_motion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "seakeeping/motions/encounter_frequency.h"
#include "seakeeping/motions/rao_interpolation.h"

namespace hullopt::sk {

std::complex<double> RelativeMotionTransfer(std::complex<double> heave, std::complex<double> pitch, double w,
                                            double x, double g) {
  const double k = w * w / g;
  return heave - x * k * pitch - std::polar(1.0, k * x);
}

double RelativeMotionMoments::rms_m() const { return std::sqrt(std::max(m0, 0.0)); }

double RelativeMotionMoments::zero_crossings_per_s() const {
  return m0 > 0.0 ? std::sqrt(std::max(m2, 0.0) / m0) / (2.0 * M_PI) : 0.0;  // [Hz]
}

RelativeMotionMoments RelativeMotionAt(const RaoTable& rao, const WaveSpectrum& spectrum, double x,
                                       const ResponseOptions& options) {
  std::string error;
  if (!IsValidRaoTable(rao, &error)) throw std::invalid_argument(error);
  if (!options.IsValid(&error)) throw std::invalid_argument("response options: " + error);
  if (!std::isfinite(x)) throw std::invalid_argument("relative motion: station x must be finite");
  RelativeMotionMoments out;
  // The same integration range as SeaResponse (point_response.h).
  const double wp = spectrum.omega_peak();
  const double lo = std::max(rao.omega_rad_s.front(), 0.2 * wp);
  const double hi = std::min(rao.omega_rad_s.back(), 12.0 * wp);
  if (!(hi > lo)) {
    out.truncated_wave_energy_fraction = 1.0;
    return out;
  }
  const int n = options.quadrature_intervals;
  const double h = (hi - lo) / n;
  const double U = rao.speed_m_s, g = rao.g_m_s2;
  double m0_inside = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = i == n ? hi : lo + i * h;
    const double simpson = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double weight = simpson * h / 3.0 * spectrum.Density(w);
    m0_inside += weight;
    if (weight == 0.0) continue;
    const double we =
        std::clamp(HeadSeaEncounterFrequency(w, U, g), rao.omega_e_rad_s.front(), rao.omega_e_rad_s.back());
    const ComplexRao r = InterpolateRao(rao, we);
    const double hr2 = std::norm(RelativeMotionTransfer(r.heave, r.pitch, w, x, g));
    out.m0 += weight * hr2;
    out.m2 += weight * we * we * hr2;
  }
  out.truncated_wave_energy_fraction = std::clamp(1.0 - m0_inside / spectrum.Moment(0), 0.0, 1.0);
  return out;
}

double RayleighExceedance(double level, double m0) {
  if (!(level >= 0.0) || !(m0 >= 0.0))
    throw std::invalid_argument("Rayleigh exceedance: level " + std::to_string(level) + " and variance " +
                                std::to_string(m0) + " must be >= 0");
  if (m0 == 0.0) return level > 0.0 ? 0.0 : 1.0;
  return std::exp(-level * level / (2.0 * m0));
}

double DeckWetnessProbability(double f, const RelativeMotionMoments& r) {
  if (!(f > 0.0)) throw std::invalid_argument("deck wetness: freeboard " + std::to_string(f) + " m must be > 0");
  return RayleighExceedance(f, r.m0);
}

double SlammingProbability(double T, double v, const RelativeMotionMoments& r) {
  if (!(T > 0.0)) throw std::invalid_argument("slamming: draught " + std::to_string(T) + " m must be > 0");
  if (!(v >= 0.0))
    throw std::invalid_argument("slamming: threshold velocity " + std::to_string(v) + " m/s must be >= 0");
  return RayleighExceedance(T, r.m0) * RayleighExceedance(v, r.m2);
}

double OchiThresholdVelocity(double L, double g) {
  if (!(L > 0.0) || !(g > 0.0)) throw std::invalid_argument("Ochi threshold velocity: L and g must be > 0");
  return kOchiThresholdVelocityFactor * std::sqrt(g * L);
}

double EventsPerHour(double p, const RelativeMotionMoments& r) { return 3600.0 * r.zero_crossings_per_s() * p; }

}  // namespace hullopt::sk
