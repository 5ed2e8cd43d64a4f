#include "seakeeping/strip/strip_operators.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "seakeeping/green/gauss_legendre.h"
#include "seakeeping/green/memory_influence.h"
#include "seakeeping/green/rankine_panel.h"
#include "seakeeping/green/transient_green.h"
#include "seakeeping/strip/contour_motion.h"

namespace hullopt::sk {
namespace {

constexpr double kInv2Pi = 0.5 / M_PI;

// Re(a·b) as std::complex computes it for finite values (ac − bd), without the imaginary part and the
// NaN-recovery branch: the same bits.
inline double RealOfProduct(std::complex<double> a, std::complex<double> b) {
  return a.real() * b.real() - a.imag() * b.imag();
}

// Collocation points (panel mid-points, where the body condition holds) and the field quadrature of ∫φ n_z
// dl; for the pressure form also the weights wt of the transport term's potential part (TransportWeights).
struct FieldSet {
  std::vector<double> cy, cz, ny, nz;  // per panel
  std::vector<double> qy, qz, wnz;     // per quadrature point: position and weight · n_z [m]
  std::vector<double> wt;              // per quadrature point [m/s], or empty
  // Per quadrature point, lateral rows only (StripOperatorOptions::lateral_rows): weight · n_y [m] and
  // weight · (y n_z − z n_y) [m²] (the roll normal about y = z = 0); empty otherwise.
  std::vector<double> wny, wr4;
  bool lateral = false;  // the lateral rows asked for (also for a step without panels: rows of zeros)
};

FieldSet MakeFieldSet(const std::vector<Panel>& panels, int points_per_panel, bool lateral = false) {
  FieldSet f;
  f.lateral = lateral;
  const auto& rule = GaussLegendre01(points_per_panel);
  for (const Panel& p : panels) {
    const auto n = p.Normal();
    f.cy.push_back(p.MidY()), f.cz.push_back(p.MidZ()), f.ny.push_back(n[0]), f.nz.push_back(n[1]);
    const double L = p.Length();
    for (int k = 0; k < points_per_panel; ++k) {
      const double u = rule.nodes[k];
      f.qy.push_back(p.y1 + u * (p.y2 - p.y1));
      f.qz.push_back(p.z1 + u * (p.z2 - p.z1));
      f.wnz.push_back(rule.weights[k] * L * n[1]);
      if (lateral) {
        f.wny.push_back(rule.weights[k] * L * n[0]);
        f.wr4.push_back(rule.weights[k] * L * (f.qy.back() * n[1] - f.qz.back() * n[0]));
      }
    }
  }
  return f;
}

// Memory of the sources on `src` at lag levels s (each to be differenced over an interval):
// nv(i, j) = (1/2π) ∫_panel ∂H⁽⁻¹⁾/∂n_i ds (real part taken), pl(j) = −(ρ/2π) Σ_q wnz_q ∫_panel Re H⁽⁻¹⁾ ds,
// pt(j) the same sum with the weights wt (empty when the field set has none).
// plat: the lateral rows (sway, roll about y = z = 0) of pl with the weights wny, wr4 (2 × ns, or 0 × ns
// without them).
struct Level {
  Eigen::MatrixXd nv;
  Eigen::RowVectorXd pl, pt;
  Eigen::MatrixXd plat;
};

// The source panels as the kernel sees them: distinct end points (adjacent panels of one contour share
// one) and per panel its two end-point indices and i e^{−iα} (dζc/ds = −i e^{iα}).
struct SourceEnds {
  std::vector<double> y, z;  // per end point
  std::vector<int> first, second;
  std::vector<std::complex<double>> i_e_minus_ialpha;
};

SourceEnds MakeSourceEnds(const std::vector<Panel>& src) {
  SourceEnds e;
  for (std::size_t j = 0; j < src.size(); ++j) {
    const Panel& p = src[j];
    if (j == 0 || !(src[j - 1].y2 == p.y1 && src[j - 1].z2 == p.z1)) e.y.push_back(p.y1), e.z.push_back(p.z1);
    e.first.push_back(static_cast<int>(e.y.size()) - 1);
    e.y.push_back(p.y2), e.z.push_back(p.z2);
    e.second.push_back(static_cast<int>(e.y.size()) - 1);
    const double L = p.Length();
    e.i_e_minus_ialpha.emplace_back((p.z2 - p.z1) / L, (p.y2 - p.y1) / L);  // i·((y2−y1) − i(z2−z1))/L
  }
  return e;
}

// The table work for `count` prepared pairs at the lags (lag 0 gives 0): four pairs per call where all
// lags are positive (eight interleaved chains), the remainder two and one at a time; out[m * nl + l] is
// pair m at lag l. Every grouping gives the same bits (the interleaved forms are the one-point arithmetic).
template <class Four, class Two, class One, class Single>
void TableWork(const TransientGreenPair* pairs, int count, const std::vector<double>& lags, Four four, Two two,
               One one, Single single, std::complex<double>* out) {
  const int nl = static_cast<int>(lags.size());
  const bool both_positive = nl == 2 && lags[0] > 0.0 && lags[1] > 0.0;
  int m = 0;
  if (both_positive) {
    for (; m + 3 < count; m += 4) four(&pairs[m], &out[m * nl]);
    for (; m + 1 < count; m += 2) two(&pairs[m], &out[m * nl]);
    for (; m < count; ++m) one(pairs[m], &out[m * nl]);
    return;
  }
  for (; m < count; ++m)
    for (int l = 0; l < nl; ++l) out[m * nl + l] = lags[l] > 0.0 ? single(pairs[m], l) : 0.0;
}

// The levels of one or two lags into out[0..nl), whose storage is reused when the sizes repeat (the hot loop
// calls this ~N²/2 times). The lag-independent part of the kernel (square roots, division, logarithm of each
// field-point/end-point offset) is computed once and shared by the lags; lag 0 gives a zero level. Without
// `velocity` only pl is computed (nv stays zero). All pairs of a call are prepared in one batch (their square
// roots and divisions overlap) and their table work runs in groups of four across field points.
void ComputeLevelsInto(const FieldSet& f, const SourceEnds& e, const std::vector<double>& lags, double g,
                       double rho, bool velocity, Level* out) {
  const int nf = static_cast<int>(f.cy.size()), ns = static_cast<int>(e.first.size());
  const int nq = static_cast<int>(f.qy.size());
  const int nl = static_cast<int>(lags.size());
  if (nl < 1 || nl > 2) throw std::logic_error("ComputeLevels: one or two lags");
  const bool transport = !f.wt.empty(), lateral = f.lateral;
  for (int l = 0; l < nl; ++l)
    out[l].nv.setZero(velocity ? nf : 0, ns), out[l].pl.setZero(ns), out[l].pt.setZero(transport ? ns : 0),
        out[l].plat.setZero(lateral ? 2 : 0, ns);
  if (ns == 0) return;
  const int ne = static_cast<int>(e.y.size());
  double log_lag[2] = {0.0, 0.0};
  for (int l = 0; l < nl; ++l) log_lag[l] = lags[l] > 0.0 ? std::log(lags[l]) : 0.0;
  // Per-thread scratch, reused from call to call.
  thread_local std::vector<std::complex<double>> h;
  thread_local std::vector<TransientGreenPair> pairs;
  thread_local std::vector<double> Y, Z;
  const std::size_t most = static_cast<std::size_t>(std::max(nf, nq)) * ne;
  if (h.size() < most * nl) h.resize(most * nl);
  if (pairs.size() < most) pairs.resize(most), Y.resize(most), Z.resize(most);
  // Field points are collocation and Gauss points strictly below z = 0 (CheckPanels), so the pairs need no
  // argument checks.
  const double half_sqrt_g = 0.5 * std::sqrt(g);
  const double* t = lags.data();
  if (velocity) {
    for (int i = 0; i < nf; ++i)
      for (int q = 0; q < ne; ++q) Y[i * ne + q] = f.cy[i] - e.y[q], Z[i * ne + q] = f.cz[i] + e.z[q];
    MakeTransientGreenPairsInFluid(Y.data(), Z.data(), nf * ne, half_sqrt_g, false, pairs.data());
    TableWork(
        pairs.data(), nf * ne, lags,
        [&](const TransientGreenPair* p, std::complex<double>* o) { TransientGreenTimeIntegrals4x2(p, t, o); },
        [&](const TransientGreenPair* p, std::complex<double>* o) { TransientGreenTimeIntegrals2x2(p, t, o); },
        [&](const TransientGreenPair& p, std::complex<double>* o) { TransientGreenTimeIntegrals2(p, t, o); },
        [&](const TransientGreenPair& p, int l) { return TransientGreenTimeIntegral(p, t[l]); }, h.data());
    // (1/2π) Re[(n_z + i n_y) i e^{−iα} (ΔH⁽⁻¹⁾(q2) − ΔH⁽⁻¹⁾(q1))] (memory_influence.h).
    for (int i = 0; i < nf; ++i) {
      const std::complex<double>* hi = &h[static_cast<std::size_t>(i) * ne * nl];
      const std::complex<double> n(f.nz[i], f.ny[i]);
      for (int j = 0; j < ns; ++j) {
        const std::complex<double> c = kInv2Pi * n * e.i_e_minus_ialpha[j];
        for (int l = 0; l < nl; ++l) out[l].nv(i, j) = RealOfProduct(c, hi[e.second[j] * nl + l] - hi[e.first[j] * nl + l]);
      }
    }
  }
  // Momentum: Σ_q wnz_q ∫_panel Re H⁽⁻¹⁾ ds, exact along the panel through K (memory_influence.h).
  for (int p = 0; p < nq; ++p)
    for (int q = 0; q < ne; ++q) Y[p * ne + q] = f.qy[p] - e.y[q], Z[p * ne + q] = f.qz[p] + e.z[q];
  MakeTransientGreenPairsInFluid(Y.data(), Z.data(), nq * ne, half_sqrt_g, true, pairs.data());
  TableWork(
      pairs.data(), nq * ne, lags,
      [&](const TransientGreenPair* p, std::complex<double>* o) {
        TransientGreenSpaceTimeIntegrals4x2(p, t, log_lag, g, o);
      },
      [&](const TransientGreenPair* p, std::complex<double>* o) {
        TransientGreenSpaceTimeIntegrals2x2(p, t, log_lag, g, o);
      },
      [&](const TransientGreenPair& p, std::complex<double>* o) {
        TransientGreenSpaceTimeIntegrals2(p, t, log_lag, g, o);
      },
      [&](const TransientGreenPair& p, int l) { return TransientGreenSpaceTimeIntegral(p, t[l], log_lag[l], g); },
      h.data());
  // Per source panel and lag the sums over the field points in registers, in the order of the points (the
  // values of accumulating into the zeroed rows point by point, without a store and reload per term).
  const std::size_t stride = static_cast<std::size_t>(ne) * nl;
  for (int j = 0; j < ns; ++j) {
    const std::complex<double> ie = e.i_e_minus_ialpha[j];
    const std::size_t first = static_cast<std::size_t>(e.first[j]) * nl, second = static_cast<std::size_t>(e.second[j]) * nl;
    for (int l = 0; l < nl; ++l) {
      double pl = 0.0, pt = 0.0, py = 0.0, pr = 0.0;
      // No field points (a dry step): the sums are zero and h may be empty, so no element of it is taken.
      const std::complex<double>* hp = nq > 0 ? &h[static_cast<std::size_t>(l)] : nullptr;
      for (int p = 0; p < nq; ++p, hp += stride) {
        const double v = RealOfProduct(ie, hp[second] - hp[first]);
        pl += f.wnz[p] * v;
        if (transport) pt += f.wt[p] * v;
        if (lateral) py += f.wny[p] * v, pr += f.wr4[p] * v;
      }
      out[l].pl(j) = pl;
      if (transport) out[l].pt(j) = pt;
      if (lateral) out[l].plat(0, j) = py, out[l].plat(1, j) = pr;
    }
  }
  for (int l = 0; l < nl; ++l)
    out[l].pl *= -rho * kInv2Pi, out[l].pt *= -rho * kInv2Pi, out[l].plat *= -rho * kInv2Pi;
}

std::vector<Level> ComputeLevels(const FieldSet& f, const SourceEnds& e, const std::vector<double>& lags,
                                 double g, double rho, bool velocity = true) {
  std::vector<Level> out(lags.size());
  ComputeLevelsInto(f, e, lags, g, rho, velocity, out.data());
  return out;
}

Level ComputeLevel(const FieldSet& f, const SourceEnds& e, double s, double g, double rho, bool velocity = true) {
  return std::move(ComputeLevels(f, e, {s}, g, rho, velocity)[0]);
}


// Rankine normal velocities at the collocation points of f from the sources `src` (with the +1/2 self term
// where a collocation point is a source panel's midpoint), the Rankine part of the momentum row and, when f
// has transport weights and `tr` is given, of the transport row.
void Rankine(const FieldSet& f, const std::vector<Panel>& src, double rho, Eigen::MatrixXd* A,
             Eigen::RowVectorXd* mom, Eigen::RowVectorXd* tr = nullptr, Eigen::MatrixXd* lat = nullptr) {
  const int nf = static_cast<int>(f.cy.size()), ns = static_cast<int>(src.size());
  A->resize(nf, ns);
  mom->setZero(ns);
  const bool lateral = lat && f.lateral;
  if (lat) lat->setZero(lateral ? 2 : 0, ns);
  const bool transport = tr && !f.wt.empty();
  if (tr) tr->setZero(transport ? ns : 0);
  for (int j = 0; j < ns; ++j) {
    for (int i = 0; i < nf; ++i) {
      const auto r = RankinePanelInfluence(src[j], f.cy[i], f.cz[i]);
      const auto m = ImagePanelInfluence(src[j], f.cy[i], f.cz[i]);
      (*A)(i, j) = f.ny[i] * (r.vy - m.vy) + f.nz[i] * (r.vz - m.vz);
    }
    double sum = 0, sum_t = 0, sum_y = 0, sum_r = 0;
    for (std::size_t q = 0; q < f.qy.size(); ++q) {
      const double phi = RankinePanelInfluence(src[j], f.qy[q], f.qz[q]).phi -
                         ImagePanelInfluence(src[j], f.qy[q], f.qz[q]).phi;
      sum += f.wnz[q] * phi;
      if (transport) sum_t += f.wt[q] * phi;
      if (lateral) sum_y += f.wny[q] * phi, sum_r += f.wr4[q] * phi;
    }
    (*mom)(j) = rho * sum;
    if (transport) (*tr)(j) = rho * sum_t;
    if (lateral) (*lat)(0, j) = rho * sum_y, (*lat)(1, j) = rho * sum_r;
  }
}

// The Rankine part of the momentum row from Green's identity instead of the source sum. The current sources
// σ give the normal velocity A σ at the collocation points of `panels` (all of the step's panels, A with the
// +1/2 and curvature self terms); the potential with that normal velocity, zero on z = 0 (the Rankine pair
// G0 = (1/2π)(ln r − ln r′)), solves ½φ_i + Σ_j φ_j ∫_j ∂G0/∂n_ξ ds = Σ_j (Aσ)_j ∫_j G0 ds, and its momentum is
// ρ Σ_i φ_i n_z,i l_i. ∇_ξ of ln r is −∇ of the field point, of ln r′ (−∂_y, +∂_z): the double layer of the
// pair is n_y(−v_y + v′_y) + n_z(−v_z − v′_z) with v, v′ the field gradients of the panel and of its image.
// A flat chord's own ln r part has no normal derivative on its line, so the self term is the ½ alone. The
// potential stays bounded at re-entrant corners where σ does not (docs/sections.md, the direct formulation).
Eigen::RowVectorXd GreenIdentityRankineMomentum(const std::vector<Panel>& panels, double rho) {
  const int n = static_cast<int>(panels.size());
  Eigen::MatrixXd A(n, n), D(n, n), S(n, n);
  Eigen::RowVectorXd c(n);
  for (int i = 0; i < n; ++i) {
    const Panel& fp = panels[i];
    const auto fn = fp.Normal();
    const double y = fp.MidY(), z = fp.MidZ();
    c(i) = fn[1] * fp.Length();
    for (int j = 0; j < n; ++j) {
      const Panel& p = panels[j];
      const auto r = RankinePanelInfluence(p, y, z);
      const auto m = ImagePanelInfluence(p, y, z);
      A(i, j) = fn[0] * (r.vy - m.vy) + fn[1] * (r.vz - m.vz);
      const auto pn = p.Normal();
      const double rvy = i == j ? 0.0 : r.vy, rvz = i == j ? 0.0 : r.vz;
      D(i, j) = pn[0] * (-rvy + m.vy) + pn[1] * (-rvz - m.vz) + (i == j ? 0.5 : 0.0);
      S(i, j) = r.phi - m.phi;
    }
  }
  // Row c D⁻¹ S A: solve Dᵀ x = cᵀ once.
  const Eigen::VectorXd x = D.transpose().partialPivLu().solve(c.transpose());
  return rho * (x.transpose() * S) * A;
}

// Mirror symmetry of one step's panels about y = yc: the reduced (half) panels and, per reduced panel, its
// own full index and its partner's (the same index for a panel on the symmetry line).
struct MirrorMap {
  std::vector<int> half, partner;
  std::vector<int> reduced_of;  // per full panel
  std::vector<double> share;    // per full panel
};

bool FindMirrorMap(const std::vector<Panel>& P, double yc, double tol, MirrorMap* out) {
  const int n = static_cast<int>(P.size());
  std::vector<int> mirror(n, -1);
  for (int j = 0; j < n; ++j) {
    // The mirror image of a panel runs the other way, so that its normal is mirrored too.
    for (int k = 0; k < n && mirror[j] < 0; ++k)
      if (std::fabs(P[k].y1 - (2 * yc - P[j].y2)) <= tol && std::fabs(P[k].z1 - P[j].z2) <= tol &&
          std::fabs(P[k].y2 - (2 * yc - P[j].y1)) <= tol && std::fabs(P[k].z2 - P[j].z1) <= tol)
        mirror[j] = k;
    if (mirror[j] < 0) return false;
  }
  MirrorMap m;
  m.reduced_of.assign(n, -1);
  m.share.assign(n, 1.0);
  for (int j = 0; j < n; ++j) {
    const double d = P[j].MidY() - yc;
    if (mirror[j] == j || d > tol) {
      m.reduced_of[j] = static_cast<int>(m.half.size());
      m.half.push_back(j);
      m.partner.push_back(mirror[j]);
    }
  }
  for (int j = 0; j < n; ++j) {
    if (m.reduced_of[j] < 0) m.reduced_of[j] = m.reduced_of[mirror[j]];
    if (m.reduced_of[j] < 0) return false;  // a pair straddling the line off its own mirror: not symmetric
    if (mirror[j] != j) m.share[j] = 0.5;
  }
  *out = std::move(m);
  return true;
}

// One symmetry line y_c for all steps (the memory couples the steps, so they must share it).
bool FindMirrorMaps(const std::vector<std::vector<Panel>>& steps, std::vector<MirrorMap>* maps) {
  double scale = 0.0, ysum = 0.0;
  int count = 0;
  for (const auto& P : steps)
    for (const Panel& p : P) {
      scale = std::fmax(scale, std::fmax(std::fmax(std::fabs(p.y1), std::fabs(p.y2)),
                                         std::fmax(std::fabs(p.z1), std::fabs(p.z2))));
      ysum += p.y1 + p.y2;
      count += 2;
    }
  if (count == 0) return false;
  const double yc = ysum / count, tol = 1e-9 * scale;
  maps->assign(steps.size(), MirrorMap{});
  for (std::size_t n = 0; n < steps.size(); ++n)
    if (!FindMirrorMap(steps[n], yc, tol, &(*maps)[n])) return false;
  return true;
}

// Columns of the full sources combined into the symmetric (σ_j = σ_j′) reduced sources, into *out (storage
// reused when the sizes repeat: the hot loop reduces every level).
template <class Dense>
void ReduceColumnsInto(const Dense& full, const MirrorMap& m, Dense* out) {
  const auto R = static_cast<Eigen::Index>(m.half.size());
  out->resize(full.rows(), R);
  for (Eigen::Index r = 0; r < R; ++r) {
    out->col(r) = full.col(m.half[r]);
    if (m.partner[r] != m.half[r]) out->col(r) += full.col(m.partner[r]);
  }
}
template <class Dense>
Dense ReduceColumns(const Dense& full, const MirrorMap& m) {
  Dense out;
  ReduceColumnsInto(full, m, &out);
  return out;
}
void ReduceLevelInto(const Level& full, const MirrorMap& m, Level* out) {
  ReduceColumnsInto(full.nv, m, &out->nv);
  ReduceColumnsInto(full.pl, m, &out->pl);
  if (full.pt.size() == 0)
    out->pt.resize(0);
  else
    ReduceColumnsInto(full.pt, m, &out->pt);
}

// The transport term of the pressure form at one step (contour_motion.h), T = ∫_S W_n ∂φ/∂z dl − Σ_wl φ ẏ_out,
// split as ∂φ/∂z = n_z ∂φ/∂n + t_z ∂φ/∂s with t = (p2 − p1)/L along each panel: the part with ∂φ/∂n is the
// body condition's V (returned per panel in *direct, ρ W_n n_z L, so that its contribution is direct·V), the
// rest is a weighted sum of φ at field points, stored as f->wt (without ρ; the levels multiply by it). On each
// panel ∫ ∂φ/∂s dl = φ(p2) − φ(p1) exactly: φ is taken at the panel's end points, which are added to the field
// set (momentum weight 0; one point per shared vertex). An end on the free surface (z = 0, where the memory
// kernel of a coinciding source end is singular) takes φ from the least-squares line through the panel's
// quadrature points extrapolated to it, as does the waterline term; that needs at least two points per panel.
// `full_of` maps the field set's panels to the step's panels (identity, or the mirror-reduced half); `twice`
// marks reduced panels that stand for a mirror pair, whose weights count twice as the momentum's do.
void TransportWeights(const std::vector<Panel>& panels, const ContourMotion& motion,
                      const std::vector<int>& full_of, const std::vector<bool>& twice, int points_per_panel,
                      double rho, FieldSet* f, Eigen::RowVectorXd* direct) {
  const auto& rule = GaussLegendre01(points_per_panel);
  double mean = 0.0, spread = 0.0, scale_m = 0.0;
  for (int k = 0; k < points_per_panel; ++k) mean += rule.nodes[k] / points_per_panel;
  for (int k = 0; k < points_per_panel; ++k) spread += (rule.nodes[k] - mean) * (rule.nodes[k] - mean);
  for (const Panel& p : panels) scale_m = std::max({scale_m, std::fabs(p.y1), std::fabs(p.y2), std::fabs(p.z1), std::fabs(p.z2)});
  const double surface_tol = 1e-9 * scale_m;
  const int R = static_cast<int>(full_of.size());
  f->wt.assign(f->qy.size(), 0.0);
  direct->setZero(R);
  // φ at the end u (0 or 1) of panel r from its quadrature points' least-squares line, weight c.
  auto add_extrapolated = [&](int r, double u, double c) {
    for (int k = 0; k < points_per_panel; ++k)
      f->wt[r * points_per_panel + k] += c * (1.0 / points_per_panel + (u - mean) * (rule.nodes[k] - mean) / spread);
  };
  // φ at a vertex below the surface: a field point of its own, shared by the panels meeting there.
  auto add_vertex = [&](double y, double z, double c) {
    for (std::size_t q = static_cast<std::size_t>(R) * points_per_panel; q < f->qy.size(); ++q)
      if (f->qy[q] == y && f->qz[q] == z) {
        f->wt[q] += c;
        return;
      }
    f->qy.push_back(y), f->qz.push_back(z), f->wnz.push_back(0.0), f->wt.push_back(c);
  };
  for (int r = 0; r < R; ++r) {
    const int j = full_of[r];
    const Panel& p = panels[j];
    const double scale = twice[r] ? 2.0 : 1.0;
    const double W = motion.normal_speed_m_s[j], tz = (p.z2 - p.z1) / p.Length();
    (*direct)(r) = scale * rho * W * p.Normal()[1] * p.Length();
    const double c = scale * W * tz;  // times φ(p2) − φ(p1)
    if (c != 0.0) {
      if (p.z2 < -surface_tol) add_vertex(p.y2, p.z2, c); else add_extrapolated(r, 1.0, c);
      if (p.z1 < -surface_tol) add_vertex(p.y1, p.z1, -c); else add_extrapolated(r, 0.0, -c);
    }
    for (const WaterlinePoint& w : motion.waterline)
      if (w.panel == j) add_extrapolated(r, w.at_end ? 1.0 : 0.0, -scale * w.speed_m_s);
  }
}

void CheckPanels(const std::vector<Panel>& panels, int step) {
  for (std::size_t j = 0; j < panels.size(); ++j) {
    const Panel& p = panels[j];
    const std::string where = "step " + std::to_string(step) + " panel " + std::to_string(j);
    if (!(std::isfinite(p.y1) && std::isfinite(p.z1) && std::isfinite(p.y2) && std::isfinite(p.z2)))
      throw std::invalid_argument(where + ": non-finite coordinate");
    if (p.z1 > 0.0 || p.z2 > 0.0)
      throw std::invalid_argument(where + ": panel above the free surface (z > 0): z1 = " +
                                  std::to_string(p.z1) + ", z2 = " + std::to_string(p.z2));
    if (!(p.Length() > 0.0)) throw std::invalid_argument(where + ": zero-length panel");
    if (p.MidZ() >= 0.0)
      throw std::invalid_argument(where + ": collocation point on z = 0 (panel lies on the surface)");
  }
}

void CheckScalars(double dt, double rho, double g, const StripOperatorOptions& options) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument(err);
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw std::invalid_argument("time step dt must be > 0, got " + std::to_string(dt));
  if (!(rho > 0.0)) throw std::invalid_argument("rho must be > 0, got " + std::to_string(rho));
  if (!(g > 0.0)) throw std::invalid_argument("g must be > 0, got " + std::to_string(g));
}

}  // namespace

