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
// (0 sway, 1 heave, 2 roll about z_G), the factor of its generalised normal (strip theory neglects n_x):
// n_5 = −xi n_3 (pitch, + bow down), n_6 = xi n_2 (yaw, + bow to port), and that factor's slope d/dx (the
// speed terms' −U ∂x of the section's displacement: STF's m_5 = n_3, m_6 = −n_2).
struct SectionalMode {
  int mode;
  double factor;
  double slope;
};
SectionalMode ModeOf(int dof, double xi) {
  switch (dof) {
    case 1:
      return {0, 1.0, 0.0};
    case 2:
      return {1, 1.0, 0.0};
    case 3:
      return {2, 1.0, 0.0};
    case 4:
      return {1, -xi, -1.0};
    default:
      return {0, xi, 1.0};
  }
}

bool Finite(double v) { return std::isfinite(v); }

// Area integrals over a section (closed by its waterline) of (z − z_G) e^{kz − ik_y y} and y e^{kz − ik_y y},
// per unit amplitude without ρg: ∫∫_A g dA = ∮ G n_z dl with G(y, z) = ∫_0^z g(y, z') dz' (divergence
// theorem; G = 0 on the waterline, so the lid adds nothing), n the panel normal (out of the section).
// Gauss–Legendre along each panel, G in closed form.
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
  else if (!Finite(speed_m_s))
    os << "speed_m_s = " << speed_m_s << " must be finite";
  else if (!(damping_cs >= 0.0) || !Finite(damping_cs))
    os << "damping_cs = " << damping_cs << " must be a finite number >= 0";
  else if (!section.IsValid(&section_error))
    os << "section: " << section_error;
  else if (roll_damping.model != RollDampingModel::kNone && !roll_damping.IsValid(&section_error))
    os << "roll_damping: " << section_error;
  else if (roll_damping.model != RollDampingModel::kNone && !roll_damping_hull.IsValid(&section_error))
    os << "roll_damping_hull: " << section_error;
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

