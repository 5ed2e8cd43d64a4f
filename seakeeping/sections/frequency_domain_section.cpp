#include "seakeeping/sections/frequency_domain_section.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>
#include <stdexcept>

#include "seakeeping/green/frequency_domain_green.h"
#include "seakeeping/green/rankine_panel.h"

namespace hullopt::sk {
namespace {

using C = std::complex<double>;
constexpr double kInv2Pi = 0.5 / M_PI;
// The lid condition tapers to the exterior free-surface condition over this fraction of the half beam from
// each waterline (see the lid rows in SolveSectionFrequencyDomain).
constexpr double kLidTaperFraction = 0.5;

// Gauss–Legendre nodes on [0, 1] and weights summing to 1 (Newton on P_n; exact to rounding for n <= 20).
struct GaussRule {
  std::vector<double> t, w;
};
GaussRule MakeGaussRule(int n) {
  GaussRule r;
  r.t.resize(n);
  r.w.resize(n);
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) break;
    }
    r.t[i] = 0.5 * (1.0 - x);
    r.w[i] = 1.0 / ((1.0 - x * x) * dp * dp);  // = w_i/2 on [−1, 1]
  }
  return r;
}

double PointSegmentDistance(double py, double pz, double ay, double az, double by, double bz) {
  const double dy = by - ay, dz = bz - az;
  const double l2 = dy * dy + dz * dz;
  double t = l2 > 0 ? ((py - ay) * dy + (pz - az) * dz) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double ey = py - (ay + t * dy), ez = pz - (az + t * dz);
  return std::sqrt(ey * ey + ez * ez);  // coordinates of O(1) m: no overflow, no need of hypot
}

struct Influence {
  C phi, vy, vz;
};

// ∫ Gs ds and its field-point gradient over the segment a → b, refined where the segment is long compared
// with its distance to the field point's image (p̄ = (y, −z), where ζc → 0) or with the wavelength.
void IntegrateSmooth(double nu, double two_log_nu, double y, double z, double ay, double az, double by, double bz,
                     int depth, const GaussRule& rule, int max_depth, Influence* acc) {
  const double len = std::sqrt((by - ay) * (by - ay) + (bz - az) * (bz - az));
  const double dist = PointSegmentDistance(y, -z, ay, az, by, bz);
  if (depth < max_depth && (len > dist || len * nu > 1.0)) {
    const double my = 0.5 * (ay + by), mz = 0.5 * (az + bz);
    IntegrateSmooth(nu, two_log_nu, y, z, ay, az, my, mz, depth + 1, rule, max_depth, acc);
    IntegrateSmooth(nu, two_log_nu, y, z, my, mz, by, bz, depth + 1, rule, max_depth, acc);
    return;
  }
  constexpr int kMaxPoints = 20;  // FrequencyDomainOptions::gauss_points <= 20
  double qy[kMaxPoints], qz[kMaxPoints], wl[kMaxPoints];
  const int count = static_cast<int>(rule.t.size());
  for (int k = 0; k < count; ++k) {
    qy[k] = ay + rule.t[k] * (by - ay);
    qz[k] = az + rule.t[k] * (bz - az);
    wl[k] = rule.w[k] * len;
  }
  WaveGreenValue sum{acc->phi, acc->vy, acc->vz};
  AddWeightedSmoothWaveGreen(nu, two_log_nu, y, z, count, qy, qz, wl, &sum);
  *acc = {sum.value, sum.dy, sum.dz};
}

// The frequency-independent part of a panel's influence at a field point: the closed-form ln r + ln r'
// integrals (1/2π)∫ (ln r + ln r') ds and their gradient, summed.
struct RankineSum {
  double phi, vy, vz;
};
RankineSum RankinePart(const Panel& p, double y, double z) {
  const SourceInfluence r = RankinePanelInfluence(p, y, z);
  const SourceInfluence im = ImagePanelInfluence(p, y, z);
  return {r.phi + im.phi, r.vy + im.vy, r.vz + im.vz};
}