bool StripOperatorOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (field_points_per_panel < 1 || field_points_per_panel > 16)
    return fail("field_points_per_panel must be in 1..16, got " + std::to_string(field_points_per_panel));
  if (sectional_force == SectionalForce::kPressure && field_points_per_panel < 2)
    return fail("the pressure form needs field_points_per_panel >= 2 (the potential's slope along each panel), got " +
                std::to_string(field_points_per_panel));
  if (body_potential == BodyPotential::kGreenIdentity && sectional_force != SectionalForce::kMomentum)
    return fail("body potential from Green's identity applies to the momentum form of the sectional force only (the "
                "pressure form evaluates earlier steps' source potentials on the current contour)");
  if (lateral_rows && (use_mirror_symmetry || sectional_force != SectionalForce::kMomentum ||
                       body_potential != BodyPotential::kSourceSum))
    return fail(
        "the lateral rows (sway force, roll moment) need full sections (no mirror symmetry), the momentum "
        "form of the sectional force and the source-sum body potential");
  return true;
}

const Eigen::MatrixXd& StripOperators::System(int n) const {
  return system_[invariant_ ? (n == 0 ? 0 : 1) : n];
}

double StripOperators::ConditionEstimate(int n) const {
  const auto& lu = lu_[invariant_ ? (n == 0 ? 0 : 1) : n];
  if (lu.rows() == 0) return 1.0;
  const double r = lu.rcond();
  return r > 0.0 ? 1.0 / r : std::numeric_limits<double>::infinity();
}

