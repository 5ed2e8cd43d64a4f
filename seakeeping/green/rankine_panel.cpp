#include "seakeeping/green/rankine_panel.h"

#include <cmath>

namespace hullopt::sk {
namespace {

constexpr double kInv2Pi = 0.5 / M_PI;
constexpr double kInv4Pi = 0.25 / M_PI;

// Q(a) = a ln(a² + w²) − 2a + 2w atan(a/w): antiderivative of ln(a² + w²) in a (w → 0 limit a ln a² − 2a).
double Q(double a, double w) {
  const double r2 = a * a + w * w;
  const double log_term = r2 > 0.0 ? a * std::log(r2) : 0.0;
  const double atan_term = w != 0.0 ? 2.0 * w * std::atan(a / w) : 0.0;
  return log_term - 2.0 * a + atan_term;
}

SourceInfluence Influence(double y1, double z1, double y2, double z2, double y, double z, bool is_image,
                          double turn_rad = 0.0) {
  const double dy = y2 - y1, dz = z2 - z1;
  const double L = std::hypot(dy, dz);
  const double ty = dy / L, tz = dz / L;  // tangent
  const double ny = -tz, nz = ty;         // normal (into the fluid for a real panel)
  const double u = (y - y1) * ty + (z - z1) * tz;
  double w = (y - y1) * ny + (z - z1) * nz;
  // A point on the panel line is put on the normal side (+0), so the self term is +1/2 (not −1/2).
  const bool on_panel = !is_image && std::fabs(w) < 1e-13 * L && u > 0.0 && u < L;
  if (!is_image && std::fabs(w) < 1e-13 * L) w = +0.0;
  SourceInfluence out;
  out.phi = kInv4Pi * (Q(u, w) - Q(u - L, w));
  const double r1 = u * u + w * w, r2 = (u - L) * (u - L) + w * w;
  const double vu = (r1 > 0.0 && r2 > 0.0) ? kInv4Pi * std::log(r1 / r2) : 0.0;  // log singular at end points
  double vw = kInv2Pi * (std::atan2(w, u - L) - std::atan2(w, u));
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