// Potential and velocity at (y, z) of a unit-density source panel with the free-surface Green function,
// (1/2π)∫ G ds, given its Rankine part. The self term of a body panel at its own midpoint is taken on the
// fluid side (+1/2).
Influence PanelInfluence(const Panel& p, const RankineSum& r, double nu, double two_log_nu, double y, double z,
                         const GaussRule& rule, int max_depth) {
  Influence s{};
  IntegrateSmooth(nu, two_log_nu, y, z, p.y1, p.z1, p.y2, p.z2, 0, rule, max_depth, &s);
  return {r.phi + kInv2Pi * s.phi, r.vy + kInv2Pi * s.vy, r.vz + kInv2Pi * s.vz};
}

// Generalised normal of mode j at (y, z) for normal (ny, nz): sway, heave, roll about +x through the origin.
double ModeNormal(int j, double ny, double nz, double y, double z) {
  if (j == 0) return ny;
  if (j == 1) return nz;
  return y * nz - z * ny;
}

void CheckSections(const std::vector<std::vector<Panel>>& sections) {
  if (sections.empty()) throw std::invalid_argument("frequency-domain solver: the strip holds no section");
  for (std::size_t k = 0; k < sections.size(); ++k) {
    const auto& s = sections[k];
    if (s.size() < 2)
      throw std::invalid_argument("frequency-domain solver: section " + std::to_string(k) +
                                  " has < 2 panels");
    const double scale = std::max(std::fabs(s.front().y1 - s.back().y2), 1e-12);
    if (std::fabs(s.front().z1) > 1e-9 * scale || std::fabs(s.back().z2) > 1e-9 * scale)
      throw std::invalid_argument("frequency-domain solver: section " + std::to_string(k) +
                                  " must start and end on the free surface z = 0");
    if (!(s.front().y1 > s.back().y2))
      throw std::invalid_argument("frequency-domain solver: section " + std::to_string(k) +
                                  " must run from the port waterline (larger y) to the starboard waterline");
  }
}


// Body panels, then lid panels (z = 0 from the starboard to the port waterline of each section), cosine-spaced
// so that the lid panels at the waterline corners are as short as the body panels there; each lid panel's
// taper weight q (see AssembleRows). Sources and field points are numbered body first, then lid.
struct StripPanels {
  std::vector<Panel> body, lid;
  std::vector<double> taper;
  int nb = 0, nl = 0, n = 0;
  const Panel& Source(int j) const { return j < nb ? body[j] : lid[j - nb]; }
};

StripPanels MakeStripPanels(const std::vector<std::vector<Panel>>& sections, const FrequencyDomainOptions& opt) {
  StripPanels sp;
  for (const auto& s : sections) sp.body.insert(sp.body.end(), s.begin(), s.end());
  for (const auto& s : sections) {
    const int n_lid = opt.lid_panels < 0 ? std::max(4, static_cast<int>(s.size()) / 2) : opt.lid_panels;
    const double ys = s.back().y2, yp = s.front().y1, half = 0.5 * (yp - ys);
    auto node = [&](int i) { return ys + half * (1.0 - std::cos(M_PI * i / n_lid)); };
    for (int i = 0; i < n_lid; ++i) {
      sp.lid.push_back({node(i), 0.0, node(i + 1), 0.0});
      const double d = std::min(sp.lid.back().MidY() - ys, yp - sp.lid.back().MidY());
      sp.taper.push_back(std::min(1.0, d / (kLidTaperFraction * half)));
    }
  }
  sp.nb = static_cast<int>(sp.body.size());
  sp.nl = static_cast<int>(sp.lid.size());
  sp.n = sp.nb + sp.nl;
  return sp;
}

// Collocation point of field index i: a body panel midpoint, or a lid midpoint on z = 0.
void FieldPoint(const StripPanels& sp, int i, double* y, double* z) {
  const Panel& fp = sp.Source(i);
  *y = fp.MidY();
  *z = i < sp.nb ? fp.MidZ() : 0.0;
}

// The Rankine parts (frequency-independent) of every source panel at each field point of `fields`, row by
// row (fields.size() × n).
std::vector<RankineSum> RankineRows(const StripPanels& sp, const std::vector<int>& fields) {
  std::vector<RankineSum> out;
  out.reserve(fields.size() * sp.n);
  for (int i : fields) {
    double y, z;
    FieldPoint(sp, i, &y, &z);
    for (int j = 0; j < sp.n; ++j) out.push_back(RankinePart(sp.Source(j), y, z));
  }
  return out;
}

