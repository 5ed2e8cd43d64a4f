#include "seakeeping/green/rankine_panel.h"

#include <cmath>

namespace hullopt::sk {
namespace {

constexpr double kRankineInv2Pi = 0.5 / M_PI;
constexpr double kInv4Pi = 0.25 / M_PI;

// Potential and velocity of a unit-density panel from its local coordinates (u along, w normal to it):
//   φ = (1/4π)[Q(u) − Q(u − L)],  Q(a) = a ln(a² + w²) − 2a + 2w atan(a/w)  (antiderivative of ln(a² + w²)),
//   v_u = (1/4π) ln(r1²/r2²),  v_w = θ/2π,
// θ = atan2(w, u − L) − atan2(w, u) the angle the panel subtends, which is also atan(u/w) − atan((u − L)/w) of
// the two Q terms: one atan2 of the arguments' product gives it, θ = atan2(wL, u(u − L) + w²), and two
// logarithms serve φ and v_u (no hypot: panel lengths are far from overflow).
SourceInfluence Influence(double y1, double z1, double y2, double z2, double y, double z, bool is_image,
                          double turn_rad = 0.0) {
  const double dy = y2 - y1, dz = z2 - z1;
  const double L = std::sqrt(dy * dy + dz * dz);
  const double ty = dy / L, tz = dz / L;  // tangent
  const double ny = -tz, nz = ty;         // normal (into the fluid for a real panel)
  const double u = (y - y1) * ty + (z - z1) * tz;
  double w = (y - y1) * ny + (z - z1) * nz;
  // A point on the panel line is put on the normal side (+0), so the self term is +1/2 (not −1/2).
  const bool on_panel = !is_image && std::fabs(w) < 1e-13 * L && u > 0.0 && u < L;
  if (!is_image && std::fabs(w) < 1e-13 * L) w = +0.0;
  const double r1 = u * u + w * w, r2 = (u - L) * (u - L) + w * w;
  const double ln1 = r1 > 0.0 ? std::log(r1) : 0.0, ln2 = r2 > 0.0 ? std::log(r2) : 0.0;
  const bool off_ends = r1 > 0.0 && r2 > 0.0;
  // At an end point the product form has no angle; there the difference of the two is the limit taken.
  const double theta = off_ends ? std::atan2(w * L, u * (u - L) + w * w) : std::atan2(w, u - L) - std::atan2(w, u);
  SourceInfluence out;
  out.phi = kInv4Pi * (u * ln1 - (u - L) * ln2 - 2.0 * L + 2.0 * w * theta);
  const double vu = off_ends ? kInv4Pi * (ln1 - ln2) : 0.0;  // log singular at end points
  double vw = kRankineInv2Pi * theta;
  if (on_panel) vw += kCurvedPanelSelfFactor * turn_rad * kInv4Pi;  // curvature term (header)
  out.vy = vu * ty + vw * ny;
  out.vz = vu * tz + vw * nz;
  return out;
}

}  // namespace

SourceInfluence RankinePanelInfluence(const Panel& p, double y, double z) {
  return Influence(p.y1, p.z1, p.y2, p.z2, y, z, false, p.turn_rad);
}

SourceInfluence ImagePanelInfluence(const Panel& p, double y, double z) {
  // Mirror image panel (z → −z); its orientation is reversed, which the potential and gradient do not feel.
  return Influence(p.y1, -p.z1, p.y2, -p.z2, y, z, true);
}

}  // namespace hullopt::sk
