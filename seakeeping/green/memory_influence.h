#pragma once
// Influence of one constant-strength source panel's memory over one time interval (docs/theory.md,
// 'Transient Green function: panel and time integrals'), per unit source density σ [m/s], with σ piecewise
// constant in time. The memory potential of the panel is
//   φ_mem(p, t) = −(1/2π) ∫_{τa}^{τb} σ ∫_panel G~(p, q, t − τ) ds dτ,
// so with lags s1 = t − τb, s2 = t − τa the time integral is exact through H⁽⁻¹⁾ = ∫_0^s H ds' (no aliasing
// of the fast Cauchy–Poisson oscillation near z = 0):
//   ∫_{τa}^{τb} G~ dτ = Re[H⁽⁻¹⁾(s2) − H⁽⁻¹⁾(s1)].
// Normal velocity: exact in space as well, from H⁽⁻¹⁾ at the panel's two end points (dζc/ds = −i e^{iα}):
//   ∫_panel ∫ ∂G~/∂n_p dτ ds = Re[(n_z + i n_y) i e^{−iα} (ΔH⁽⁻¹⁾(q2) − ΔH⁽⁻¹⁾(q1))].
// Potential: exact in space as well, through K with dK/dζc = H⁽⁻¹⁾ (transient_green.h):
//   ∫_panel H⁽⁻¹⁾ ds = i e^{−iα} (K(q2) − K(q1)).
// (Adaptive quadrature of the same integral is kept as the independent check.)
#include <complex>

#include "seakeeping/green/panel.h"

namespace hullopt::sk {

/// (1/2π) ∫_{s1}^{s2} ∫_panel ∂G~/∂n_p ds dτ [-] at field point (y, z) [m] with unit normal (ny, nz), lags
/// 0 <= s1 <= s2 [s]. Exact. The field point must not be a panel end point on z = 0.
double MemoryNormalVelocity(const Panel& source, double y, double z, double ny, double nz, double s1,
                            double s2, double g);

/// The same from H⁽⁻¹⁾ differences already evaluated at the panel's end points: dh1 = ΔH⁽⁻¹⁾ at (y1, z1),
/// dh2 at (y2, z2) (lets a caller share end points between adjacent panels).
double MemoryNormalVelocityFromEnds(const Panel& source, std::complex<double> dh1, std::complex<double> dh2,
                                    double ny, double nz);

/// ∫_panel Re H⁽⁻¹⁾(p, q, s) ds_q [m] at one lag s >= 0: the potential of the panel's memory, before the
/// difference over the interval. Exact: Re[i e^{−iα} (K(q2) − K(q1))] with K = TransientGreenSpaceTimeIntegral.
double MemoryPotentialLevel(const Panel& source, double y, double z, double s, double g);

/// The same from K already evaluated at the panel's end points (k1 at (y1, z1), k2 at (y2, z2)).
double MemoryPotentialLevelFromEnds(const Panel& source, std::complex<double> k1, std::complex<double> k2);

/// The same by adaptive Gauss–Kronrod quadrature of Re H⁽⁻¹⁾ along the panel, to ~rel_tol of
/// L·max(1, |H⁽⁻¹⁾|): the independent second method the closed form is tested against.
double MemoryPotentialLevelQuadrature(const Panel& source, double y, double z, double s, double g,
                                      double rel_tol = 1e-10);

/// (1/2π) ∫_{s1}^{s2} ∫_panel G~ ds dτ [m] = (level(s2) − level(s1))/2π.
double MemoryPotential(const Panel& source, double y, double z, double s1, double s2, double g);

}  // namespace hullopt::sk