// Influence matrices: normal velocity at body midpoints, potential at body midpoints, and the lid condition
// at lid midpoints. On z = 0 every source panel's potential satisfies φ_z = νφ (the Green function's
// free-surface condition) except for the lid sheet's own jump: just below the lid (inside the body)
// ∂φ/∂z = νφ − σ. The lid rows impose ∂φ/∂z + (2q − 1)νφ = 0 there, i.e. 2qνφ − σ = 0, q the taper weight:
// in the middle of the lid (q = 1) the free-surface condition with the opposite sign. Without a lid the
// interior problem (φ = 0 on the body, φ_z − νφ = 0 on the lid) has the irregular frequencies as
// eigenvalues; with q = 1 everywhere it has none (∫|∇φ|² = −ν∫_lid |φ|² forces φ ≡ 0, so all sources
// vanish). But then the interior potential cannot meet the body potential at the waterline corners
// smoothly: its slope along the body (from the exterior, ∂φ/∂z = νφ) and the lid's ∂φ/∂z = −νφ differ by
// 2νφ, which makes the interior gradient, and so the body source density, log-singular at the corners, and
// the lid densities end there at 2νφ against the body sheet. Constant panels then converge at first order,
// worst at high frequency (semicircle b33 at ω²R/g = 3: +16%, +10% at 14, 28 panels against the lid-off
// +6%, +1.7%). With q → 0 linearly towards each waterline (over kLidTaperFraction of the half beam) the lid
// density vanishes at the corners, the condition there is the exterior one and the corner is regular; the
// interior problem keeps ∫|∇φ|² = ν∫(1 − 2q)|φ|² with a positive part only next to the corners, where
// φ → 0 on the body, which pushes its eigenvalues far above the range of the tests (none up to ω²R/g = 7
// for the semicircle and the B/T = 2 rectangle). A Dirichlet lid (φ = 0) conflicts with the body potential
// at the corners (φ jumps from φ(waterline) to 0): the densities grow like 1/r there (docs/theory.md).
//
// AssembleRows fills row r of A (and, for a body field point, of Phi_body, whose rows are the body fields in
// order; body fields come first in `fields`) for the field index fields[r], all n sources as columns.
void AssembleRows(const StripPanels& sp, const std::vector<int>& fields, const std::vector<RankineSum>& rankine,
                  double nu, const GaussRule& rule, int max_depth, Eigen::MatrixXcd* A, Eigen::MatrixXcd* Phi_body) {
  const double two_log_nu = 2.0 * std::log(nu);
  const int n = sp.n;
  for (std::size_t r = 0; r < fields.size(); ++r) {
    const int i = fields[r];
    const bool on_body = i < sp.nb;
    double y, z;
    FieldPoint(sp, i, &y, &z);
    const auto nrm = sp.Source(i).Normal();
    const auto row = static_cast<Eigen::Index>(r);
    for (int j = 0; j < n; ++j) {
      const Influence inf =
          PanelInfluence(sp.Source(j), rankine[r * n + j], nu, two_log_nu, y, z, rule, max_depth);
      if (on_body) {
        (*A)(row, j) = inf.vy * nrm[0] + inf.vz * nrm[1];
        (*Phi_body)(row, j) = inf.phi;
      } else {
        (*A)(row, j) = 2.0 * nu * sp.taper[i - sp.nb] * inf.phi - (j == i ? 1.0 : 0.0);
      }
    }
  }
}

