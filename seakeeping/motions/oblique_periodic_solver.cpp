#include "seakeeping/motions/oblique_periodic_solver.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {
namespace {
using cd = std::complex<double>;
using Vector6cd = Eigen::Matrix<cd, 6, 1>;

// cos and sin of a heading in degrees, exact at multiples of 90° (so that head, following and beam seas have
// no round-off sway or heave input).
void HeadingCosSin(double deg, double* c, double* s) {
  const double r = std::remainder(deg, 360.0);
  if (r == 0.0)
    *c = 1.0, *s = 0.0;
  else if (r == 90.0)
    *c = 0.0, *s = 1.0;
  else if (r == 180.0 || r == -180.0)
    *c = -1.0, *s = 0.0;
  else if (r == -90.0)
    *c = 0.0, *s = -1.0;
  else
    *c = std::cos(r * M_PI / 180.0), *s = std::sin(r * M_PI / 180.0);
}

// ∫_0^1 e^{a t} dt and ∫_0^1 t e^{a t} dt, by their series where the closed forms cancel.
void ExpMoments(cd a, cd* m0, cd* m1) {
  if (std::abs(a) < 0.02) {
    *m0 = 1.0 + a * (1.0 / 2 + a * (1.0 / 6 + a * (1.0 / 24 + a * (1.0 / 120 + a / 720.0))));
    *m1 = 0.5 + a * (1.0 / 3 + a * (1.0 / 8 + a * (1.0 / 30 + a * (1.0 / 144 + a / 840.0))));
    return;
  }
  const cd e = std::exp(a);
  *m0 = (e - 1.0) / a;
  *m1 = (e * (a - 1.0) + 1.0) / (a * a);
}

// −∫ e^{kz − i ky y} (n_y, n_z, y n_z − z n_y) dl over the panels (n into the fluid), exact along straight
// panels: the Froude–Krylov (sway, vertical, roll about y = z = 0) per unit ρ g A of the incident pressure at
// the section; at k = 0 its vertical entry is the waterline integral ∫ e^{−i ky y} dy (the width B at ky =
// 0).
Eigen::Vector3cd PressureIntegrals(const std::vector<Panel>& panels, double k, double ky) {
  Eigen::Vector3cd out = Eigen::Vector3cd::Zero();
  for (const Panel& p : panels) {
    const auto n = p.Normal();
    const double L = p.Length(), dy = p.y2 - p.y1, dz = p.z2 - p.z1;
    cd m0, m1;
    ExpMoments(cd(k * dz, -ky * dy), &m0, &m1);
    const cd base = L * std::exp(cd(k * p.z1, -ky * p.y1));
    out(0) -= base * n[0] * m0;
    out(1) -= base * n[1] * m0;
    out(2) -= base * ((p.y1 * n[1] - p.z1 * n[0]) * m0 + (dy * n[1] - dz * n[0]) * m1);
  }
  return out;
}

// A section's (sway force, vertical force, roll moment about y = z = 0) as generalised forces on the dofs
// (index 1 sway .. 5 yaw; 0 surge stays zero) of a section at x from the CG, roll about the CG's height z_G.
Vector6cd Generalised(const Eigen::Vector3cd& f, double x, double zg) {
  Vector6cd g;
  g << 0.0, f(0), f(1), f(2) + zg * f(0), -x * f(1), x * f(0);
  return g;
}

}  // namespace

bool ObliquePeriodicOptions::IsValid(std::string* error) const {
  std::string e;
  if (!mass.IsValid(&e)) {
    if (error) *error = "mass: " + e;
    return false;
  }
  if (!roll.IsValid(&e)) {
    if (error) *error = "roll: " + e;
    return false;
  }
  return true;
}

ObliquePeriodicStripForce KernelObliqueStripForce(const StripKernel& kernel) {
  if (static_cast<int>(kernel.lateral_force.size()) != kernel.Steps())
    throw std::invalid_argument(
        "oblique periodic solver: the strip kernel has no lateral rows (build it with "
        "StripOperatorOptions::lateral_rows on full sections)");
  ObliquePeriodicStripForce strip;
  strip.first_step = [](int) { return 0; };
  strip.dot = [&kernel](int n, int m, const Eigen::VectorXcd& v, double) -> Eigen::Vector3cd {
    const Eigen::VectorXd re = v.real(), im = v.imag();
    const Eigen::MatrixXd& lat = kernel.lateral_force[n][m];
    const Eigen::RowVectorXd& vert = kernel.force[n][m];
    if (lat.cols() == 0) return Eigen::Vector3cd::Zero();  // a dry step: no panels, no force (and no rows to take)
    return {cd(lat.row(0).dot(re), lat.row(0).dot(im)), cd(vert.dot(re), vert.dot(im)),
            cd(lat.row(1).dot(re), lat.row(1).dot(im))};
  };
  return strip;
}