Eigen::MatrixXd StripOperators::Solve(int n, const Eigen::MatrixXd& rhs) const {
  if (rhs.size() == 0) return rhs;
  return lu_[invariant_ ? (n == 0 ? 0 : 1) : n].solve(rhs);
}

namespace {
void RequireStart(bool has_start) {
  if (!has_start)
    throw std::logic_error(
        "strip operators built steady_state_only: no memory of the first interval for marching");
}
}  // namespace

const Eigen::MatrixXd& StripOperators::Memory(int n, int k) const {
  if (!invariant_) return memory_[n][k];
  if (k == 0) RequireStart(has_start_);
  return k == 0 ? memory_[1][n] : memory_[0][n - k];
}

const Eigen::RowVectorXd& StripOperators::MomentumCurrent(int n) const {
  return momentum_current_[invariant_ ? (n == 0 ? 0 : 1) : n];
}

const Eigen::MatrixXd& StripOperators::LateralMomentumCurrent(int n) const {
  if (lateral_current_.empty())
    throw std::logic_error("LateralMomentumCurrent: operators built without lateral rows");
  return lateral_current_[n];
}

const Eigen::MatrixXd& StripOperators::LateralMomentumMemory(int n, int k) const {
  if (lateral_current_.empty())
    throw std::logic_error("LateralMomentumMemory: operators built without lateral rows");
  return lateral_memory_[n][k];
}