// The direct formulation's matrices (SectionFormulation::kDirect): at each body midpoint and each lid
// midpoint (rows, body first), the single-layer influence S = (1/2π)∫_j G ds and the double-layer influence
// D = (1/2π)∫_j ∂G/∂n_ξ ds of every body panel j (columns), n_ξ its normal into the fluid; ½ on the diagonal
// of the body rows. G depends on ξ = (η, ζ) through y − η in all three parts and through z − ζ (ln r) or
// z + ζ (ln r′, wave part), so ∇_ξ of the parts is (−∂_y, −∂_z), (−∂_y, +∂_z), (−∂_y, +∂_z) of the field
// gradients that the source formulation already integrates. A body panel's own ln r part has no normal
// derivative on its own line (the flat chord's principal value is zero) and no tangential one at its
// midpoint, so its self term is the ½ alone; no curvature term enters (that corrects the source density's
// normal-velocity operator, which this formulation does not use).
void AssembleDirectRows(const StripPanels& sp, double nu, const GaussRule& rule, int max_depth, Eigen::MatrixXcd* D,
                        Eigen::MatrixXcd* S) {
  const double two_log_nu = 2.0 * std::log(nu);
  const int rows = sp.n, nb = sp.nb;
  for (int i = 0; i < rows; ++i) {
    double y, z;
    FieldPoint(sp, i, &y, &z);
    for (int j = 0; j < nb; ++j) {
      const Panel& p = sp.body[j];
      const SourceInfluence r = RankinePanelInfluence(p, y, z);
      const SourceInfluence im = ImagePanelInfluence(p, y, z);
      Influence w{};
      IntegrateSmooth(nu, two_log_nu, y, z, p.y1, p.z1, p.y2, p.z2, 0, rule, max_depth, &w);
      const C wvy = kInv2Pi * w.vy, wvz = kInv2Pi * w.vz;
      const bool self = i == j;
      const double rvy = self ? 0.0 : r.vy, rvz = self ? 0.0 : r.vz;
      const auto nrm = p.Normal();
      (*D)(i, j) = nrm[0] * (-rvy - im.vy - wvy) + nrm[1] * (-rvz + im.vz + wvz) + (self ? 0.5 : 0.0);
      (*S)(i, j) = r.phi + im.phi + kInv2Pi * w.phi;
    }
  }
}

}  // namespace

bool FrequencyDomainOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  if (!(rho_kg_m3 > 0) || !std::isfinite(rho_kg_m3))
    os << "rho_kg_m3 = " << rho_kg_m3 << " must be a finite number > 0";
  else if (!(g_m_s2 > 0) || !std::isfinite(g_m_s2))
    os << "g_m_s2 = " << g_m_s2 << " must be a finite number > 0";
  else if (lid_panels < -1)
    os << "lid_panels = " << lid_panels << " must be -1 (automatic), 0 (no lid) or > 0";
  else if (gauss_points < 2 || gauss_points > 20)
    os << "gauss_points = " << gauss_points << " must be in 2..20";
  else if (max_subdivision < 0 || max_subdivision > 30)
    os << "max_subdivision = " << max_subdivision << " must be in 0..30";
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

