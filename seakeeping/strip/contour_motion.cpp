#include "seakeeping/strip/contour_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hullopt::sk {
namespace {

// Size of a step's contour, for the tolerance of shared end points.
double ContourScale(const std::vector<Panel>& panels) {
  double s = 0.0;
  for (const Panel& p : panels)
    s = std::max({s, std::fabs(p.y1), std::fabs(p.y2), std::fabs(p.z1), std::fabs(p.z2)});
  return s;
}

// Offset along the unit normal (ny, nz) from (y, z) to the closest point of `panels`.
double NormalOffset(const std::vector<Panel>& panels, double y, double z, double ny, double nz) {
  double best = std::numeric_limits<double>::infinity(), offset = 0.0;
  for (const Panel& p : panels) {
    const double dy = p.y2 - p.y1, dz = p.z2 - p.z1;
    const double len2 = dy * dy + dz * dz;
    const double u = std::clamp(((y - p.y1) * dy + (z - p.z1) * dz) / len2, 0.0, 1.0);
    const double qy = p.y1 + u * dy - y, qz = p.z1 + u * dz - z;
    const double d2 = qy * qy + qz * qz;
    if (d2 < best) best = d2, offset = qy * ny + qz * nz;
  }
  return offset;
}

// The neighbour's waterline point matching `w` (same outward side, nearest in y); null if there is none.
const WaterlinePoint* Match(const std::vector<WaterlinePoint>& other, const WaterlinePoint& w) {
  const WaterlinePoint* best = nullptr;
  for (const WaterlinePoint& o : other)
    if (o.outward == w.outward && (!best || std::fabs(o.y_m - w.y_m) < std::fabs(best->y_m - w.y_m))) best = &o;
  return best;
}

}  // namespace

std::vector<WaterlinePoint> FindWaterlinePoints(const std::vector<Panel>& panels, double tol_m) {
  std::vector<WaterlinePoint> out;
  const int P = static_cast<int>(panels.size());
  auto shared = [&](int self, double y, double z) {
    for (int k = 0; k < P; ++k) {
      if (k == self) continue;
      const Panel& q = panels[k];
      if ((std::fabs(q.y1 - y) <= tol_m && std::fabs(q.z1 - z) <= tol_m) ||
          (std::fabs(q.y2 - y) <= tol_m && std::fabs(q.z2 - z) <= tol_m))
        return true;
    }
    return false;
  };
  for (int j = 0; j < P; ++j) {
    const Panel& p = panels[j];
    const double ny = p.Normal()[0];
    if (ny == 0.0) continue;  // a flat panel on the surface has no side to run to
    for (int e = 0; e < 2; ++e) {
      const double y = e ? p.y2 : p.y1, z = e ? p.z2 : p.z1;
      if (std::fabs(z) > tol_m || shared(j, y, z)) continue;
      WaterlinePoint w;
      w.panel = j, w.at_end = e == 1, w.y_m = y, w.outward = ny > 0.0 ? 1.0 : -1.0;
      out.push_back(w);
    }
  }
  return out;
}

ContourMotion StepContourMotion(const std::vector<std::vector<Panel>>& steps, int n, double dt,
                                const std::vector<std::vector<Panel>>* contours) {
  const int N = static_cast<int>(steps.size());
  if (n < 0 || n >= N) throw std::out_of_range("contour motion: step " + std::to_string(n) + " of " + std::to_string(N));
  if (!(dt > 0.0)) throw std::invalid_argument("contour motion: dt must be > 0, got " + std::to_string(dt));
  if (contours && contours->size() != steps.size())
    throw std::invalid_argument("contour motion: " + std::to_string(contours->size()) + " contours for " +
                                std::to_string(N) + " steps");
  const std::vector<Panel>& here = steps[n];
  ContourMotion m;
  m.normal_speed_m_s.assign(here.size(), 0.0);
  const double tol = 1e-9 * std::max(ContourScale(here), 1e-300);
  m.waterline = FindWaterlinePoints(here, tol);
  const bool before = n > 0 && !steps[n - 1].empty(), after = n + 1 < N && !steps[n + 1].empty();
  if (!before && !after) return m;
  // Central difference where both neighbours exist, else one-sided.
  const double span = (before && after ? 2.0 : 1.0) * dt;
  for (std::size_t j = 0; j < here.size(); ++j) {
    const Panel& p = here[j];
    const auto nrm = p.Normal();
    const double y = p.MidY(), z = p.MidZ();
    auto offset = [&](int k) { return NormalOffset(contours ? (*contours)[k] : steps[k], y, z, nrm[0], nrm[1]); };
    const double own = contours ? offset(n) : 0.0;  // the chord's own sagitta
    const double ahead = after ? offset(n + 1) : own;
    const double behind = before ? offset(n - 1) : own;
    m.normal_speed_m_s[j] = (ahead - behind) / span;
  }
  std::vector<WaterlinePoint> prev, next;
  if (before) prev = FindWaterlinePoints(steps[n - 1], 1e-9 * std::max(ContourScale(steps[n - 1]), 1e-300));
  if (after) next = FindWaterlinePoints(steps[n + 1], 1e-9 * std::max(ContourScale(steps[n + 1]), 1e-300));
  for (WaterlinePoint& w : m.waterline) {
    const WaterlinePoint* a = after ? Match(next, w) : nullptr;
    const WaterlinePoint* b = before ? Match(prev, w) : nullptr;
    if (!a && !b) continue;
    const double ya = a ? a->y_m : w.y_m, yb = b ? b->y_m : w.y_m;
    w.speed_m_s = w.outward * (ya - yb) / ((a && b ? 2.0 : 1.0) * dt);
  }
  return m;
}

}  // namespace hullopt::sk