const Eigen::RowVectorXd& StripOperators::MomentumMemory(int n, int k) const {
  if (!invariant_) return momentum_memory_[n][k];
  if (k == 0) RequireStart(has_start_);
  return k == 0 ? momentum_memory_[1][n] : momentum_memory_[0][n - k];
}

namespace {
void RequirePressure(SectionalForce force, int n, int k, int steps) {
  if (force != SectionalForce::kPressure || n < 0 || n >= steps || k < 0 || k > n)
    throw std::out_of_range("transport rows: need general operators built for the pressure form, 0 <= k <= n < steps");
}
}  // namespace

const Eigen::RowVectorXd& StripOperators::TransportCurrent(int n) const {
  RequirePressure(invariant_ ? SectionalForce::kMomentum : force_, n, n, steps_);
  return transport_current_[n];
}

const Eigen::RowVectorXd& StripOperators::TransportMemory(int n, int k) const {
  RequirePressure(invariant_ ? SectionalForce::kMomentum : force_, n, k, steps_);
  if (k == n) throw std::out_of_range("TransportMemory: k < n");
  return transport_memory_[n][k];
}

const Eigen::RowVectorXd& StripOperators::TransportDirect(int n) const {
  RequirePressure(invariant_ ? SectionalForce::kMomentum : force_, n, n, steps_);
  return transport_direct_[n];
}