namespace {

// Every (frequency, station) 2D problem is independent: one parallel loop. hydro[f * wet.size() + s].
std::vector<SectionHydrodynamics> SolveSections(const std::vector<ObliqueStripStation>& stations,
                                                const std::vector<int>& wet,
                                                const std::vector<double>& omegas,
                                                const FrequencyDomainOptions& so) {
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
  return hydro;
}

// body(i) for i = 0 .. n-1 in one parallel loop over the frequencies (or (heading, frequency) pairs); each i
// writes its own results only, so they are the same bits for any thread count. An exception is rethrown
// after the loop, the one of the lowest i (the one a serial loop would meet first).
template <class Body>
void ForEachFrequency(int n, const Body& body) {
  std::vector<std::exception_ptr> failures(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(dynamic, 1)
  for (int i = 0; i < n; ++i) {
    try {
      body(i);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  }
  for (const std::exception_ptr& f : failures)
    if (f) std::rethrow_exception(f);
}

// The sectional coefficients about the CG's height and their strip sums (no speed terms) at one frequency,
// from hydro[first .. first + wet.size()).
ObliqueFrequencyResult FrequencyCoefficients(const std::vector<ObliqueStripStation>& stations,
                                             const std::vector<int>& wet,
                                             const std::vector<SectionHydrodynamics>& hydro,
                                             std::size_t first, double w, double g, double x_g, double zg) {
  // Roll about the CG's height: n_4' = n_4 + z_G n_2, so every sectional row and column of roll gains z_G
  // times sway's.
  Eigen::Matrix3d t = Eigen::Matrix3d::Identity();
  t(2, 0) = zg;
  ObliqueFrequencyResult fr;
  fr.omega_rad_s = w;
  fr.k_per_m = w * w / g;
  fr.sections.resize(stations.size());
  for (std::size_t s = 0; s < wet.size(); ++s) {
    const SectionHydrodynamics& h = hydro[first + s];
    ObliqueSectionCoefficients& sc = fr.sections[wet[s]];
    sc.added_mass = t * h.added_mass * t.transpose();
    sc.damping = t * h.damping * t.transpose();
    const double x = stations[wet[s]].x_m - x_g, wt = stations[wet[s]].weight_m;
    for (int d = 1; d < 6; ++d)
      for (int e = 1; e < 6; ++e) {
        const SectionalMode md = ModeOf(d, x), me = ModeOf(e, x);
        const double c = wt * md.factor * me.factor;
        fr.added_mass(d, e) += c * sc.added_mass(md.mode, me.mode);
        fr.damping(d, e) += c * sc.damping(md.mode, me.mode);
      }
  }
  return fr;
}

// A section's Froude–Krylov and diffraction loads from the wave Re[A e^{i(ωt − k x cosβ − k sinβ y)}] about
// y = z = 0 (SectionWaveLoadIntegrals), moved to roll about z_G.
struct SectionLoadsAboutCg {
  std::array<C, 3> froude_krylov;
  std::array<C, 3> diffraction;
};
SectionLoadsAboutCg LoadsAboutCg(const SectionHydrodynamics& hydro, double k, double beta, double rho,
                                 double g, double zg) {
  const SectionWaveLoads l = SectionWaveLoadIntegrals(hydro, k, k * std::sin(beta), rho, g);
  return {{l.froude_krylov[0], l.froude_krylov[1], l.froude_krylov[2] + zg * l.froude_krylov[0]},
          {l.diffraction[0], l.diffraction[1], l.diffraction[2] + zg * l.diffraction[0]}};
}

// The n_x parts of the Froude–Krylov pitch and yaw moments of one section
// (options.longitudinal_froude_krylov): −∫∫ p (z − z_G) n_x dS = −∫∫∫ (z − z_G) ∂p/∂x dV and ∫∫ p y n_x dS =
// ∫∫∫ y ∂p/∂x dV, with ∂p/∂x = −ik cosβ p (the waterplane closing the volume has n_x = 0). Added to
// wr.froude_krylov[4], [5] times phase.
void AddLongitudinalFroudeKrylov(const std::vector<Panel>& panels, double k, double beta, double rho,
                                 double g, double zg, C phase, ObliqueWaveResult& wr) {
  const std::array<C, 2> m = SectionPressureMoments(panels, k, k * std::sin(beta), zg);
  const C ikc(0.0, k * std::cos(beta) * rho * g);
  wr.froude_krylov[4] += phase * ikc * m[0];
  wr.froude_krylov[5] -= phase * ikc * m[1];
}

// Waterline integrals of one section (closed by its waterline): ∫_wl f(y) dy = −∮ f(y) n_z ds (the lid's normal
// is +z and ∮ f(y) n_z ds over the closed section vanishes), for f = 1 (the breadth, exact) and e^{−ik_y y}
// (Gauss–Legendre along each panel, as SectionPressureMoments).
struct WaterlineIntegrals {
  double breadth = 0.0;  // [m]
  C wave;                // [m] ∫_wl e^{−ik_y y} dy
};
WaterlineIntegrals SectionWaterline(const std::vector<Panel>& panels, double ky) {
  const QuadratureRule& rule = GaussLegendre01(8);
  WaterlineIntegrals out;
  for (const Panel& p : panels) {
    const double nzl = p.Normal()[1] * p.Length();
    out.breadth -= nzl;
    const int parts = 1 + static_cast<int>(std::fabs(ky * (p.y2 - p.y1)) / 0.5);
    for (int part = 0; part < parts; ++part)
      for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
        const double t = (part + rule.nodes[q]) / parts;
        out.wave += std::polar(-nzl * rule.weights[q] / parts, -ky * (p.y1 + t * (p.y2 - p.y1)));
      }
  }
  return out;
}

// The paper's sectional damping D = ½ Cs ρ U B (v − ζ_t) against the section's vertical velocity v = ẋ3 − ξ ẋ5
// + U x5 relative to the incident surface (head_sea_ship_model.h), ζ_t = iω ζ its earth-frame rate averaged over
// the section's waterline (the oblique wave varies across it): a heave–pitch damping matrix, a U x5 restoring
// part and a wave excitation. At β = 180° they are the head-sea path's terms. Roll keeps the roll damping model
// (roll_damping.h), whose multihull form is this term's roll analogue (the demihulls' heave, v = y ẋ4), so it is
// not counted twice. Adds to wr.cs_damping, cs_restoring and cs_excitation.
void AddCsDamping(const std::vector<ObliqueStripStation>& stations, double x_g_m, double k, double w,
                  double beta, const ObliqueStripOptions& options, ObliqueWaveResult& wr) {
  const double damp = 0.5 * options.damping_cs * options.rho_kg_m3 * options.speed_m_s;
  const double U = options.speed_m_s, ky = k * std::sin(beta);
  for (const ObliqueStripStation& st : stations) {
    if (st.panels.empty()) continue;
    const WaterlineIntegrals wl = SectionWaterline(st.panels, ky);
    const double xi = st.x_m - x_g_m, d = damp * st.weight_m * wl.breadth;
    // Heave (index 2) and pitch (4): the section's vertical velocity per unit ẋ3 is 1, per unit ẋ5 −ξ.
    wr.cs_damping(2, 2) += d;
    wr.cs_damping(2, 4) -= d * xi;
    wr.cs_damping(4, 2) -= d * xi;
    wr.cs_damping(4, 4) += d * xi * xi;
    wr.cs_restoring(2, 4) += d * U;
    wr.cs_restoring(4, 4) -= d * U * xi;
    const C surface = C(0.0, w) * damp * st.weight_m * wl.wave * std::polar(1.0, -k * xi * std::cos(beta));
    wr.cs_excitation[2] += surface;
    wr.cs_excitation[4] -= surface * xi;
  }
}

// Excitation = Froude–Krylov + diffraction, then the 5-dof solve; rotations per wave slope kA.
void SolveWave(const Eigen::PartialPivLU<Eigen::MatrixXcd>& lu, double k, ObliqueWaveResult& wr) {
  Eigen::VectorXcd rhs(5);
  for (int d = 1; d < 6; ++d) {
    wr.excitation[d] = wr.froude_krylov[d] + wr.diffraction[d];
    if (wr.cs_excitation[d] != C(0.0)) wr.excitation[d] += wr.cs_excitation[d];
    rhs[d - 1] = wr.excitation[d];
  }
  const Eigen::VectorXcd x = lu.solve(rhs);
  for (int d = 1; d < 6; ++d) wr.rao[d] = d >= 3 ? x[d - 1] / k : x[d - 1];
}

// The forward-speed solution (U ≠ 0). Salvesen, Tuck & Faltinsen (1970): the sections are solved at the
// encounter frequency ω_e = ω − kU cosβ (deep water) and the hydrodynamic force on a section is
// the 2D force seen through the substantial derivative along the hull, f = (1 − (U/iω_e) ∂/∂x) F_2D, with the
// section moving at the relative normal velocity (iω_e − U ∂/∂x) of its displacement (STF's m_j terms,
// m_5 = n_3, m_6 = −n_2). Integrating a_j f over the hull by parts gives STF's speed-dependent coefficients
// with their transom ("aftermost section") terms, for heave–pitch (STF 1970's heave–pitch coefficients: A35 =
// −∫ξa33 − (U/ω_e²)B33⁰ + (U/ω_e²)ξ_A b33^A − (U²/ω_e²) a33^A, B35 = −∫ξb33 + U A33⁰ − U ξ_A a33^A −
// (U²/ω_e²) b33^A, ...) and for sway–roll–yaw (STF 1970's sway–roll–yaw coefficients: A26 = ∫ξa22 +
// (U/ω_e²)B22⁰ ..., B46 = ∫ξb24 − U A24⁰ ..., A66 = ∫ξ²a22 + (U²/ω_e²)A22⁰ ...), and the diffraction's speed
// term (STF's exciting forces: the (U/iω_e) h_{j−2} part). The x-derivative is taken on the station grid as
// strip_theory_stf.h takes it (stations ordered bow to stern, a backward difference per station, whose hull
// sum telescopes to the transom term exactly): F_jk = Σ_n a_j(ξ_n) [w_n G_n + (U/iω_e)(G_n − G_{n−1})], G_n =
// Z_n c_k(ξ_n) the section's force for the dof k's velocity c_k = iω_e a_k − U a_k', Z = −(iω_e a + b),
// G_{−1} = 0 (the bow); a dry station has G = 0. F_jk = ω_e² A_jk − iω_e B_jk. Timman–Newman: with no transom
// (G = 0 at both ends) and uniform station spacing equal to the weights this gives A_jk(U) = A_kj(−U),
// B_jk(U) = B_kj(−U) up to the 2D solver's reciprocity.
void SolveAtSpeed(const std::vector<ObliqueStripStation>& stations, const std::vector<int>& wet,
                  const ObliqueMassProperties& mass, const std::vector<double>& omegas,
                  const std::vector<double>& headings_deg, const ObliqueStripOptions& options,
                  const FrequencyDomainOptions& so, ObliqueStripResult& out) {
  const double U = options.speed_m_s, rho = options.rho_kg_m3, g = options.g_m_s2, zg = mass.z_g_m;
  const std::size_t nh = headings_deg.size(), nf = omegas.size(), ns = wet.size();
  // Encounter frequencies, each distinct one solved once.
  std::vector<double> distinct;
  std::vector<std::size_t> entry(nh * nf);
  for (std::size_t hd = 0; hd < nh; ++hd)
    for (std::size_t f = 0; f < nf; ++f) {
      const double w = omegas[f], beta = headings_deg[hd] * M_PI / 180.0;
      const double we = w - w * w / g * U * std::cos(beta);
      if (!(we > 0.0)) {
        std::ostringstream os;
        os << "oblique strip theory: encounter frequency omega_e = " << we << " rad/s <= 0 at omega = " << w
           << " rad/s, heading " << headings_deg[hd] << " deg, speed " << U
           << " m/s (following and quartering seas with omega_e <= 0 are not solved)";
        throw std::domain_error(os.str());
      }
      const auto it = std::find(distinct.begin(), distinct.end(), we);
      entry[hd * nf + f] = static_cast<std::size_t>(it - distinct.begin());
      if (it == distinct.end()) distinct.push_back(we);
    }
  const std::vector<SectionHydrodynamics> hydro = SolveSections(stations, wet, distinct, so);
  out.frequencies.resize(distinct.size());
  ForEachFrequency(static_cast<int>(distinct.size()), [&](int e) {
    out.frequencies[e] = FrequencyCoefficients(stations, wet, hydro, e * ns, distinct[e], g, mass.x_g_m, zg);
  });
  // Stations bow to stern (the order the strip passes them), and each one's wet index (−1: dry).
  std::vector<int> order(stations.size()), wet_index(stations.size(), -1);
  for (std::size_t n = 0; n < order.size(); ++n) order[n] = static_cast<int>(n);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return stations[a].x_m > stations[b].x_m; });
  for (std::size_t s = 0; s < ns; ++s) wet_index[wet[s]] = static_cast<int>(s);