ObliqueStripResult SolveObliquePeriodic(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                                        const std::vector<double>& headings_deg,
                                        const ObliquePeriodicOptions& options,
                                        const ObliquePeriodicStripForce& strip) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument("oblique periodic solver: " + err);
  if (omega_rad_s.empty())
    throw std::invalid_argument("oblique periodic solver: the frequency list is empty");
  for (double w : omega_rad_s)
    if (!(w > 0.0) || !std::isfinite(w))
      throw std::invalid_argument("oblique periodic solver: omega = " + std::to_string(w) +
                                  " rad/s must be > 0");
  if (headings_deg.empty()) throw std::invalid_argument("oblique periodic solver: the heading list is empty");
  for (double b : headings_deg)
    if (!std::isfinite(b)) throw std::invalid_argument("oblique periodic solver: a heading is not finite");

  const StripKernel& K = model.kernel();
  const auto& st = model.stations();
  const int N = model.Steps();
  const double U = model.speed(), g = model.g(), rho = model.rho(), dt = model.dt();
  const double damp = model.DampingFactor(), zg = options.mass.z_g_m;
  const std::size_t nh = headings_deg.size(), nf = omega_rad_s.size();
  for (std::size_t h = 0; h < nh; ++h)
    for (double w : omega_rad_s) {
      double c, s;
      HeadingCosSin(headings_deg[h], &c, &s);
      const double we = w - w * w / g * U * c;
      if (!(we > 0.0)) {
        std::ostringstream os;
        os << "oblique periodic solver: encounter frequency omega_e = " << we
           << " rad/s <= 0 at omega = " << w << " rad/s, heading " << headings_deg[h] << " deg, speed " << U
           << " m/s (following and quartering seas with omega_e <= 0 are not solved)";
        throw std::domain_error(os.str());
      }
    }

  // Mass (the model's M and I55), hydrostatics of the kernel's sections, restoring: ρ g V GM_T for roll, the
  // head-sea strip sums for heave and pitch.
  ObliqueStripResult out;
  out.headings_deg = headings_deg;
  std::vector<ObliqueStripStation> stations(N);
  const double x_g = N > 0 ? K.x_m[0] - st[0].x_cg_m : 0.0;
  for (int n = 0; n < N; ++n) stations[n] = {K.x_m[n], st[n].weight_m, K.panels[n]};
  out.hydrostatics = ObliqueStationHydrostatics(stations, x_g);
  out.restoring = ObliqueRestoring(out.hydrostatics, x_g, zg, rho, g);
  double c33 = 0, c35 = 0, c55 = 0;
  for (const StationData& s : st) {
    c33 += rho * g * s.beam_m * s.weight_m;
    c35 -= rho * g * s.beam_m * s.x_cg_m * s.weight_m;
    c55 += rho * g * s.beam_m * s.x_cg_m * s.x_cg_m * s.weight_m;
  }
  out.restoring(2, 2) = c33, out.restoring(2, 4) = out.restoring(4, 2) = c35, out.restoring(4, 4) = c55;
  out.mass.diagonal().head<3>().setConstant(model.mass());
  out.mass.bottomRightCorner<3, 3>() = options.mass.inertia_kg_m2;
  out.mass(4, 4) = model.pitch_inertia();
  ObliqueStripOptions roll = options.roll;
  roll.rho_kg_m3 = rho, roll.g_m_s2 = g, roll.speed_m_s = U;

  // Unit normal velocities per station (complex, as the strip force takes them): n_y, n_z and the roll normal
  // about y = z = 0, y n_z − z n_y, at the collocation points.
  std::vector<Eigen::VectorXcd> ny(N), nz(N), r4(N);
  std::vector<Eigen::VectorXd> ym(N);
  for (int m = 0; m < N; ++m) {
    const auto& panels = K.panels[m];
    const auto P = static_cast<Eigen::Index>(panels.size());
    ny[m].resize(P), nz[m].resize(P), r4[m].resize(P), ym[m].resize(P);
    for (Eigen::Index i = 0; i < P; ++i) {
      const auto nrm = panels[i].Normal();
      ym[m](i) = panels[i].MidY();
      ny[m](i) = nrm[0], nz[m](i) = nrm[1];
      r4[m](i) = panels[i].MidY() * nrm[1] - panels[i].MidZ() * nrm[0];
    }
  }

  out.waves.resize(nh * nf);
  std::vector<int> bad(nh * nf, 0);
