#include "seas/irregular_sea.h"

#include <cmath>
#include <complex>
#include <random>
#include <stdexcept>

#include "seakeeping/motions/encounter_frequency.h"
#include "seakeeping/motions/rao_interpolation.h"

namespace hullopt::sk {
namespace {
constexpr double kTwoPi = 6.28318530717958647692;
double Uniform(std::mt19937_64& gen) { return static_cast<double>(gen() >> 11) * 0x1.0p-53; }
}  // namespace

bool IrregularSeaOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (components < 10 || components > 100000)
    return fail("components = " + std::to_string(components) + ": must be within 10..100000");
  if (omega_min_rad_s < 0.0 || omega_max_rad_s < 0.0 || !std::isfinite(omega_min_rad_s) ||
      !std::isfinite(omega_max_rad_s))
    return fail("omega_min_rad_s and omega_max_rad_s must be finite and >= 0 (0 = automatic)");
  if (omega_min_rad_s > 0.0 && omega_max_rad_s > 0.0 && !(omega_max_rad_s > omega_min_rad_s))
    return fail("omega_max_rad_s must exceed omega_min_rad_s");
  return true;
}

std::vector<IrregularSeaComponent> IrregularSeaComponents(const WaveSpectrum& spectrum, double U, double g,
                                                          const IrregularSeaOptions& o) {
  std::string error;
  if (!o.IsValid(&error)) throw std::invalid_argument("irregular sea: " + error);
  const double wp = spectrum.omega_peak();
  const double w0 = o.omega_min_rad_s > 0.0 ? o.omega_min_rad_s : 0.2 * wp;
  const double w1 = o.omega_max_rad_s > 0.0 ? o.omega_max_rad_s : 5.0 * wp;
  if (!(w1 > w0)) throw std::invalid_argument("irregular sea: empty frequency band");
  const double dw = (w1 - w0) / o.components;
  std::mt19937_64 gen(o.seed);
  std::vector<IrregularSeaComponent> out;
  out.reserve(o.components);
  for (int i = 0; i < o.components; ++i) {
    IrregularSeaComponent c;
    c.omega_rad_s = w0 + (i + Uniform(gen)) * dw;
    c.omega_e_rad_s = HeadSeaEncounterFrequency(c.omega_rad_s, U, g);
    c.amplitude_m = std::sqrt(2.0 * spectrum.Density(c.omega_rad_s) * dw);
    c.phase_rad = kTwoPi * Uniform(gen);
    out.push_back(c);
  }
  return out;
}

double WaveElevationAtCg(const std::vector<IrregularSeaComponent>& components, double t) {
  double z = 0.0;
  for (const auto& c : components) z += c.amplitude_m * std::cos(c.omega_e_rad_s * t + c.phase_rad);
  return z;
}

std::vector<double> PointAccelerationTimeSeries(const RaoTable& rao,
                                                const std::vector<IrregularSeaComponent>& components,
                                                double x, double dt, int n) {
  std::string error;
  if (!IsValidRaoTable(rao, &error)) throw std::invalid_argument(error);
  // Complex acceleration amplitude of each component: −ω_e² a_i e^{iφ_i} (X3/A − x k X5/(kA)).
  std::vector<std::complex<double>> amp;
  std::vector<double> we;
  for (const auto& c : components) {
    if (c.omega_e_rad_s < rao.omega_e_rad_s.front() || c.omega_e_rad_s > rao.omega_e_rad_s.back()) continue;
    const ComplexRao r = InterpolateRao(rao, c.omega_e_rad_s);
    const double k = c.omega_rad_s * c.omega_rad_s / rao.g_m_s2;
    const std::complex<double> h = r.heave - x * k * r.pitch;
    amp.push_back(-c.omega_e_rad_s * c.omega_e_rad_s * c.amplitude_m * std::polar(1.0, c.phase_rad) * h);
    we.push_back(c.omega_e_rad_s);
  }
  // Advance each component's phasor by e^{iω_e dt} per step (one complex multiply instead of cos and sin);
  // renormalise every 1000 steps against round-off drift.
  std::vector<std::complex<double>> rot(we.size()), cur(amp);
  for (size_t i = 0; i < we.size(); ++i) rot[i] = std::polar(1.0, we[i] * dt);
  std::vector<double> a(n > 0 ? n : 0);
  for (int step = 0; step < n; ++step) {
    double sum = 0.0;
    for (size_t i = 0; i < cur.size(); ++i) {
      sum += cur[i].real();
      cur[i] *= rot[i];
    }
    a[step] = sum;
    if (step % 1000 == 999)
      for (size_t i = 0; i < cur.size(); ++i) cur[i] = amp[i] * std::polar(1.0, we[i] * dt * (step + 1));
  }
  return a;
}

}  // namespace hullopt::sk
