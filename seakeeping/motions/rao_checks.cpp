#include "seakeeping/motions/rao_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {

void RequireFiniteRaos(const RaoTable& t) {
  for (std::size_t i = 0; i < t.omega_rad_s.size(); ++i) {
    const std::pair<const char*, std::complex<double>> v[] = {{"heave", t.heave[i]}, {"pitch", t.pitch[i]}};
    for (const auto& [name, z] : v) {
      if (std::isfinite(z.real()) && std::isfinite(z.imag())) continue;
      std::ostringstream m;
      m << name << " RAO at omega = " << t.omega_rad_s[i] << " rad/s (omega_e = " << t.omega_e_rad_s[i]
        << " rad/s) is not finite (the motion equations are singular there)";
      throw std::domain_error(m.str());
    }
  }
}

RaoPeakFit FitRaoPeak(const std::vector<double>& omega, const std::vector<std::complex<double>>& v) {
  RaoPeakFit f;
  if (v.empty()) return f;
  for (std::size_t i = 1; i < v.size(); ++i)
    if (std::abs(v[i]) > std::abs(v[f.at])) f.at = i;
  f.sampled = f.fitted = std::abs(v[f.at]);
  f.omega_fitted = omega[f.at];
  if (f.at == 0 || f.at + 1 >= v.size()) return f;
  // 1/|X|² through the three samples (Lagrange), its minimum on [ω_{at−1}, ω_{at+1}].
  const double* w = &omega[f.at - 1];
  const double y0 = 1 / std::norm(v[f.at - 1]), y1 = 1 / std::norm(v[f.at]), y2 = 1 / std::norm(v[f.at + 1]);
  const double d01 = (y1 - y0) / (w[1] - w[0]), d12 = (y2 - y1) / (w[2] - w[1]);
  const double c2 = (d12 - d01) / (w[2] - w[0]);  // curvature / 2
  if (!(c2 > 0 && std::isfinite(y0) && std::isfinite(y2))) return f;
  const double wm = std::clamp(0.5 * (w[0] + w[1]) - d01 / (2 * c2), w[0], w[2]);
  const double ym = y1 + d01 * (wm - w[1]) + c2 * (wm - w[0]) * (wm - w[1]);
  f.fitted_ok = true;
  f.fitted = ym > 0 ? 1 / std::sqrt(ym) : std::numeric_limits<double>::infinity();
  f.omega_fitted = wm;
  // Or no neighbour within the half-power band: the grid has one sample on the resonance, and the fit through
  // tails that need not be a single resonance's cannot be trusted either.
  const double half_power = f.sampled / std::sqrt(2.0);
  f.single = std::abs(v[f.at - 1]) < half_power && std::abs(v[f.at + 1]) < half_power;
  return f;
}

std::vector<std::string> RaoResonanceWarnings(const RaoTable& t, const std::string& advice) {
  std::vector<std::string> out;
  for (int q = 0; q < 2; ++q) {
    const auto& v = q == 0 ? t.heave : t.pitch;
    if (v.empty()) continue;
    const RaoPeakFit f = FitRaoPeak(t.omega_rad_s, v);
    const char* unit = q == 0 ? " m/m" : " rad/rad";
    const char* name = q == 0 ? "heave" : "pitch";
    if (f.UnderSampled()) {
      std::ostringstream m;
      m.precision(3);
      // No commas: the message goes into CSV notes as it is.
      m << name << " RAO peak is under-sampled by the frequency grid: largest sample " << f.sampled << unit
        << " at omega = " << t.omega_rad_s[f.at] << " rad/s with ";
      if (f.single)
        m << "both neighbours below 1/sqrt(2) of it (one sample in the half-power band)";
      else if (std::isfinite(f.fitted))
        m << "a single-mode fit through it and its neighbours peaking at " << f.fitted << unit << " near omega = "
          << f.omega_fitted << " rad/s";
      else
        m << "a single-mode fit through it and its neighbours unbounded near omega = " << f.omega_fitted << " rad/s";
      m << "; the peak and what integrates through it (accelerations and MSI) depend on the grid: refine "
        << "the frequencies between " << t.omega_rad_s[f.at - 1] << " and " << t.omega_rad_s[f.at + 1] << " rad/s ("
        << advice << ")";
      out.push_back(m.str());
    }
    if (!(f.sampled > kResonanceWarningRao)) continue;
    std::ostringstream m;
    m.precision(3);
    m << (q == 0 ? "heave RAO peaks at " : "pitch RAO peaks at ") << f.sampled
      << (q == 0 ? " m/m" : " rad/rad") << " at omega = " << t.omega_rad_s[f.at]
      << " rad/s: a lightly damped resonance (fast hulls peak at 1-3; above " << kResonanceWarningRao
      << " the result rests on the damping Cs)";
    out.push_back(m.str());
  }
  return out;
}

