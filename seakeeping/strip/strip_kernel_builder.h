#pragma once
// Reduction of a strip's operators to the linear map of seakeeping/strip_kernel.h (docs/ship-motions.md;
// the last stage, after strip_operators.h and strip_marcher.h):
//   f_n = Σ_{m<=n} force[n][m] V_m.
// The P_n × P_m source responses S_{n,m} = ∂σ_n/∂V_m follow from the marching equations,
//   S_{m,m} = System(m)⁻¹,   S_{n,m} = System(n)⁻¹ Σ_{k=m}^{n−1} Memory(n, k) S_{k,m},
// the momentum responses J_{n,m} = MomentumCurrent(n) S_{n,m} + Σ_{k=m}^{n−1} MomentumMemory(n, k) S_{k,m},
// and force[n][m] = (3 J_{n,m} − 4 J_{n−1,m} + J_{n−2,m}) / (2 dt) (J_{n',m} = 0 for n' < m; end rows of
// their own for StationLayout::kCellFaces, StripOperators::ForceStencil), exactly the force of StripMarcher
// for any inputs. Cost O(N³ P³ / 6).
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/strip/strip_kernel.h"
#include "seakeeping/strip/strip_operators.h"

namespace hullopt::sk {

/// Kernel of a strip whose operators are built; x_m [m]: station from the AP held at each step (size
/// ops.Steps()). speed_m_s and dx_m are set from dt and the first station spacing |x_m[1] − x_m[0]| (0 for a
/// single step). Throws std::invalid_argument when x_m has the wrong size.
StripKernel BuildStripKernel(const StripOperators& ops, const std::vector<double>& x_m);

/// Convenience: operators and kernel in one call. panels_per_step[n] are the panels of the section at x_m[n]
/// (all bodies in the strip), dt = dx/U [s].
StripKernel BuildStripKernel(const std::vector<std::vector<Panel>>& panels_per_step,
                             const std::vector<double>& x_m, double dt, double rho, double g,
                             const StripOperatorOptions& options = {});

/// The same with StripOperatorOptions::use_mirror_symmetry on: when the sections are mirror-symmetric (all
/// hull types here), the symmetric half is solved and the force rows are spread back over all panels; the
/// vertical force is the same as the full solve's for any input (the antisymmetric part gives none) at about
/// half the kernel evaluations and 1/8 of the reduction. Falls back to the full solve otherwise.
StripKernel BuildStripKernelMirrorReduced(const std::vector<std::vector<Panel>>& panels_per_step,
                                          const std::vector<double>& x_m, double dt, double rho, double g,
                                          StripOperatorOptions options = {});

}  // namespace hullopt::sk
