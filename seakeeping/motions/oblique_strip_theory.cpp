#include "seakeeping/motions/oblique_strip_theory.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>
#include <stdexcept>

#include "seakeeping/green/gauss_legendre.h"

namespace hullopt::sk {
namespace {

using C = std::complex<double>;

// A 3D dof (1 sway .. 5 yaw as indices) seen by a section at xi = x − x_G: the sectional mode it moves
// (0 sway, 1 heave, 2 roll about z_G) and the factor of its generalised normal (strip theory neglects n_x):
// n_5 = −xi n_3 (pitch, + bow down), n_6 = xi n_2 (yaw, + bow to port).
struct SectionalMode {
  int mode;
  double factor;
};
SectionalMode ModeOf(int dof, double xi) {
  switch (dof) {
    case 1: return {0, 1.0};
    case 2: return {1, 1.0};
    case 3: return {2, 1.0};
    case 4: return {1, -xi};
    default: return {0, xi};
  }
}

bool Finite(double v) { return std::isfinite(v); }

// Area integrals over a section (closed by its waterline) of (z − z_G) e^{kz − ik_y y} and y e^{kz − ik_y y}, per
// unit amplitude without ρg: ∫∫_A g dA = ∮ G n_z dl with G(y, z) = ∫_0^z g(y, z') dz' (divergence theorem; G = 0
// on the waterline, so the lid adds nothing), n the panel normal (out of the section). Gauss–Legendre along each
// panel, G in closed form.
std::array<C, 2> SectionPressureMoments(const std::vector<Panel>& panels, double k, double ky, double zg) {
  const QuadratureRule& rule = GaussLegendre01(8);
  std::array<C, 2> out{};
  for (const Panel& p : panels) {
    const double l = p.Length(), nz = p.Normal()[1];
    const int parts = 1 + static_cast<int>(l * std::max(k, std::fabs(ky)) / 0.5);
    for (int s = 0; s < parts; ++s)
      for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
        const double t = (s + rule.nodes[q]) / parts;
        const double y = p.y1 + t * (p.y2 - p.y1), z = p.z1 + t * (p.z2 - p.z1);
        // ∫_0^z e^{kz'} dz' = expm1(kz)/k and ∫_0^z z' e^{kz'} dz' = z e^{kz}/k − expm1(kz)/k² (z <= 0), the
        // latter by its series where kz is small (the closed form cancels there).
        const double kz = k * z;
        const double e0 = z * (std::fabs(kz) < 1e-8 ? 1.0 : std::expm1(kz) / kz);
        const double e1 = std::fabs(kz) < 1e-3 ? z * z * (0.5 + kz / 3.0 + kz * kz / 8.0)
                                               : z * std::exp(kz) / k - std::expm1(kz) / (k * k);
        const C lat = std::polar(rule.weights[q] * l / parts * nz, -ky * y);
        out[0] += lat * (e1 - zg * e0);
        out[1] += lat * y * e0;
      }
  }
  return out;
}

}  // namespace

std::vector<ObliqueStripStation> ObliqueStripStations(const hull::HullForm& hull,
                                                      const StripGeometryOptions& options) {
  // The strip solvers' grid and sections; the speed only sets the kernel's time step, unused here.
  constexpr double kAnySpeed = 1.0, kAnyRho = 1000.0, kAnyG = 9.81;
  const StripKernel k = StripKernelGeometry(hull, options, kAnySpeed, kAnyRho, kAnyG);
  std::vector<ObliqueStripStation> out(k.Steps());
  for (int n = 0; n < k.Steps(); ++n) out[n] = {k.x_m[n], k.Weight(n), k.panels[n]};
  return out;
}