#pragma omp parallel for schedule(dynamic)
  for (int job = 0; job < static_cast<int>(nh * nf); ++job) {
    const std::size_t h = job / nf, f = job % nf;
    const double w = omega_rad_s[f], k = w * w / g;
    double cb, sb;
    HeadingCosSin(headings_deg[h], &cb, &sb);
    const double we = w - k * U * cb, ky = k * sb;
    const cd iwe(0.0, we), iw(0.0, w);
    std::vector<cd> lag(N), ex(N);
    std::vector<Eigen::VectorXcd> wave(N);
    for (int j = 0; j < N; ++j) lag[j] = std::polar(1.0, -we * j * dt);
    for (int m = 0; m < N; ++m) {
      // The wave's phase along the hull and −(v n_y + w n_z) per unit A on the panels of station m.
      ex[m] = std::polar(1.0, -k * st[m].x_cg_m * cb);
      const auto P = ny[m].size();
      wave[m].resize(P);
      for (Eigen::Index i = 0; i < P; ++i)
        wave[m](i) = -w * std::exp(k * st[m].z_mid(i)) * std::polar(1.0, -ky * ym[m](i)) *
                     (sb * ny[m](i) + cd(0.0, 1.0) * nz[m](i)) * ex[m];
    }
    Eigen::Matrix<cd, 6, 6> moving = Eigen::Matrix<cd, 6, 6>::Zero();  // ω_e² A − iω_e B
    Vector6cd fk = Vector6cd::Zero(), diff = Vector6cd::Zero();
    for (int n = 0; n < N; ++n) {
      const double x = st[n].x_cg_m, dx = st[n].weight_m, B = st[n].beam_m;
      Eigen::Vector3cd G[6];  // per dof 1..5: the section's force per unit motion amplitude
      for (auto& v : G) v.setZero();
      Eigen::Vector3cd a = Eigen::Vector3cd::Zero();
      for (int m = strip.first_step(n); m <= n; ++m) {
        const cd l = lag[n - m];
        const double xm = st[m].x_cg_m;
        const Eigen::Vector3cd dy = strip.dot(n, m, ny[m], we), dz = strip.dot(n, m, nz[m], we),
                               dr = strip.dot(n, m, r4[m], we);
        G[1] += l * dy * iwe;
        G[2] += l * dz * iwe;
        G[3] += l * (dr + zg * dy) * iwe;
        G[4] += l * dz * (U - iwe * xm);
        G[5] += l * dy * (iwe * xm - U);
        a += l * strip.dot(n, m, wave[m], we);
      }
      // The Cs damping against the section's vertical velocity relative to the water surface across its
      // waterline (head_sea_ship_model.h), and the incident pressure.
      G[2](1) += -damp * B * iwe;
      G[4](1) += -damp * B * (U - iwe * x);
      a(1) += damp * iw * ex[n] * PressureIntegrals(K.panels[n], 0.0, ky)(1);
      const Eigen::Vector3cd p = rho * g * ex[n] * PressureIntegrals(K.panels[n], k, ky);
      for (int d = 1; d < 6; ++d) moving.col(d) += Generalised(G[d], x, zg) * dx;
      diff += Generalised(a, x, zg) * dx;
      fk += Generalised(p, x, zg) * dx;
    }
    ObliqueWaveResult& wr = out.waves[job];
    wr.heading_deg = headings_deg[h];
    wr.omega_rad_s = w;
    wr.omega_e_rad_s = we;
    wr.added_mass = moving.real() / (we * we);
    wr.damping = -moving.imag() / we;
    wr.viscous_roll_damping = ObliqueViscousRollB44(roll, we);
    Eigen::VectorXcd rhs(5);
    for (int d = 1; d < 6; ++d) {
      wr.froude_krylov[d] = fk(d);
      wr.diffraction[d] = diff(d);
      wr.excitation[d] = fk(d) + diff(d);
      rhs(d - 1) = wr.excitation[d];
    }
    const Eigen::VectorXcd X =
        ObliqueMotionMatrix(we, out.mass, wr.added_mass, wr.damping, out.restoring, wr.viscous_roll_damping)
            .solve(rhs);
    for (int d = 1; d < 6; ++d) {
      wr.rao[d] = d >= 3 ? X(d - 1) / k : X(d - 1);
      if (!std::isfinite(wr.rao[d].real()) || !std::isfinite(wr.rao[d].imag())) bad[job] = 1;
    }
  }
  for (std::size_t j = 0; j < bad.size(); ++j)
    if (bad[j])
      model.ReportNonFinite(
          "RAO at heading " + std::to_string(headings_deg[j / nf]) + " deg (oblique periodic solution)",
          omega_rad_s[j % nf]);
  return out;
}

ObliqueStripResult SolveObliquePeriodic(const HeadSeaShipModel& model, const std::vector<double>& omega_rad_s,
                                        const std::vector<double>& headings_deg,
                                        const ObliquePeriodicOptions& options) {
  return SolveObliquePeriodic(model, omega_rad_s, headings_deg, options,
                              KernelObliqueStripForce(model.kernel()));
}

}  // namespace hullopt::sk