const Eigen::MatrixXd& StripOperators::LagMemory(int l) const {
  if (!invariant_ || l < 1 || l >= steps_)
    throw std::out_of_range("LagMemory: needs time-invariant operators, 1 <= l < steps");
  return memory_[0][l];
}

const Eigen::RowVectorXd& StripOperators::LagMomentum(int l) const {
  if (!invariant_ || l < 1 || l >= steps_)
    throw std::out_of_range("LagMomentum: needs time-invariant operators, 1 <= l < steps");
  return momentum_memory_[0][l];
}

StripOperators BuildStripOperators(const std::vector<std::vector<Panel>>& panels_per_step, double dt,
                                   double rho, double g, const StripOperatorOptions& options,
                                   const std::vector<ContourMotion>* motions) {
  CheckScalars(dt, rho, g, options);
  const int N = static_cast<int>(panels_per_step.size());
  if (motions) {
    bool fits = static_cast<int>(motions->size()) == N;
    for (int n = 0; fits && n < N; ++n) fits = (*motions)[n].normal_speed_m_s.size() == panels_per_step[n].size();
    if (!fits) throw std::invalid_argument("strip operators: the contour motions do not match the steps' panels");
  }
  for (int n = 0; n < N; ++n) CheckPanels(panels_per_step[n], n);
  StripOperators ops;
  ops.steps_ = N, ops.dt_ = dt, ops.rho_ = rho, ops.g_ = g, ops.invariant_ = false;
  ops.layout_ = options.layout;
  ops.force_ = options.sectional_force;
  if (ops.layout_ == StationLayout::kCellFaces && N < 4)
    throw std::invalid_argument("strip operators: stations at the cell faces need >= 4 steps, got " +
                                std::to_string(N));
  std::vector<MirrorMap> maps;
  ops.reduced_ = options.use_mirror_symmetry && FindMirrorMaps(panels_per_step, &maps);
  ops.reduced_index_.resize(N);
  ops.reduced_share_.resize(N);
  if (ops.reduced_) {
    ops.full_panels_ = panels_per_step;
    ops.panels_.resize(N);
    for (int n = 0; n < N; ++n) {
      for (int j : maps[n].half) ops.panels_[n].push_back(panels_per_step[n][j]);
      ops.reduced_index_[n] = maps[n].reduced_of;
      ops.reduced_share_[n] = maps[n].share;
    }
  } else {
    ops.panels_ = panels_per_step;
    for (int n = 0; n < N; ++n) {
      const int P = static_cast<int>(panels_per_step[n].size());
      for (int j = 0; j < P; ++j) ops.reduced_index_[n].push_back(j);
      ops.reduced_share_[n].assign(P, 1.0);
    }
  }
  ops.system_.resize(N);
  ops.lu_.resize(N);
  ops.momentum_current_.resize(N);
  ops.memory_.resize(N);
  ops.momentum_memory_.resize(N);
  const bool lateral = options.lateral_rows;
  if (lateral) ops.lateral_current_.resize(N), ops.lateral_memory_.resize(N);
  const bool pressure = ops.force_ == SectionalForce::kPressure;
  if (pressure) ops.transport_current_.resize(N), ops.transport_memory_.resize(N), ops.transport_direct_.resize(N);
  std::vector<SourceEnds> ends(N);  // the source panels of each step as the kernel sees them, once
  for (int n = 0; n < N; ++n) ends[n] = MakeSourceEnds(panels_per_step[n]);
  // Each n is independent and computed by one thread in a fixed order: bitwise identical for any thread
  // count.
#pragma omp parallel for schedule(dynamic, 1)
  for (int n = N - 1; n >= 0; --n) {  // largest work first
    FieldSet f = MakeFieldSet(ops.panels_[n], options.field_points_per_panel, lateral);
    std::vector<bool> twice(ops.panels_[n].size(), false);
    std::vector<int> full_of(ops.panels_[n].size());
    for (std::size_t r = 0; r < full_of.size(); ++r) full_of[r] = static_cast<int>(r);
    if (ops.reduced_) {
      // The momentum integrand is symmetric: the points of a mirror pair's half count twice.
      const int pp = options.field_points_per_panel;
      for (std::size_t r = 0; r < maps[n].half.size(); ++r) {
        full_of[r] = maps[n].half[r];
        twice[r] = maps[n].partner[r] != maps[n].half[r];
        if (twice[r])
          for (int q = 0; q < pp; ++q) f.wnz[r * pp + q] *= 2.0;
      }
    }
    if (pressure && !panels_per_step[n].empty())
      TransportWeights(panels_per_step[n], motions ? (*motions)[n] : StepContourMotion(panels_per_step, n, dt), full_of, twice,
                       options.field_points_per_panel, rho, &f, &ops.transport_direct_[n]);
    Eigen::MatrixXd A;
    Eigen::RowVectorXd mom, tr;
    Eigen::MatrixXd lat;
    Rankine(f, panels_per_step[n], rho, &A, &mom, pressure ? &tr : nullptr, lateral ? &lat : nullptr);
    if (options.body_potential == BodyPotential::kGreenIdentity && !panels_per_step[n].empty())
      mom = GreenIdentityRankineMomentum(panels_per_step[n], rho);
    if (ops.reduced_) {
      A = ReduceColumns(A, maps[n]), mom = ReduceColumns(mom, maps[n]);
      if (tr.size() > 0) tr = ReduceColumns(tr, maps[n]);
    }
    ops.memory_[n].resize(n);
    ops.momentum_memory_[n].resize(n);
    if (pressure) ops.transport_memory_[n].resize(n);
    if (lateral) ops.lateral_memory_[n].resize(n);
    for (int k = 0; k <= n; ++k) {
      // Lags of interval k seen at t_n: [max(0, t_k − dt/2), t_k + dt/2] (k < n), [t_n − dt/2, t_n] (k = n).
      double s1, s2;
      if (k == n) {
        if (n == 0) break;
        s1 = 0.0, s2 = 0.5 * dt;
      } else {
        s1 = (n - k - 0.5) * dt;
        s2 = k == 0 ? n * dt : (n - k + 0.5) * dt;
      }
      thread_local Level full[2], reduced[2];
      thread_local std::vector<double> lags(2);
      lags[0] = s1, lags[1] = s2;
      ComputeLevelsInto(f, ends[k], lags, g, rho, true, full);
      if (ops.reduced_) ReduceLevelInto(full[0], maps[k], &reduced[0]), ReduceLevelInto(full[1], maps[k], &reduced[1]);
      const Level& a = ops.reduced_ ? reduced[0] : full[0];
      const Level& b = ops.reduced_ ? reduced[1] : full[1];
      if (k == n) {
        A -= b.nv - a.nv;
        mom += b.pl - a.pl;
        if (tr.size() > 0) tr += b.pt - a.pt;
        if (lateral) lat += b.plat - a.plat;
      } else {
        ops.memory_[n][k] = b.nv - a.nv;
        ops.momentum_memory_[n][k] = b.pl - a.pl;
        if (pressure) ops.transport_memory_[n][k] = b.pt - a.pt;
        if (lateral) ops.lateral_memory_[n][k] = b.plat - a.plat;
      }
    }
    if (lateral) ops.lateral_current_[n] = lat;
    if (pressure) ops.transport_current_[n] = tr;
    ops.system_[n] = A;
    if (A.rows() > 0) ops.lu_[n].compute(A);
    ops.momentum_current_[n] = mom;
  }
  return ops;
}

