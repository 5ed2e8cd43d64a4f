#pragma once
// Closed-form influence of a constant-strength 2D Rankine source panel (docs/theory.md, 'Rankine panel
// integrals'): the potential (1/2π)∫ ln r ds and its gradient at a field point, per unit source density σ
// [m²/s per m]. With the potential of a point source of strength m taken as (m/2π) ln r, σ is the volume flux
// per unit panel length.
#include "seakeeping/green/panel.h"

namespace hullopt::sk {

/// Potential [m] and velocity components [-] per unit source density.
struct SourceInfluence {
  double phi = 0.0;  ///< (1/2π) ∫ ln r ds
  double vy = 0.0;   ///< ∂/∂y of phi
  double vz = 0.0;   ///< ∂/∂z of phi
};

/// Influence at (y, z) of the source panel. A field point on the panel itself (its midpoint, say) is taken on
/// the fluid side (the side the panel normal points to), so the normal self-velocity of the flat chord is
/// +1/2; to it is added the curvature term kCurvedPanelSelfFactor · turn_rad/(4π) along the normal (below).
SourceInfluence RankinePanelInfluence(const Panel& panel, double y, double z);

/// Why the curvature term: flat chords of a curved contour make the normal-velocity operator of a source
/// distribution consistent only to O(h). On the contour itself ∂/∂n ln r from a nearby source point is κ/2
/// (finite), so a curved piece of turning τ = κL adds τ/(4π) to its own normal velocity, which the chord
/// lacks; the kinks between neighbouring chords miss a further (2 ln 2 − 1) τ/(4π) in total. On a regular
/// N-gon the operator's Fourier eigenvalues all fall short of the circle's (1, ½, ½, …) by the same
/// 2 ln 2 · τ/(4π) + O(τ²), τ = 2π/N (tests/unit/test_rankine_panel.cpp), so the defect is a local diagonal
/// one and this factor on the self term restores O(h²): the heave added mass of a circle converges at second
/// order instead of first (docs/sections.md). A straight panel (τ = 0) is unchanged.
inline constexpr double kCurvedPanelSelfFactor = 1.3862943611198906;  // 2 ln 2

/// The same for the panel's mirror image above the free surface (z → −z), i.e. (1/2π)∫ ln r' ds.
SourceInfluence ImagePanelInfluence(const Panel& panel, double y, double z);

}  // namespace hullopt::sk