SectionHydrodynamics SolveSectionFrequencyDomain(const std::vector<std::vector<Panel>>& sections,
                                                 double omega, const FrequencyDomainOptions& opt) {
  std::string err;
  if (!opt.IsValid(&err)) throw std::invalid_argument("frequency-domain options: " + err);
  if (!(omega > 0) || !std::isfinite(omega))
    throw std::invalid_argument("frequency-domain solver: omega = " + std::to_string(omega) +
                                " rad/s must be > 0");
  CheckSections(sections);
  const double rho = opt.rho_kg_m3, g = opt.g_m_s2;
  const double nu = omega * omega / g;
  const GaussRule rule = MakeGaussRule(opt.gauss_points);

  const StripPanels sp = MakeStripPanels(sections, opt);
  const std::vector<Panel>& body = sp.body;
  const int nb = sp.nb, n = sp.n;
  auto source = [&](int j) -> const Panel& { return sp.Source(j); };

  // Body normal velocities: three radiation modes (unit velocity) and the beam-sea diffraction problem.
  const C ig_over_omega(0.0, g / omega);  // φ_I = (ig/ω) e^{νz − iνy} per unit wave amplitude
  Eigen::MatrixXcd vn(nb, 4);
  for (int i = 0; i < nb; ++i) {
    const Panel& p = body[i];
    const auto nrm = p.Normal();
    const double y = p.MidY(), z = p.MidZ();
    for (int j = 0; j < 3; ++j) vn(i, j) = ModeNormal(j, nrm[0], nrm[1], y, z);
    const C e = std::exp(C(nu * z, -nu * y));
    vn(i, 3) = -ig_over_omega * nu * C(nrm[1], -nrm[0]) * e;  // −∂φ_I/∂n
  }
  Eigen::MatrixXcd phi;  // potentials at body midpoints, one column per problem
  // Far field: φ → i e^{νz} e^{∓iνy} Σ_j ∫_j s±_j(m) e^{νζ ± iνη} ds for y → ±∞ over the panels j of
  // `far_panels`: s± the source density, or V − φ ν(n_z ± i n_y) in the direct formulation (the far field of
  // G and of its normal derivative at ξ).
  Eigen::MatrixXcd far_plus, far_minus;
  int far_panels = n;
  if (opt.formulation == SectionFormulation::kDirect) {
    Eigen::MatrixXcd D(n, nb), S(n, nb);
    AssembleDirectRows(sp, nu, rule, opt.max_subdivision, &D, &S);
    const Eigen::MatrixXcd rhs = S * vn;
    phi = sp.nl == 0 ? Eigen::MatrixXcd(Eigen::PartialPivLU<Eigen::MatrixXcd>(D).solve(rhs))
                     : Eigen::MatrixXcd(D.colPivHouseholderQr().solve(rhs));
    far_panels = nb;
    far_plus.resize(nb, 4);
    far_minus.resize(nb, 4);
    for (int j = 0; j < nb; ++j) {
      const auto nrm = body[j].Normal();
      const C up = nu * C(nrm[1], nrm[0]), um = nu * C(nrm[1], -nrm[0]);
      for (int m = 0; m < 4; ++m) {
        far_plus(j, m) = vn(j, m) - phi(j, m) * up;
        far_minus(j, m) = vn(j, m) - phi(j, m) * um;
      }
    }
  } else {
    std::vector<int> fields(n);
    for (int i = 0; i < n; ++i) fields[i] = i;
    Eigen::MatrixXcd A(n, n);          // system: body rows ∂φ/∂n, lid rows ∂φ/∂z + νφ from below
    Eigen::MatrixXcd Phi_body(nb, n);  // potential at body midpoints
    AssembleRows(sp, fields, RankineRows(sp, fields), nu, rule, opt.max_subdivision, &A, &Phi_body);
    Eigen::MatrixXcd rhs = Eigen::MatrixXcd::Zero(n, 4);
    rhs.topRows(nb) = vn;
    const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(A);
    const Eigen::MatrixXcd sigma = lu.solve(rhs);
    phi = Phi_body * sigma;
    far_plus = sigma;
    far_minus = sigma;
  }

  SectionHydrodynamics out;
  out.omega_rad_s = omega;
  out.wave_number_per_m = nu;
  out.panels = body;
  out.radiation_potential = phi.leftCols(3);
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 3; ++k) {
      C integral = 0.0;  // ∫ ψ_k n_j ds
      for (int i = 0; i < nb; ++i) {
        const auto nrm = body[i].Normal();
        integral +=
            phi(i, k) * ModeNormal(j, nrm[0], nrm[1], body[i].MidY(), body[i].MidZ()) * body[i].Length();
      }
      out.added_mass(j, k) = -rho * integral.real();
      out.damping(j, k) = rho * omega * integral.imag();
    }
  }
  // Beam-sea exciting force: Froude–Krylov (Gauss along each panel) + diffraction pressure.
  const SectionWaveLoads loads = SectionWaveLoadIntegrals(out, nu, nu, rho, g);
  for (int j = 0; j < 3; ++j) {
    C diff = 0.0;
    for (int i = 0; i < nb; ++i) {
      const auto nrm = body[i].Normal();
      diff += phi(i, 3) * ModeNormal(j, nrm[0], nrm[1], body[i].MidY(), body[i].MidZ()) * body[i].Length();
    }
    out.froude_krylov[j] = loads.froude_krylov[j];
    out.exciting_force[j] = loads.froude_krylov[j] + C(0.0, omega * rho) * diff;
    out.exciting_force_haskind[j] = loads.froude_krylov[j] + loads.diffraction[j];
  }
  // Far-field elevation per unit motion iν K± (K± the sums above).
  for (int m = 0; m < 3; ++m) {
    C kp = 0.0, km = 0.0;
    for (int j = 0; j < far_panels; ++j) {
      const Panel& p = source(j);
      const double L = p.Length();
      for (std::size_t q = 0; q < rule.t.size(); ++q) {
        const double eta = p.y1 + rule.t[q] * (p.y2 - p.y1), zeta = p.z1 + rule.t[q] * (p.z2 - p.z1);
        kp += far_plus(j, m) * rule.w[q] * L * std::exp(C(nu * zeta, nu * eta));
        km += far_minus(j, m) * rule.w[q] * L * std::exp(C(nu * zeta, -nu * eta));
      }
    }
    out.far_wave_plus[m] = C(0.0, nu) * kp;
    out.far_wave_minus[m] = C(0.0, nu) * km;
  }
  return out;
}

