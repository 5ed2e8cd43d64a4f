#include "seakeeping/strip/strip_kernel_builder.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "seakeeping/strip/block_product.h"

namespace hullopt::sk {

StripKernel BuildStripKernel(const StripOperators& ops, const std::vector<double>& x_m) {
  const int N = ops.Steps();
  if (static_cast<int>(x_m.size()) != N)
    throw std::invalid_argument("strip kernel: x_m has " + std::to_string(x_m.size()) + " stations for " +
                                std::to_string(N) + " steps");
  StripKernel K;
  K.dt_s = ops.Dt();
  K.dx_m = N > 1 ? std::fabs(x_m[1] - x_m[0]) : 0.0;
  K.speed_m_s = K.dx_m / K.dt_s;
  K.rho_kg_m3 = ops.Rho();
  K.g_m_s2 = ops.G();
  K.layout = ops.Layout();
  K.x_m = x_m;
  K.panels.resize(N);
  for (int n = 0; n < N; ++n) K.panels[n] = ops.FullPanelsAt(n);
  K.force.resize(N);
  for (int n = 0; n < N; ++n) K.force[n].resize(n + 1);
  const bool lateral = ops.HasLateralRows();
  if (lateral) {
    K.lateral_force.resize(N);
    for (int n = 0; n < N; ++n) K.lateral_force[n].resize(n + 1);
  }
  for (int n = 0; n < N; ++n) K.system_condition.push_back(ops.PanelCount(n) > 0 ? ops.ConditionEstimate(n) : 1.0);
  // Column by column (input step m): propagate the source responses forward in n. Columns are independent
  // and each is computed by one thread in a fixed order (bitwise identical for any thread count); the work
  // of column m falls like (N − m)², so the largest go first.
#pragma omp parallel for schedule(dynamic, 1)
  for (int m = 0; m < N; ++m) {
    const int Pm = ops.PanelCount(m);
    std::vector<Eigen::MatrixXd> S(N);  // S[n] = ∂σ_n/∂V_m, n >= m
    std::vector<Eigen::RowVectorXd> J(N);
    std::vector<Eigen::MatrixXd> JL(lateral ? N : 0);  // the lateral momenta (sway, roll), lateral rows only
    const Eigen::RowVectorXd zero = Eigen::RowVectorXd::Zero(Pm);  // the momenta before input step m
    const Eigen::MatrixXd zero_lateral = Eigen::MatrixXd::Zero(2, Pm);
    for (int n = m; n < N; ++n) {
      const int Pn = ops.PanelCount(n);
      Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(Pn, Pm);
      Eigen::RowVectorXd j = Eigen::RowVectorXd::Zero(Pm);
      if (n == m) rhs.setIdentity();
      for (int k = m; k < n; ++k) {
        if (ops.PanelCount(k) == 0) continue;
        if (Pn > 0) AddProduct(ops.Memory(n, k), S[k], &rhs);
        j.noalias() += ops.MomentumMemory(n, k).lazyProduct(S[k]);
      }
      S[n] = Pn > 0 ? ops.Solve(n, rhs) : Eigen::MatrixXd(0, Pm);
      if (Pn > 0) j.noalias() += ops.MomentumCurrent(n) * S[n];
      J[n] = j;
      auto at = [&](int k) -> const Eigen::RowVectorXd& { return k >= m ? J[k] : zero; };
      const auto c = ops.ForceStencil(n);
      Eigen::RowVectorXd f = (c[0] * J[n] + c[1] * at(n - 1) + c[2] * at(n - 2)) / (2.0 * ops.Dt());
      if (lateral) {
        // The same momentum sum and difference for the sway and roll rows.
        Eigen::MatrixXd jl = Eigen::MatrixXd::Zero(2, Pm);
        for (int k = m; k < n; ++k)
          if (ops.PanelCount(k) > 0) jl.noalias() += ops.LateralMomentumMemory(n, k) * S[k];
        if (Pn > 0) jl.noalias() += ops.LateralMomentumCurrent(n) * S[n];
        JL[n] = jl;
        auto lat = [&](int k) -> const Eigen::MatrixXd& { return k >= m ? JL[k] : zero_lateral; };
        K.lateral_force[n][m] = (c[0] * JL[n] + c[1] * lat(n - 1) + c[2] * lat(n - 2)) / (2.0 * ops.Dt());
      }
      if (ops.Force() == SectionalForce::kPressure && Pn > 0) {
        // Minus the moving contour's transport term (strip_operators.h); sources before m are zero.
        f.noalias() -= ops.TransportCurrent(n) * S[n];
        for (int k = m; k < n; ++k)
          if (ops.PanelCount(k) > 0) f.noalias() -= ops.TransportMemory(n, k) * S[k];
        if (n == m) f -= ops.TransportDirect(n);
      }
      if (!ops.MirrorReduced()) {
        K.force[n][m] = f;
        continue;
      }
      // Back to all panels: each panel of a mirror pair takes half the reduced input (its symmetric part).
      const auto& index = ops.ReducedIndex(m);
      const auto& share = ops.ReducedShare(m);
      K.force[n][m].resize(static_cast<Eigen::Index>(index.size()));
      for (std::size_t p = 0; p < index.size(); ++p) K.force[n][m](p) = share[p] * f(index[p]);
    }
  }
  return K;
}

StripKernel BuildStripKernel(const std::vector<std::vector<Panel>>& panels_per_step,
                             const std::vector<double>& x_m, double dt, double rho, double g,
                             const StripOperatorOptions& options) {
  return BuildStripKernel(BuildStripOperators(panels_per_step, dt, rho, g, options), x_m);
}

StripKernel BuildStripKernelMirrorReduced(const std::vector<std::vector<Panel>>& panels_per_step,
                                          const std::vector<double>& x_m, double dt, double rho, double g,
                                          StripOperatorOptions options) {
  options.use_mirror_symmetry = true;
  return BuildStripKernel(BuildStripOperators(panels_per_step, dt, rho, g, options), x_m);
}

}  // namespace hullopt::sk
