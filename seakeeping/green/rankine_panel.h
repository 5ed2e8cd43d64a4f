#pragma once
// Closed-form influence of a constant-strength 2D Rankine source panel (theory notes §1.2): the potential
// (1/2π)∫ ln r ds and its gradient at a field point, per unit source density σ [m²/s per m]. With the
// potential of a point source of strength m taken as (m/2π) ln r, σ is the volume flux per unit panel length.
#include "seakeeping/green/panel.h"

namespace hullopt::sk {

/// Potential [m] and velocity components [-] per unit source density.
struct SourceInfluence {
  double phi = 0.0;  ///< (1/2π) ∫ ln r ds
  double vy = 0.0;   ///< ∂/∂y of phi
  double vz = 0.0;   ///< ∂/∂z of phi
};

/// Influence at (y, z) of the source panel. A field point on the panel itself (its midpoint, say) is taken on
/// the fluid side (the side the panel normal points to), so the normal self-velocity is +1/2.
SourceInfluence RankinePanelInfluence(const Panel& panel, double y, double z);

/// The same for the panel's mirror image above the free surface (z → −z), i.e. (1/2π)∫ ln r' ds.
SourceInfluence ImagePanelInfluence(const Panel& panel, double y, double z);

}  // namespace hullopt::sk