std::vector<SectionHydrodynamics> SolveSectionFrequencyDomain(const std::vector<std::vector<Panel>>& sections,
                                                              const std::vector<double>& omegas,
                                                              const FrequencyDomainOptions& opt) {
  std::vector<SectionHydrodynamics> out(omegas.size());
  std::exception_ptr failure = nullptr;
  const int count = static_cast<int>(omegas.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic)
#endif
  for (int i = 0; i < count; ++i) {
    try {
      out[i] = SolveSectionFrequencyDomain(sections, omegas[i], opt);
    } catch (...) {
#ifdef _OPENMP
#pragma omp critical
#endif
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  return out;
}

bool MirrorImagePanels(const std::vector<Panel>& a, const std::vector<Panel>& b, double y_axis, double tol) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Panel &p = a[k], &q = b[b.size() - 1 - k];
    if (!(std::fabs(p.y1 - (2.0 * y_axis - q.y2)) <= tol && std::fabs(p.y2 - (2.0 * y_axis - q.y1)) <= tol &&
          std::fabs(p.z1 - q.z2) <= tol && std::fabs(p.z2 - q.z1) <= tol &&
          std::fabs(p.turn_rad - q.turn_rad) <= 1e-12 * (1.0 + std::fabs(p.turn_rad))))
      return false;
  }
  return true;
}

struct SectionHeaveSolver::Data {
  FrequencyDomainOptions options;
  GaussRule rule;
  StripPanels sp;
  std::vector<int> mirror;   // mirror partner of each source/field index; empty: not symmetric
  std::vector<int> fields;   // field points (and, when symmetric, the unknowns) solved for: body first
  int body_fields = 0;       // how many of `fields` are body panels
  std::vector<RankineSum> rankine;
  std::vector<std::vector<Panel>> sections;  // kept for SectionFormulation::kDirect, solved in full
};

namespace {

// Mirror partners of a strip symmetric about y = y_c: body panel j ↔ nb − 1 − j and lid panel k ↔ nl − 1 − k
// (port waterline → keel → starboard waterline order, sections from one side to the other), each the
// reversed mirror image of the other to 1e-12 of the strip's size. Empty if any pair fails.
std::vector<int> MirrorPartners(const StripPanels& sp) {
  double ymin = sp.body.front().y1, ymax = ymin, zmin = 0.0;
  for (const Panel& p : sp.body) {
    ymin = std::min({ymin, p.y1, p.y2});
    ymax = std::max({ymax, p.y1, p.y2});
    zmin = std::min({zmin, p.z1, p.z2});
  }
  const double yc = 0.5 * (ymin + ymax), tol = 1e-12 * std::max(ymax - ymin, -zmin);
  if (!MirrorImagePanels(sp.body, sp.body, yc, tol) || !MirrorImagePanels(sp.lid, sp.lid, yc, tol)) return {};
  std::vector<int> m(sp.n);
  for (int j = 0; j < sp.n; ++j) m[j] = j < sp.nb ? sp.nb - 1 - j : sp.nb + (sp.nl - 1 - (j - sp.nb));
  return m;
}

}  // namespace

SectionHeaveSolver::SectionHeaveSolver(const std::vector<std::vector<Panel>>& sections,
                                       const FrequencyDomainOptions& opt) {
  std::string err;
  if (!opt.IsValid(&err)) throw std::invalid_argument("frequency-domain options: " + err);
  CheckSections(sections);
  auto d = std::make_shared<Data>();
  d->options = opt;
  d->rule = MakeGaussRule(opt.gauss_points);
  d->sp = MakeStripPanels(sections, opt);
  d->mirror = MirrorPartners(d->sp);
  for (int j = 0; j < d->sp.n; ++j)
    if (d->mirror.empty() || j <= d->mirror[j]) d->fields.push_back(j);
  for (int j : d->fields) d->body_fields += j < d->sp.nb;
  if (opt.formulation == SectionFormulation::kDirect)
    d->sections = sections;
  else
    d->rankine = RankineRows(d->sp, d->fields);
  data_ = std::move(d);
}

