#pragma once
// Michell's (1898) thin-ship wave resistance of one or more bodies, with the wave interference between them.
//
// For a body with centre-plane half-breadth f(x, d) (d depth below the waterline) the amplitude function is
//   I(λ) = ∫∫ ∂f/∂x exp(-k0 λ² d) exp(i k0 λ x) dx dd,   k0 = g/U², λ = sec θ,
// θ the direction of the Kelvin wave component. Bodies at lateral positions y_j add with the phase of the
// wave component there, exp(i k0 y_j λ √(λ²-1)), so a mirror pair contributes 2 I_j cos(k0 y_j λ √(λ²-1))
// (Tuck & Lazauskas' multihull form), and
//   R_W = 4 ρ g² / (π U²) ∫_1^∞ |Σ_j A_j(λ)|² λ² / √(λ²-1) dλ.
//
// Numerics:
// - x: f linear between stations, so ∂f/∂x is constant on each interval and the oscillatory factor is
//   integrated exactly (Filon-type: Δx sinc(k0 λ Δx / 2) at the interval midpoint); no points per wave needed
//   in x.
// - depth: f linear between the depth nodes and exp(-k0 λ² d) integrated exactly against it.
// - the bow closes the body (f drops to 0 at the last station); the aft end is left OPEN: at a dry transom
//   the flow leaves the hull at the transom edge and the hollow behind it continues the body's breadth, so no
//   closing sink is placed there (the thin-ship treatment of a dry transom used by Michlet and by Doctors &
//   Day 1997; the missing hydrostatic pressure on the transom is a separate term, dry_transom.h).
// - λ: the substitution λ = cosh u removes the inverse-square-root singularity at λ = 1 (the integrand
//   becomes |A|² cosh² u); u is cut into intervals of at most 1/intervals_per_wave of the local oscillation
//   period of the integrand (phase rate k0 (X + 2 Y λ) dλ/du, X the x extent of all bodies and Y the largest
//   lateral body position) and of at most max_du, each integrated by 4-point Gauss–Legendre, up to
//   λ = lambda_max. The tail beyond is bounded by the integral over [lambda_max/2, lambda_max] (exact bound
//   for an integrand decaying like λ^-2, the slowest decay of a body closed by a step; open transoms and
//   pointed bows decay like λ^-4), returned as tail_bound_N.
#include <complex>
#include <string>
#include <vector>

#include "resistance/centre_plane.h"

namespace hullopt::res {

struct MichellOptions {
  int depth_points = 24;           ///< depth nodes of the centre-plane grid (>= 2)
  double intervals_per_wave = 2.0; ///< Gauss–Legendre intervals per oscillation period of the λ integrand
  double max_du = 0.02;            ///< largest interval in u (λ = cosh u), for the smooth part near λ = 1
  double lambda_max = 40.0;        ///< upper limit of λ = sec θ (θ_max = acos(1/λ_max), 88.6° at 40)
  /// Checks ranges; on failure writes "<name> = <value>: <rule>" and returns false.
  bool IsValid(std::string* error) const;
};

/// The amplitude function I(λ) of one body at wavenumber k0 = g/U² [1/m] and λ = sec θ >= 1 [m^2].
std::complex<double> AmplitudeFunction(const CentrePlaneGrid& body, double k0, double lambda);

struct WaveResistanceResult {
  double R_W_N = 0.0;        ///< [N] wave resistance of all bodies with their interference
  double tail_bound_N = 0.0; ///< [N] bound on the part beyond lambda_max (see above), not included in R_W_N
  int evaluations = 0;       ///< λ values at which the amplitude functions were evaluated
};

/// Wave resistance of the bodies at speed U_m_s > 0 in water of density rho and gravity g.
/// Throws std::invalid_argument for U <= 0, g <= 0, rho <= 0, no bodies or invalid options.
WaveResistanceResult MichellWaveResistance(const std::vector<CentrePlaneGrid>& bodies, double U_m_s,
                                           double g_m_s2, double rho_kg_m3, const MichellOptions& options);

}  // namespace hullopt::res