  out.waves.resize(nh * nf);
  ForEachFrequency(static_cast<int>(nh * nf), [&](int job) {
    const std::size_t hd = job / nf, f = job % nf;
    {  // one (heading, frequency) pair
      const std::size_t e = entry[hd * nf + f];
      const ObliqueFrequencyResult& fr = out.frequencies[e];
      const double w = omegas[f], k = w * w / g, we = distinct[e], beta = headings_deg[hd] * M_PI / 180.0;
      const C iwe(0.0, we), s = U / iwe;
      ObliqueWaveResult& wr = out.waves[hd * nf + f];
      wr.heading_deg = headings_deg[hd];
      wr.omega_rad_s = w;
      wr.omega_e_rad_s = we;
      wr.frequency_entry = e;
      Eigen::Matrix<C, 6, 6> force = Eigen::Matrix<C, 6, 6>::Zero();  // ω_e² A − iω_e B
      std::array<std::array<C, 3>, 6> g_prev{}, g_now{};              // G per dof k, sectional mode p
      std::array<C, 3> d_prev{}, d_now{};                             // diffraction per unit length
      for (const int n : order) {
        const ObliqueStripStation& st = stations[n];
        const double xi = st.x_m - mass.x_g_m, wt = st.weight_m;
        const ObliqueSectionCoefficients& sc = fr.sections[n];
        const Eigen::Matrix3cd z = -(iwe * sc.added_mass.cast<C>() + sc.damping.cast<C>());
        for (int kd = 1; kd < 6; ++kd) {
          const SectionalMode mk = ModeOf(kd, xi);
          const C ck = iwe * mk.factor - U * mk.slope;
          for (int p = 0; p < 3; ++p) g_now[kd][p] = z(p, mk.mode) * ck;
        }
        d_now = {};
        if (wet_index[n] >= 0) {
          const SectionLoadsAboutCg l = LoadsAboutCg(hydro[e * ns + wet_index[n]], k, beta, rho, g, zg);
          const C phase = std::polar(wt, -k * xi * std::cos(beta));
          // The diffraction potential's pressure −ρ(iω_e − U∂x)φ_D: the Haskind integral at ω_e, so the
          // zero-speed form's factor ω becomes ω_e (in STF the sectional h_j are taken at ω_e).
          const C unit_phase = std::polar(we / w, -k * xi * std::cos(beta));
          for (int p = 0; p < 3; ++p) d_now[p] = unit_phase * l.diffraction[p];
          for (int d = 1; d < 6; ++d) {
            const SectionalMode md = ModeOf(d, xi);
            wr.froude_krylov[d] += phase * md.factor * l.froude_krylov[md.mode];
          }
          if (options.longitudinal_froude_krylov)
            AddLongitudinalFroudeKrylov(st.panels, k, beta, rho, g, zg, phase, wr);
        }
        for (int d = 1; d < 6; ++d) {
          const SectionalMode md = ModeOf(d, xi);
          const int p = md.mode;
          for (int kd = 1; kd < 6; ++kd)
            force(d, kd) += md.factor * (wt * g_now[kd][p] + s * (g_now[kd][p] - g_prev[kd][p]));
          wr.diffraction[d] += md.factor * (wt * d_now[p] + s * (d_now[p] - d_prev[p]));
        }
        g_prev = g_now;
        d_prev = d_now;
      }
      wr.added_mass = force.real() / (we * we);
      wr.damping = -force.imag() / we;
      wr.viscous_roll_damping = ObliqueViscousRollB44(options, we);
      if (options.damping_cs > 0.0) {
        AddCsDamping(stations, mass.x_g_m, k, w, beta, options, wr);
        SolveWave(ObliqueMotionMatrix(we, out.mass, wr.added_mass, wr.damping + wr.cs_damping,
                                      out.restoring + wr.cs_restoring, wr.viscous_roll_damping),
                  k, wr);
      } else {
        SolveWave(ObliqueMotionMatrix(we, out.mass, wr.added_mass, wr.damping, out.restoring,
                                      wr.viscous_roll_damping),
                  k, wr);
      }
    }
  });
}

}  // namespace