StripOperators BuildFixedSectionOperators(const std::vector<Panel>& panels, int steps, double dt, double rho,
                                          double g, const StripOperatorOptions& options,
                                          bool steady_state_only) {
  CheckScalars(dt, rho, g, options);
  CheckPanels(panels, 0);
  if (steps < 1) throw std::invalid_argument("steps must be >= 1, got " + std::to_string(steps));
  if (panels.empty()) throw std::invalid_argument("fixed section has no panels");
  if (options.lateral_rows) throw std::invalid_argument("fixed-section operators have no lateral rows");
  const int N = steps;
  StripOperators ops;
  ops.steps_ = N, ops.dt_ = dt, ops.rho_ = rho, ops.g_ = g, ops.invariant_ = true;
  ops.has_start_ = !steady_state_only;
  ops.panels_ = {panels};
  ops.reduced_index_.assign(1, {});
  for (std::size_t j = 0; j < panels.size(); ++j) ops.reduced_index_[0].push_back(static_cast<int>(j));
  ops.reduced_share_.assign(1, std::vector<double>(panels.size(), 1.0));
  const FieldSet f = MakeFieldSet(panels, options.field_points_per_panel);
  const SourceEnds ends = MakeSourceEnds(panels);
  // Levels: half[m] at (m + ½)dt, m = 0..N−1; whole[n] at n·dt, n = 1..N−1.
  std::vector<Level> half(N), whole(N);
  const int jobs = steady_state_only ? N : 2 * N - 1;
#pragma omp parallel for schedule(dynamic, 1)
  for (int job = 0; job < jobs; ++job) {
    if (job < N)
      half[job] = ComputeLevel(f, ends, (job + 0.5) * dt, g, rho);
    else
      whole[job - N + 1] = ComputeLevel(f, ends, (job - N + 1) * dt, g, rho);
  }
  Eigen::MatrixXd A;
  Eigen::RowVectorXd mom;
  Rankine(f, panels, rho, &A, &mom);
  if (options.body_potential == BodyPotential::kGreenIdentity) mom = GreenIdentityRankineMomentum(panels, rho);
  ops.system_ = {A, A - half[0].nv};
  ops.lu_.resize(2);
  ops.lu_[0].compute(ops.system_[0]);
  ops.lu_[1].compute(ops.system_[1]);
  ops.momentum_current_ = {mom, mom + half[0].pl};
  ops.memory_.assign(2, std::vector<Eigen::MatrixXd>(N));
  ops.momentum_memory_.assign(2, std::vector<Eigen::RowVectorXd>(N));
  for (int l = 1; l < N; ++l) {
    ops.memory_[0][l] = half[l].nv - half[l - 1].nv;
    ops.momentum_memory_[0][l] = half[l].pl - half[l - 1].pl;
    if (steady_state_only) continue;
    ops.memory_[1][l] = whole[l].nv - half[l - 1].nv;
    ops.momentum_memory_[1][l] = whole[l].pl - half[l - 1].pl;
  }
  return ops;
}

}  // namespace hullopt::sk
