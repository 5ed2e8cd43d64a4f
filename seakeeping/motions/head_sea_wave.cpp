#include "seakeeping/motions/head_sea_wave.h"

#include <cmath>

namespace hullopt::sk {

double WaveFrequencyFromLength(double wave_length_m, double g_m_s2) {
  return std::sqrt(2.0 * M_PI * g_m_s2 / wave_length_m);
}

double WaveLength(double omega_rad_s, double g_m_s2) {
  return 2.0 * M_PI * g_m_s2 / (omega_rad_s * omega_rad_s);
}

HeadSea::HeadSea(std::vector<WaveComponent> components, double speed_m_s, double g_m_s2)
    : components_(std::move(components)) {
  for (const auto& c : components_)
    terms_.push_back({c.amplitude_m, c.omega_rad_s,
                      HeadSeaEncounterFrequency(c.omega_rad_s, speed_m_s, g_m_s2),
                      c.omega_rad_s * c.omega_rad_s / g_m_s2, c.phase_rad});
}

double HeadSea::Elevation(double x_m, double t_s) const {
  double z = 0.0;
  for (const auto& c : terms_) z += c.a * std::cos(c.omega_e * t_s + c.k * x_m + c.phase);
  return z;
}

double HeadSea::VerticalVelocity(double x_m, double z_m, double t_s) const {
  double w = 0.0;
  for (const auto& c : terms_)
    w -= c.omega * c.a * std::exp(c.k * z_m) * std::sin(c.omega_e * t_s + c.k * x_m + c.phase);
  return w;
}

}  // namespace hullopt::sk
