#include "seakeeping/motions/periodic_motion_solver.h"

#include <cmath>
#include <stdexcept>

#include "seakeeping/motions/encounter_frequency.h"

namespace hullopt::sk {
namespace {
using cd = std::complex<double>;

void CheckFrequencies(const std::vector<double>& omega_rad_s) {
  if (omega_rad_s.empty()) throw std::invalid_argument("RAO sweep: the frequency list is empty");
  for (double w : omega_rad_s)
    if (!(w > 0.0) || !std::isfinite(w))
      throw std::invalid_argument("RAO sweep: wave frequency " + std::to_string(w) + " rad/s must be > 0");
}
}  // namespace

HeadSeaCoefficients PeriodicCoefficients(const HeadSeaShipModel& model, double w,
                                         const PeriodicStripForce& strip, PeriodicKinematics kinematics) {
  const auto& st = model.stations();
  const int N = model.Steps();
  const double U = model.speed(), g = model.g(), rho = model.rho(), dt = model.dt();
  const double damp = model.DampingFactor();
  const double we = HeadSeaEncounterFrequency(w, U, g);
  const double k = w * w / g;
  // iwe: the motion's d/dt (exact or the trapezoid's); the wave's own rates stay exact (iω).
  const double wm = kinematics == PeriodicKinematics::kExact ? we : 2.0 / dt * std::tan(0.5 * we * dt);
  const cd iwe(0.0, wm), iw(0.0, w);
  std::vector<cd> lag(N);  // e^{−iω_e j Δt}: the strip now at step n was at step m (n − m) steps ago
  for (int j = 0; j < N; ++j) lag[j] = std::polar(1.0, -we * j * dt);
  // Wave input at each station: e^{ikx_m} and the panel weights n_z e^{k z} (the strip sees −iω A times
  // them).
  std::vector<cd> eikx(N);
  std::vector<Eigen::VectorXd> nz_ekz(N);
  for (int m = 0; m < N; ++m) {
    eikx[m] = std::polar(1.0, k * st[m].x_cg_m);
    nz_ekz[m] = st[m].nz.array() * (k * st[m].z_mid.array()).exp();
  }
  HeadSeaCoefficients c;
  c.omega_rad_s = w;
  c.omega_e_rad_s = we;
  c.motion_omega_rad_s = wm;
  c.k_rad_m = k;
  c.mass_kg = model.mass();
  c.inertia_kg_m2 = model.pitch_inertia();
  for (int n = 0; n < N; ++n) {
    const StationData& s = st[n];
    cd h = 0, p = 0, a = 0;  // strip force per unit heave, pitch and wave amplitude
    for (int m = strip.first_step(n); m <= n; ++m) {
      const cd l = lag[n - m];
      const cd unit = strip.dot(n, m, st[m].nz, we);  // uniform unit vertical velocity of section m
      h += l * unit * iwe;
      p += l * unit * (U - iwe * st[m].x_cg_m);
      a += l * (-iw) * strip.dot(n, m, nz_ekz[m], we) * eikx[m];
    }
    // The empirical damping (against v − ζ_t), hydrostatic restoring and Froude–Krylov (head_sea_ship_model.h).
    const double B = s.beam_m, x = s.x_cg_m, dx = s.weight_m;
    h += -damp * B * iwe;
    p += -damp * B * (U - iwe * x);
    const cd fk = rho * g * s.FroudeKrylovWidth(k) * eikx[n], dw = damp * B * iw * eikx[n];
    c.moving[0][0] += h * dx;
    c.moving[0][1] += p * dx;
    c.moving[1][0] -= x * h * dx;
    c.moving[1][1] -= x * p * dx;
    c.restoring[0][0] += rho * g * B * dx;
    c.restoring[0][1] -= rho * g * B * x * dx;
    c.restoring[1][0] -= rho * g * B * x * dx;
    c.restoring[1][1] += rho * g * B * x * x * dx;
    c.diffraction[0] += a * dx;
    c.diffraction[1] -= x * a * dx;
    c.froude_krylov[0] += fk * dx;
    c.froude_krylov[1] -= x * fk * dx;
    c.damping_wave[0] += dw * dx;
    c.damping_wave[1] -= x * dw * dx;
  }
  return c;
}

std::array<std::complex<double>, 2> SolvePeriodicFrequency(const HeadSeaShipModel& model, double w,
                                                           const PeriodicStripForce& strip,
                                                           PeriodicKinematics kinematics) {
  return PeriodicCoefficients(model, w, strip, kinematics).Solve();
}

std::vector<HeadSeaCoefficients> PeriodicCoefficientSweep(const HeadSeaShipModel& model,
                                                          const std::vector<double>& omega_rad_s,
                                                          const PeriodicStripForce& strip,
                                                          PeriodicKinematics kinematics) {
  CheckFrequencies(omega_rad_s);
  std::vector<HeadSeaCoefficients> out(omega_rad_s.size());
#pragma omp parallel for schedule(dynamic)
  for (int f = 0; f < static_cast<int>(omega_rad_s.size()); ++f)
    out[f] = PeriodicCoefficients(model, omega_rad_s[f], strip, kinematics);
  return out;
}

PeriodicStripForce KernelStripForce(const StripKernel& kernel) {
  PeriodicStripForce strip;
  strip.first_step = [](int) { return 0; };
  strip.dot = [&kernel](int n, int m, const Eigen::VectorXd& v, double) -> std::complex<double> {
    return kernel.force[n][m].dot(v);
  };
  return strip;
}

RaoTable SolvePeriodicRaos(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                           const PeriodicStripForce& strip, PeriodicKinematics kinematics) {
  CheckFrequencies(omega_rad_s);
  RaoTable out;
  out.speed_m_s = model.speed();
  out.g_m_s2 = model.g();
  const auto nf = static_cast<int>(omega_rad_s.size());
  out.omega_rad_s = omega_rad_s;
  out.omega_e_rad_s.resize(nf);
  out.heave.resize(nf);
  out.pitch.resize(nf);
  std::vector<int> bad(nf, 0);
#pragma omp parallel for schedule(dynamic)
  for (int f = 0; f < nf; ++f) {
    const auto x = SolvePeriodicFrequency(model, omega_rad_s[f], strip, kinematics);
    out.omega_e_rad_s[f] = HeadSeaEncounterFrequency(omega_rad_s[f], model.speed(), model.g());
    out.heave[f] = x[0];
    out.pitch[f] = x[1];
    bad[f] = !(std::isfinite(x[0].real()) && std::isfinite(x[0].imag()) && std::isfinite(x[1].real()) &&
               std::isfinite(x[1].imag()));
  }
  for (int f = 0; f < nf; ++f)
    if (bad[f]) model.ReportNonFinite("heave/pitch RAO (periodic solution)", omega_rad_s[f]);
  return out;
}

RaoTable SolvePeriodicRaos(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                           PeriodicKinematics kinematics) {
  return SolvePeriodicRaos(model, omega_rad_s, KernelStripForce(model.kernel()), kinematics);
}

}  // namespace hullopt::sk
