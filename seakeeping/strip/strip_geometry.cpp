#include "seakeeping/strip/strip_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "parametric_hull/section_geometry.h"
#include "seakeeping/green/panel.h"

namespace hullopt::sk {

bool StripGeometryOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  if (sections < 2) {
    os << "sections = " << sections << ": must be >= 2";
  } else if (panels < 4 || panels % 2 != 0) {
    os << "panels = " << panels << ": must be even and >= 4";
  } else if (layout == StationLayout::kCellFaces && sections < 3) {
    os << "sections = " << sections << ": must be >= 3 with stations at the cell faces";
  } else if (!(spacing.end_spacing > 0.0 && spacing.end_spacing <= 1.0)) {
    os << "spacing.end_spacing = " << spacing.end_spacing << ": must lie in (0, 1] (a fraction of the uniform spacing)";
  } else if (!(spacing.grading > 0.0 && spacing.grading <= 10.0)) {
    os << "spacing.grading = " << spacing.grading << ": must lie in (0, 10]";
  } else if (body < -1) {
    os << "body = " << body << ": must be -1 (all bodies) or a body index";
  }
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

std::vector<Panel> StripSectionPanels(const hull::HullForm& hull, double x, double T,
                                      const StripGeometryOptions& options, std::vector<Panel>* contour) {
  std::vector<Panel> panels;
  if (contour) contour->clear();
  for (std::size_t bi = 0; bi < hull.bodies.size(); ++bi) {
    if (options.body >= 0 && options.body != static_cast<int>(bi)) continue;
    const hull::Demihull* b = &hull.bodies[bi];
    const hull::Station st = hull::InterpolateStation(*b, x);
    const auto wet = hull::WettedContour(st, T);
    if (wet.size() < 2) continue;  // dry here
    std::vector<std::array<double, 2>> half;
    for (const auto& p : wet) half.push_back({p[0], p[1] - T});
    double girth = 0.0;
    for (std::size_t i = 1; i < half.size(); ++i)
      girth += std::hypot(half[i][0] - half[i - 1][0], half[i][1] - half[i - 1][1]);
    if (girth <= 1e-9 * T) continue;  // keel exactly at the waterline: no wetted girth
    // A section of zero thickness (a knife-edge stem, met at the bow face of kCellFaces) is a plate in its
    // own plane: vertical motion does not disturb the water, and its panels would make a singular system.
    double half_breadth = 0.0;
    for (const auto& p : half) half_breadth = std::max(half_breadth, std::fabs(p[0]));
    if (half_breadth <= 1e-9 * T) continue;
    if (std::fabs(half.back()[1]) > 1e-9 * T) {
      std::ostringstream os;
      os << "body '" << b->role << "' at x = " << x
         << " m: the section does not reach the waterline (contour ends " << -half.back()[1]
         << " m below z = T = " << T << " m); extend the offsets above the draught";
      throw std::domain_error(os.str());
    }
    const bool mirrored = options.body < 0 && b->y_centre_m > 0.0;
    if (contour)  // the wetted polyline itself, both sides, and the mirror body's
      for (double side : mirrored ? std::vector<double>{1.0, -1.0} : std::vector<double>{1.0})
        for (std::size_t i = 1; i < half.size(); ++i)
          for (double sign : {1.0, -1.0}) {
            const double yc = side * b->y_centre_m;
            contour->push_back({yc + sign * half[i - 1][0], half[i - 1][1], yc + sign * half[i][0], half[i][1]});
          }
    try {
      auto ps = PanelSymmetricSection(half, options.panels, b->y_centre_m, options.spacing);
      panels.insert(panels.end(), ps.begin(), ps.end());
      if (mirrored) {  // the same panels shifted to the mirror demihull (y → y − 2 y_centre)
        for (auto& p : ps) p.y1 -= 2.0 * b->y_centre_m, p.y2 -= 2.0 * b->y_centre_m;
        panels.insert(panels.end(), ps.begin(), ps.end());
      }
    } catch (const std::invalid_argument& e) {
      std::ostringstream os;
      os << "body '" << b->role << "' at x = " << x << " m: " << e.what();
      throw std::domain_error(os.str());
    }
  }
  return panels;
}

StripKernel StripKernelGeometry(const hull::HullForm& hull, const StripGeometryOptions& options,
                                double speed_m_s, double rho_kg_m3, double g_m_s2) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument("strip geometry: " + err);
  if (!(speed_m_s > 0.0) || !std::isfinite(speed_m_s)) {
    std::ostringstream os;
    os << "strip geometry: ship speed U = " << speed_m_s << " m/s must be > 0";
    throw std::invalid_argument(os.str());
  }
  if (!(rho_kg_m3 > 0.0) || !(g_m_s2 > 0.0))
    throw std::invalid_argument("strip geometry: ρ and g must be > 0");
  if (options.body >= static_cast<int>(hull.bodies.size()))
    throw std::invalid_argument("strip geometry: body index " + std::to_string(options.body) +
                                " but the hull has " + std::to_string(hull.bodies.size()) + " bodies");
  if (!(hull.draught_m > 0.0)) throw std::invalid_argument("strip geometry: hull draught must be > 0");
  double x_aft = std::numeric_limits<double>::infinity(), x_fwd = -x_aft;
  for (const auto& body : hull.bodies) {  // the strip grid spans all bodies, so per-body kernels line up
    const auto* b = &body;
    if (b->stations.empty()) continue;
    x_aft = std::min(x_aft, b->stations.front().x_m);
    x_fwd = std::max(x_fwd, b->stations.back().x_m);
  }
  if (!(x_fwd > x_aft)) throw std::invalid_argument("strip geometry: the hull has no length (no stations)");

