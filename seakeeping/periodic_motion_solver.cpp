#include "seakeeping/periodic_motion_solver.h"

#include <cmath>
#include <stdexcept>

#include "seakeeping/head_sea_wave.h"

namespace hullopt::sk {
namespace {
using cd = std::complex<double>;
}  // namespace

RaoTable SolvePeriodicRaos(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s) {
  if (omega_rad_s.empty()) throw std::invalid_argument("RAO sweep: the frequency list is empty");
  for (double w : omega_rad_s)
    if (!(w > 0.0) || !std::isfinite(w))
      throw std::invalid_argument("RAO sweep: wave frequency " + std::to_string(w) + " rad/s must be > 0");
  const StripKernel& kernel = model.kernel();
  const auto& st = model.stations();
  const int N = model.Steps();
  const double U = model.speed(), g = model.g(), rho = model.rho(), dx = model.dx(), dt = model.dt();
  const double damp = model.DampingFactor();

  // Frequency independent: S[n][m] = force[n][m] · n_z of step m (the response to a uniform unit vertical
  // velocity of the section held at step m).
  std::vector<std::vector<double>> S(N);
  for (int n = 0; n < N; ++n) {
    S[n].resize(n + 1);
    for (int m = 0; m <= n; ++m) S[n][m] = kernel.force[n][m].dot(st[m].nz);
  }

  RaoTable out;
  out.speed_m_s = U;
  out.g_m_s2 = g;
  const auto nf = static_cast<int>(omega_rad_s.size());
  out.omega_rad_s = omega_rad_s;
  out.omega_e_rad_s.resize(nf);
  out.heave.resize(nf);
  out.pitch.resize(nf);
  std::vector<int> bad(nf, 0);

#pragma omp parallel for schedule(dynamic)
  for (int f = 0; f < nf; ++f) {
    const double w = omega_rad_s[f];
    const double we = HeadSeaEncounterFrequency(w, U, g);
    const double k = w * w / g;
    const cd iwe(0.0, we), iw(0.0, w);
    std::vector<cd> lag(N);  // e^{−iω_e j Δt}
    for (int j = 0; j < N; ++j) lag[j] = std::polar(1.0, -we * j * dt);
    // Wave input at each station: e^{ikx_m} and the panel weights n_z e^{k z} (the kernel sees −iω A of
    // them).
    std::vector<cd> eikx(N);
    std::vector<Eigen::VectorXd> nz_ekz(N);
    for (int m = 0; m < N; ++m) {
      eikx[m] = std::polar(1.0, k * st[m].x_cg_m);
      nz_ekz[m] = st[m].nz.array() * (k * st[m].z_mid.array()).exp();
    }
    cd F33 = 0, F35 = 0, F3A = 0, F53 = 0, F55 = 0, F5A = 0;
    for (int n = 0; n < N; ++n) {
      const StationData& s = st[n];
      cd h = 0, p = 0, a = 0;  // kernel force per unit heave, pitch and wave amplitude
      for (int m = 0; m <= n; ++m) {
        const cd l = lag[n - m];
        h += l * S[n][m] * iwe;
        p += l * S[n][m] * (U - iwe * st[m].x_cg_m);
        a += l * (-iw) * kernel.force[n][m].dot(nz_ekz[m]) * eikx[m];
      }
      // Hydrostatic restoring, Froude–Krylov and the empirical damping (see head_sea_ship_model.h).
      const double B = s.beam_m, x = s.x_cg_m;
      h += -rho * g * B - damp * B * iwe;
      p += rho * g * B * x - damp * B * (U - iwe * x);
      a += rho * g * s.FroudeKrylovWidth(k) * eikx[n] + damp * B * iw * eikx[n];
      F33 += h * dx;
      F35 += p * dx;
      F3A += a * dx;
      F53 -= x * h * dx;
      F55 -= x * p * dx;
      F5A -= x * a * dx;
    }
    // Cramer's rule on the 2×2 system: NaN or infinity anywhere in it propagates into X (a pivoting solver
    // could silently treat a NaN row as rank-deficient and return zeros).
    const cd a11 = -we * we * model.mass() - F33, a12 = -F35, a21 = -F53,
             a22 = -we * we * model.pitch_inertia() - F55;
    const cd det = a11 * a22 - a12 * a21;
    const Eigen::Vector2cd X((a22 * F3A - a12 * F5A) / det, (a11 * F5A - a21 * F3A) / det);
    out.omega_e_rad_s[f] = we;
    out.heave[f] = X[0];
    out.pitch[f] = X[1] / k;
    if (!std::isfinite(X[0].real()) || !std::isfinite(X[0].imag()) || !std::isfinite(out.pitch[f].real()) ||
        !std::isfinite(out.pitch[f].imag()))
      bad[f] = 1;
  }
  for (int f = 0; f < nf; ++f)
    if (bad[f]) model.ReportNonFinite("heave/pitch RAO (periodic solution)", omega_rad_s[f]);
  return out;
}

}  // namespace hullopt::sk
