#include "seakeeping/strip/impulsive_strip_kernel.h"

#include <stdexcept>
#include <string>

#include "seakeeping/green/rankine_panel.h"

namespace hullopt::sk {

Eigen::RowVectorXd ImpulsivePotentialIntegral(const std::vector<Panel>& panels) {
  const auto n = static_cast<Eigen::Index>(panels.size());
  if (n == 0) return Eigen::RowVectorXd();
  Eigen::MatrixXd A(n, n), S(n, n);
  Eigen::RowVectorXd nzl(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Panel& pi = panels[i];
    const auto nrm = pi.Normal();
    nzl[i] = nrm[1] * pi.Length();
    for (Eigen::Index j = 0; j < n; ++j) {
      const auto r = RankinePanelInfluence(panels[j], pi.MidY(), pi.MidZ());
      const auto im = ImagePanelInfluence(panels[j], pi.MidY(), pi.MidZ());
      // φ = 0 on z = 0: the image source has the opposite sign.
      A(i, j) = nrm[0] * (r.vy - im.vy) + nrm[1] * (r.vz - im.vz);
      S(i, j) = r.phi - im.phi;
    }
  }
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  // q = nzl S A⁻¹  ⇔  Aᵀ qᵀ = Sᵀ nzlᵀ.
  const Eigen::VectorXd rhs = S.transpose() * nzl.transpose();
  const Eigen::VectorXd q = A.transpose().partialPivLu().solve(rhs);
  if (!q.allFinite()) throw std::domain_error("impulsive strip kernel: singular Rankine system");
  return q.transpose();
}

void FillImpulsiveStripKernel(StripKernel* k) {
  if (!(k->dt_s > 0.0) || !(k->rho_kg_m3 > 0.0) || static_cast<int>(k->panels.size()) != k->Steps())
    throw std::invalid_argument("FillImpulsiveStripKernel: the kernel geometry (dt, rho, panels) is missing");
  const int N = k->Steps();
  std::vector<Eigen::RowVectorXd> q(N);
#pragma omp parallel for schedule(dynamic)
  for (int n = 0; n < N; ++n) q[n] = ImpulsivePotentialIntegral(k->panels[n]);
  k->force.assign(N, {});
  const double c = k->rho_kg_m3 / k->dt_s;
  for (int n = 0; n < N; ++n) {
    // Rows scaled by dx/weight (2 at the end faces of kCellFaces): the hull sum telescopes to U Φ_T exactly.
    const double cn = k->layout == StationLayout::kCellMidpoints ? c : c * k->dx_m / k->Weight(n);
    for (int m = 0; m <= n; ++m) k->force[n].push_back(Eigen::RowVectorXd::Zero(k->panels[m].size()));
    k->force[n][n] = cn * q[n];
    if (n >= 1) k->force[n][n - 1] = -cn * q[n - 1];
  }
}

}  // namespace hullopt::sk