double ObliqueViscousRollB44(const ObliqueStripOptions& options, double we) {
  if (options.roll_damping.model == RollDampingModel::kNone) return 0.0;
  RollDampingOptions r = options.roll_damping;
  r.rho_kg_m3 = options.rho_kg_m3;
  r.g_m_s2 = options.g_m_s2;
  return ViscousRollDamping(options.roll_damping_hull, we, options.speed_m_s, r).equivalent;
}

Eigen::PartialPivLU<Eigen::MatrixXcd> ObliqueMotionMatrix(double we, const Matrix6d& mass,
                                                          const Matrix6d& added_mass, Matrix6d damping,
                                                          const Matrix6d& restoring, double viscous_b44) {
  if (viscous_b44 != 0.0) damping(3, 3) += viscous_b44;
  const Eigen::MatrixXcd z =
      (-we * we * (mass + added_mass)).cast<C>() + C(0.0, we) * damping.cast<C>() + restoring.cast<C>();
  return Eigen::PartialPivLU<Eigen::MatrixXcd>(z.bottomRightCorner(5, 5));
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
      throw std::invalid_argument("oblique strip theory: omega = " + std::to_string(w) +
                                  " rad/s must be > 0");
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
  if (options.speed_m_s != 0.0) {
    SolveAtSpeed(stations, wet, mass, omegas, headings_deg, options, so, out);
    return out;
  }

  const int nf = static_cast<int>(omegas.size()), ns = static_cast<int>(wet.size());
  const std::vector<SectionHydrodynamics> hydro = SolveSections(stations, wet, omegas, so);
  const std::size_t nh = headings_deg.size();
  out.waves.resize(nh * nf);
  out.frequencies.resize(nf);
  ForEachFrequency(nf, [&](int f) {
    const ObliqueFrequencyResult& fr = out.frequencies[f] =
        FrequencyCoefficients(stations, wet, hydro, f * ns, omegas[f], g, mass.x_g_m, zg);
    const double w = omegas[f], k = fr.k_per_m;
    const double viscous_b44 = ObliqueViscousRollB44(options, w);
    const auto lu = ObliqueMotionMatrix(w, out.mass, fr.added_mass, fr.damping, out.restoring, viscous_b44);
    for (std::size_t hd = 0; hd < nh; ++hd) {
      ObliqueWaveResult& wr = out.waves[hd * nf + f];
      const double beta = headings_deg[hd] * M_PI / 180.0;
      wr.heading_deg = headings_deg[hd];
      wr.omega_rad_s = w;
      wr.omega_e_rad_s = w;
      wr.frequency_entry = static_cast<std::size_t>(f);
      wr.added_mass = fr.added_mass;
      wr.damping = fr.damping;
      wr.viscous_roll_damping = viscous_b44;
      for (int s = 0; s < ns; ++s) {
        // The section's loads moved to the wave phase at the section's x.
        const SectionLoadsAboutCg l = LoadsAboutCg(hydro[f * ns + s], k, beta, rho, g, zg);
        const double x = stations[wet[s]].x_m - mass.x_g_m, wt = stations[wet[s]].weight_m;
        const C phase = std::polar(wt, -k * x * std::cos(beta));
        for (int d = 1; d < 6; ++d) {
          const SectionalMode md = ModeOf(d, x);
          wr.froude_krylov[d] += phase * md.factor * l.froude_krylov[md.mode];
          wr.diffraction[d] += phase * md.factor * l.diffraction[md.mode];
        }
        if (options.longitudinal_froude_krylov)
          AddLongitudinalFroudeKrylov(stations[wet[s]].panels, k, beta, rho, g, zg, phase, wr);
      }
      SolveWave(lu, k, wr);
    }
  });
  return out;
}

}  // namespace hullopt::sk