bool ObliqueMassProperties::IsValid(std::string* error) const {
  std::ostringstream os;
  if (!(mass_kg > 0) || !Finite(mass_kg))
    os << "mass_kg = " << mass_kg << " must be a finite number > 0";
  else if (!Finite(x_g_m) || !Finite(z_g_m))
    os << "CG (x_g_m = " << x_g_m << ", z_g_m = " << z_g_m << ") must be finite";
  else if (!inertia_kg_m2.allFinite() || !(inertia_kg_m2(0, 0) > 0) || !(inertia_kg_m2(1, 1) > 0) ||
           !(inertia_kg_m2(2, 2) > 0))
    os << "inertia_kg_m2 must be finite with diagonal entries > 0 (I44 = " << inertia_kg_m2(0, 0)
       << ", I55 = " << inertia_kg_m2(1, 1) << ", I66 = " << inertia_kg_m2(2, 2) << ")";
  else if ((inertia_kg_m2 - inertia_kg_m2.transpose()).cwiseAbs().maxCoeff() > 1e-12 * inertia_kg_m2.norm())
    os << "inertia_kg_m2 must be symmetric";
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

bool ObliqueStripOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  std::string section_error;
  if (!(rho_kg_m3 > 0) || !Finite(rho_kg_m3))
    os << "rho_kg_m3 = " << rho_kg_m3 << " must be a finite number > 0";
  else if (!(g_m_s2 > 0) || !Finite(g_m_s2))
    os << "g_m_s2 = " << g_m_s2 << " must be a finite number > 0";
  else if (speed_m_s != 0.0)
    os << "speed_m_s = " << speed_m_s << " must be 0 (oblique-sea strip theory is implemented at zero speed only)";
  else if (!section.IsValid(&section_error))
    os << "section: " << section_error;
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

ObliqueHydrostatics ObliqueStationHydrostatics(const std::vector<ObliqueStripStation>& stations,
                                               double x_g_m) {
  // Per section, closed by its waterline (where z = 0, so the lid adds nothing to the first three):
  //   area S = ½ ∮ (y n_y + z n_z) ds, ∫∫ z dA = ½ ∮ z² n_z ds, waterline breadth b = −∮ n_z ds,
  //   ∫_waterline y² dy = −∮ y² n_z ds,
  // n the normal out of the body (into the fluid); each integrand is a polynomial along a straight panel.
  ObliqueHydrostatics h;
  double vz = 0.0, vx = 0.0, ax = 0.0, ax2 = 0.0;
  for (const ObliqueStripStation& st : stations) {
    double s = 0.0, sz = 0.0, b = 0.0, iy = 0.0;
    for (const Panel& p : st.panels) {
      const auto n = p.Normal();
      const double l = p.Length();
      s += 0.5 * (p.MidY() * n[0] + p.MidZ() * n[1]) * l;
      sz += 0.5 * n[1] * l * (p.z1 * p.z1 + p.z1 * p.z2 + p.z2 * p.z2) / 3.0;
      b -= n[1] * l;
      iy -= n[1] * l * (p.y1 * p.y1 + p.y1 * p.y2 + p.y2 * p.y2) / 3.0;
    }
    const double w = st.weight_m, xi = st.x_m - x_g_m;
    h.volume_m3 += w * s;
    vx += w * s * st.x_m;
    vz += w * sz;
    h.waterplane_area_m2 += w * b;
    ax += w * b * st.x_m;
    ax2 += w * b * xi * xi;
    h.waterplane_i_t_m4 += w * iy;
  }
  if (h.volume_m3 > 0) {
    h.x_b_m = vx / h.volume_m3;
    h.z_b_m = vz / h.volume_m3;
  }
  if (h.waterplane_area_m2 > 0) h.x_f_m = ax / h.waterplane_area_m2;
  h.waterplane_i_l_cg_m4 = ax2;
  return h;
}

Matrix6d ObliqueRestoring(const ObliqueHydrostatics& h, double x_g_m, double z_g_m, double rho, double g) {
  Matrix6d c = Matrix6d::Zero();
  const double rg = rho * g, bg = h.volume_m3 * (h.z_b_m - z_g_m);
  c(2, 2) = rg * h.waterplane_area_m2;
  // Pitch θ (bow down) lowers the waterline at xi = x − x_G by xi θ: heave force ρg θ ∫ b xi dx = −C35 θ.
  c(2, 4) = c(4, 2) = -rg * h.waterplane_area_m2 * (h.x_f_m - x_g_m);
  c(3, 3) = rg * (h.waterplane_i_t_m4 + bg);
  c(4, 4) = rg * (h.waterplane_i_l_cg_m4 + bg);
  return c;
}

ObliqueStripResult SolveObliqueStripTheory(const std::vector<ObliqueStripStation>& stations,
                                           const ObliqueMassProperties& mass,
                                           const std::vector<double>& omegas,
                                           const std::vector<double>& headings_deg,
                                           const ObliqueStripOptions& options) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument("oblique strip theory options: " + err);
  if (!mass.IsValid(&err)) throw std::invalid_argument("oblique strip theory mass: " + err);
  if (omegas.empty()) throw std::invalid_argument("oblique strip theory: the frequency list is empty");
  for (double w : omegas)
    if (!(w > 0) || !Finite(w))
      throw std::invalid_argument("oblique strip theory: omega = " + std::to_string(w) + " rad/s must be > 0");
  for (double b : headings_deg)
    if (!Finite(b)) throw std::invalid_argument("oblique strip theory: a heading is not finite");
  std::vector<int> wet;
  for (std::size_t n = 0; n < stations.size(); ++n) {
    if (stations[n].panels.empty()) continue;
    if (!(stations[n].weight_m >= 0) || !Finite(stations[n].weight_m) || !Finite(stations[n].x_m))
      throw std::invalid_argument("oblique strip theory: station " + std::to_string(n) +
                                  " needs a finite x and a weight >= 0");
    wet.push_back(static_cast<int>(n));
  }
  if (wet.empty()) throw std::invalid_argument("oblique strip theory: no station has panels");

  const double rho = options.rho_kg_m3, g = options.g_m_s2, zg = mass.z_g_m;
  FrequencyDomainOptions so = options.section;
  so.rho_kg_m3 = rho;
  so.g_m_s2 = g;

  ObliqueStripResult out;
  out.headings_deg = headings_deg;
  out.hydrostatics = ObliqueStationHydrostatics(stations, mass.x_g_m);
  out.restoring = ObliqueRestoring(out.hydrostatics, mass.x_g_m, zg, rho, g);
  out.mass.diagonal().head<3>().setConstant(mass.mass_kg);
  out.mass.bottomRightCorner<3, 3>() = mass.inertia_kg_m2;

  // Every (frequency, station) 2D problem is independent: one parallel loop, then the serial assembly.
  const int nf = static_cast<int>(omegas.size()), ns = static_cast<int>(wet.size());
  std::vector<SectionHydrodynamics> hydro(static_cast<std::size_t>(nf) * ns);
  std::exception_ptr failure = nullptr;
#pragma omp parallel for schedule(dynamic, 1)
  for (int job = 0; job < nf * ns; ++job) {
    try {
      hydro[job] = SolveSectionFrequencyDomain({stations[wet[job % ns]].panels}, omegas[job / ns], so);
    } catch (...) {
#pragma omp critical(oblique_strip_sections)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);

  // Roll about the CG's height: n_4' = n_4 + z_G n_2, so every sectional row and column of roll gains z_G
  // times sway's.
  Eigen::Matrix3d t = Eigen::Matrix3d::Identity();
  t(2, 0) = zg;
  const std::size_t nh = headings_deg.size();
  out.waves.resize(nh * nf);
  for (int f = 0; f < nf; ++f) {
    ObliqueFrequencyResult& fr = out.frequencies.emplace_back();
    const double w = omegas[f], k = w * w / g;
    fr.omega_rad_s = w;
    fr.k_per_m = k;
    fr.sections.resize(stations.size());
    for (int s = 0; s < ns; ++s) {
      const SectionHydrodynamics& h = hydro[f * ns + s];
      ObliqueSectionCoefficients& sc = fr.sections[wet[s]];
      sc.added_mass = t * h.added_mass * t.transpose();
      sc.damping = t * h.damping * t.transpose();
      const double x = stations[wet[s]].x_m - mass.x_g_m, wt = stations[wet[s]].weight_m;
      for (int d = 1; d < 6; ++d)
        for (int e = 1; e < 6; ++e) {
          const SectionalMode md = ModeOf(d, x), me = ModeOf(e, x);
          const double c = wt * md.factor * me.factor;
          fr.added_mass(d, e) += c * sc.added_mass(md.mode, me.mode);
          fr.damping(d, e) += c * sc.damping(md.mode, me.mode);
        }
    }
    // The 5-dof equations (sway..yaw): [−ω²(M + A) + iωB + C] X = F.
    const Eigen::MatrixXcd z = (-w * w * (out.mass + fr.added_mass)).cast<C>() +
                               C(0.0, w) * fr.damping.cast<C>() + out.restoring.cast<C>();
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(z.bottomRightCorner(5, 5));
    for (std::size_t hd = 0; hd < nh; ++hd) {
      ObliqueWaveResult& wr = out.waves[hd * nf + f];
      const double beta = headings_deg[hd] * M_PI / 180.0;
      wr.heading_deg = headings_deg[hd];
      wr.omega_rad_s = w;
      for (int s = 0; s < ns; ++s) {
        // The section's loads from the wave Re[A e^{i(ωt − k x cosβ − k sinβ y)}] about y = z = 0, moved to
        // roll about z_G and to the wave phase at the section's x.
        const SectionWaveLoads l = SectionWaveLoadIntegrals(hydro[f * ns + s], k, k * std::sin(beta), rho, g);
        const double x = stations[wet[s]].x_m - mass.x_g_m, wt = stations[wet[s]].weight_m;
        const C phase = std::polar(wt, -k * x * std::cos(beta));
        const std::array<C, 3> fk{l.froude_krylov[0], l.froude_krylov[1],
                                  l.froude_krylov[2] + zg * l.froude_krylov[0]};
        const std::array<C, 3> df{l.diffraction[0], l.diffraction[1], l.diffraction[2] + zg * l.diffraction[0]};
        for (int d = 1; d < 6; ++d) {
          const SectionalMode md = ModeOf(d, x);
          wr.froude_krylov[d] += phase * md.factor * fk[md.mode];
          wr.diffraction[d] += phase * md.factor * df[md.mode];
        }
        if (options.longitudinal_froude_krylov) {
          // −∫∫ p (z − z_G) n_x dS = −∫∫∫ (z − z_G) ∂p/∂x dV and ∫∫ p y n_x dS = ∫∫∫ y ∂p/∂x dV, with
          // ∂p/∂x = −ik cosβ p (the waterplane closing the volume has n_x = 0).
          const std::array<C, 2> m = SectionPressureMoments(stations[wet[s]].panels, k, k * std::sin(beta), zg);
          const C ikc(0.0, k * std::cos(beta) * rho * g);
          wr.froude_krylov[4] += phase * ikc * m[0];
          wr.froude_krylov[5] -= phase * ikc * m[1];
        }
      }
      Eigen::VectorXcd rhs(5);
      for (int d = 1; d < 6; ++d) {
        wr.excitation[d] = wr.froude_krylov[d] + wr.diffraction[d];
        rhs[d - 1] = wr.excitation[d];
      }
      const Eigen::VectorXcd x = lu.solve(rhs);
      for (int d = 1; d < 6; ++d) wr.rao[d] = d >= 3 ? x[d - 1] / k : x[d - 1];
    }
  }
  return out;
}

}  // namespace hullopt::sk