std::vector<std::string> ObliqueSamplingWarnings(const ObliqueStripResult& r, const std::string& advice) {
  std::vector<std::string> out;
  const std::size_t nh = r.headings_deg.size();
  if (nh == 0 || r.waves.empty()) return out;
  const std::size_t nf = r.waves.size() / nh;
  struct Mode {
    int dof;
    const char* name;
    const char* unit;
  };
  for (const Mode& m : {Mode{2, "heave", " m/m"}, Mode{3, "roll", " rad/rad"}, Mode{4, "pitch", " rad/rad"}}) {
    std::vector<double> headings;
    RaoPeakFit worst;
    double worst_heading = 0.0, worst_ratio = 0.0;
    std::vector<double> omega(nf), omega_worst;
    std::vector<std::complex<double>> v(nf);
    // A mode that a heading does not excite (roll and sway in head seas on a symmetric hull: round-off) has no
    // peak to sample: headings whose largest sample is below 1e-6 of the mode's largest are skipped.
    double largest = 0.0;
    for (const ObliqueWaveResult& w : r.waves) largest = std::max(largest, std::abs(w.rao[static_cast<std::size_t>(m.dof)]));
    for (std::size_t h = 0; h < nh; ++h) {
      for (std::size_t f = 0; f < nf; ++f) {
        const ObliqueWaveResult& w = r.Wave(h, f);
        omega[f] = w.omega_rad_s;
        v[f] = w.rao[static_cast<std::size_t>(m.dof)];
      }
      const RaoPeakFit fit = FitRaoPeak(omega, v);
      if (!fit.UnderSampled() || !(fit.sampled > 1e-6 * largest)) continue;
      headings.push_back(r.headings_deg[h]);
      const double ratio = std::isfinite(fit.fitted) ? fit.fitted / fit.sampled : HUGE_VAL;
      if (headings.size() == 1 || ratio > worst_ratio) {
        worst = fit;
        worst_ratio = ratio;
        worst_heading = r.headings_deg[h];
        omega_worst = omega;
      }
    }
    if (headings.empty()) continue;
    std::ostringstream s;
    s.precision(3);
    // No commas: the message goes into CSV notes as it is.
    s << m.name << " RAO peak is under-sampled by the frequency grid at " << headings.size() << " of " << nh
      << " headings (";
    for (std::size_t i = 0; i < headings.size(); ++i) s << (i ? " " : "") << headings[i];
    s << " deg); the worst at " << worst_heading << " deg: largest sample " << worst.sampled << m.unit
      << " at omega = " << omega_worst[worst.at] << " rad/s with ";
    if (worst.single)
      s << "both neighbours below 1/sqrt(2) of it";
    else if (std::isfinite(worst.fitted))
      s << "a single-mode fit peaking at " << worst.fitted << m.unit;
    else
      s << "a single-mode fit unbounded near omega = " << worst.omega_fitted << " rad/s";
    s << "; the peak and what integrates through it depend on the grid: refine the frequencies between "
      << omega_worst[worst.at - 1] << " and " << omega_worst[worst.at + 1] << " rad/s (" << advice << ")";
    out.push_back(s.str());
  }
  return out;
}

}  // namespace hullopt::sk