bool SectionHeaveSolver::mirror_symmetric() const { return !data_->mirror.empty(); }

Eigen::VectorXcd SectionHeaveSolver::HeavePotential(double omega) const {
  if (!(omega > 0) || !std::isfinite(omega))
    throw std::invalid_argument("frequency-domain solver: omega = " + std::to_string(omega) +
                                " rad/s must be > 0");
  const Data& d = *data_;
  if (d.options.formulation == SectionFormulation::kDirect)
    return SolveSectionFrequencyDomain(d.sections, omega, d.options).radiation_potential.col(1);
  const StripPanels& sp = d.sp;
  const double nu = omega * omega / d.options.g_m_s2;
  const auto nf = static_cast<Eigen::Index>(d.fields.size()), nfb = static_cast<Eigen::Index>(d.body_fields);
  Eigen::MatrixXcd A(nf, sp.n), Phi(nfb, sp.n);
  AssembleRows(sp, d.fields, d.rankine, nu, d.rule, d.options.max_subdivision, &A, &Phi);
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(nf);  // unit heave velocity: ∂ψ/∂n = n_z; lid rows 0
  for (Eigen::Index r = 0; r < nfb; ++r) rhs[r] = sp.body[d.fields[r]].Normal()[1];
  Eigen::VectorXcd out(sp.nb);
  if (d.mirror.empty()) {
    const Eigen::VectorXcd sigma = Eigen::PartialPivLU<Eigen::MatrixXcd>(A).solve(rhs);
    out = Phi * sigma;
    return out;
  }
  // σ_m(j) = σ_j: the columns of mirror partners added, the unknowns those of the half.
  Eigen::MatrixXcd Ah(nf, nf), Phih(nfb, nf);
  for (Eigen::Index c = 0; c < nf; ++c) {
    const int j = d.fields[c], mj = d.mirror[j];
    Ah.col(c) = A.col(j);
    Phih.col(c) = Phi.col(j);
    if (mj != j) {
      Ah.col(c) += A.col(mj);
      Phih.col(c) += Phi.col(mj);
    }
  }
  const Eigen::VectorXcd sigma = Eigen::PartialPivLU<Eigen::MatrixXcd>(Ah).solve(rhs);
  const Eigen::VectorXcd half = Phih * sigma;
  for (Eigen::Index r = 0; r < nfb; ++r) {
    out[d.fields[r]] = half[r];
    out[d.mirror[d.fields[r]]] = half[r];
  }
  return out;
}

SectionWaveLoads SectionWaveLoadIntegrals(const SectionHydrodynamics& hydro, double k, double ky, double rho,
                                          double g) {
  static const GaussRule rule = MakeGaussRule(8);
  SectionWaveLoads out;
  for (std::size_t i = 0; i < hydro.panels.size(); ++i) {
    const Panel& p = hydro.panels[i];
    const auto nrm = p.Normal();
    const double L = p.Length();
    // Sub-panels keep each Gauss rule within a fraction of the wavelength.
    const int parts = 1 + static_cast<int>(L * std::max(k, std::fabs(ky)) / 0.5);
    for (int s = 0; s < parts; ++s) {
      for (std::size_t q = 0; q < rule.t.size(); ++q) {
        const double t = (s + rule.t[q]) / parts;
        const double y = p.y1 + t * (p.y2 - p.y1), z = p.z1 + t * (p.z2 - p.z1);
        const C e = std::exp(C(k * z, -ky * y)) * (rule.w[q] * L / parts);
        const C dn = C(k * nrm[1], -ky * nrm[0]);  // (k n_z − i k_y n_y)
        for (int j = 0; j < 3; ++j) {
          out.froude_krylov[j] += -rho * g * e * ModeNormal(j, nrm[0], nrm[1], y, z);
          out.diffraction[j] += rho * g * hydro.radiation_potential(i, j) * dn * e;
        }
      }
    }
  }
  return out;
}

}  // namespace hullopt::sk