  StripKernel k;
  k.speed_m_s = speed_m_s;
  k.dx_m = (x_fwd - x_aft) / options.sections;
  k.dt_s = k.dx_m / speed_m_s;
  k.rho_kg_m3 = rho_kg_m3;
  k.g_m_s2 = g_m_s2;
  k.layout = options.layout;
  const double T = hull.draught_m;
  const int steps = StationCount(options.layout, options.sections);
  const double offset = options.layout == StationLayout::kCellFaces ? 0.0 : 0.5;
  for (int n = 0; n < steps; ++n) {
    // The last face is x_aft itself (not x_fwd − N·Δx, which rounding can put outside the hull).
    const double x = options.layout == StationLayout::kCellFaces && n == options.sections
                         ? x_aft
                         : x_fwd - (n + offset) * k.dx_m;
    std::vector<Panel> panels = StripSectionPanels(hull, x, T, options);
    k.x_m.push_back(x);
    k.panels.push_back(std::move(panels));
  }
  k.force.resize(steps);
  for (int n = 0; n < steps; ++n)
    for (int m = 0; m <= n; ++m) k.force[n].push_back(Eigen::RowVectorXd::Zero(k.panels[m].size()));
  return k;
}

StripKernel CombineIndependentKernels(const std::vector<StripKernel>& parts) {
  if (parts.empty()) throw std::invalid_argument("CombineIndependentKernels: no kernels");
  StripKernel out = parts.front();
  const int N = out.Steps();
  for (std::size_t p = 1; p < parts.size(); ++p) {
    const StripKernel& q = parts[p];
    if (q.Steps() != N || q.dx_m != out.dx_m || q.dt_s != out.dt_s || q.x_m != out.x_m ||
        q.layout != out.layout)
      throw std::invalid_argument(
          "CombineIndependentKernels: kernels differ in steps, dx, dt, stations or layout");
    // The combined section's force is the sum of both bodies' forces, each from its own panels only: the row
    // over the concatenated panels is the two rows side by side.
    for (int n = 0; n < N; ++n) {
      for (int m = 0; m <= n; ++m) {
        Eigen::RowVectorXd row(out.force[n][m].size() + q.force[n][m].size());
        row << out.force[n][m], q.force[n][m];
        out.force[n][m] = row;
      }
    }
    for (int n = 0; n < N; ++n)
      out.panels[n].insert(out.panels[n].end(), q.panels[n].begin(), q.panels[n].end());
    // Independent systems: the worse of the two per step.
    if (out.system_condition.size() == static_cast<std::size_t>(N) &&
        q.system_condition.size() == static_cast<std::size_t>(N)) {
      for (int n = 0; n < N; ++n) out.system_condition[n] = std::max(out.system_condition[n], q.system_condition[n]);
    } else {
      out.system_condition.clear();
    }
  }
  return out;
}

}  // namespace hullopt::sk
