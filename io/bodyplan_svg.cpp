#include "io/bodyplan_svg.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "io/atomic_file.h"
#include "io/input_error.h"

namespace hullopt::io {
namespace {
// At most this many sections per half of the drawing (more become an unreadable blur).
constexpr int kMaxSectionsPerHalf = 11;
}  // namespace

void WriteBodyPlanSvg(const std::string& path, const hull::HullForm& hull, const std::string& title) {
  // Extent: lateral from every body's centre +- its half-breadths, vertical from 0 to the highest point.
  double ymax = 0.0, zmax = hull.draught_m, zmin = 0.0;
  for (const auto& b : hull.bodies)
    for (const auto& s : b.stations)
      for (size_t k = 0; k < s.y_m.size(); ++k) {
        ymax = std::max(ymax, b.y_centre_m + s.y_m[k]);
        zmax = std::max(zmax, s.z_m[k]);
        zmin = std::min(zmin, s.z_m[k]);
      }
  const double W = 960, Hmax = 600, margin = 50, top = 70;
  const double scale = std::min((W - 2 * margin) / (2.0 * std::max(ymax, 1e-9)),
                                (Hmax - top - margin) / std::max(zmax - zmin, 1e-9));
  const double H = top + margin + scale * (zmax - zmin) + 10;  // as tall as the drawing needs
  const double cx = W / 2;
  auto X = [&](double y) { return cx + scale * y; };
  auto Z = [&](double z) { return H - margin - scale * (z - zmin); };
  const double x_mid = hull.bodies.empty() || hull.bodies[0].stations.empty()
                           ? 0.0
                           : 0.5 * (hull.bodies[0].stations.front().x_m + hull.bodies[0].stations.back().x_m);

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" viewBox=\"0 0 " << W << ' ' << H
      << "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << margin << "\" y=\"28\" font-size=\"18\">" << title << "</text>\n";
  svg << "<text x=\"" << margin
      << "\" y=\"50\" font-size=\"13\" fill=\"#1f4e9c\">aft sections (AP to midships)</text>\n";
  svg << "<text x=\"" << W - margin
      << "\" y=\"50\" font-size=\"13\" text-anchor=\"end\" fill=\"#b02a2a\">forward sections (midships to "
         "FP)</text>\n";
  // Centreline, baseline, design waterline.
  svg << "<line x1=\"" << cx << "\" y1=\"" << top - 8 << "\" x2=\"" << cx << "\" y2=\"" << H - margin + 10
      << "\" stroke=\"#888\" stroke-dasharray=\"8 4 2 4\"/>\n";
  svg << "<line x1=\"" << margin / 2 << "\" y1=\"" << Z(0) << "\" x2=\"" << W - margin / 2 << "\" y2=\""
      << Z(0) << "\" stroke=\"#888\"/>\n<text x=\"" << margin / 2 << "\" y=\"" << Z(0) + 16
      << "\" font-size=\"12\" fill=\"#555\">BL</text>\n";
  svg << "<line x1=\"" << margin / 2 << "\" y1=\"" << Z(hull.draught_m) << "\" x2=\"" << W - margin / 2
      << "\" y2=\"" << Z(hull.draught_m) << "\" stroke=\"#0a8a3a\" stroke-width=\"1.5\"/>\n<text x=\""
      << margin / 2 << "\" y=\"" << Z(hull.draught_m) - 5
      << "\" font-size=\"12\" fill=\"#0a8a3a\">DWL  T = " << hull.draught_m << " m</text>\n";

  for (const auto& body : hull.bodies) {
    const int n = int(body.stations.size());
    for (int half = 0; half < 2; ++half) {  // 0: aft on the left, 1: forward on the right
      std::vector<int> idx;
      for (int i = 0; i < n; ++i) {
        const double x = body.stations[i].x_m;
        if ((half == 0 && x <= x_mid + 1e-9) || (half == 1 && x >= x_mid - 1e-9)) idx.push_back(i);
      }
      const int step = std::max(1, int(std::ceil(double(idx.size()) / kMaxSectionsPerHalf)));
      const double sign = half == 0 ? -1.0 : 1.0;
      const char* colour = half == 0 ? "#1f4e9c" : "#b02a2a";
      for (size_t j = 0; j < idx.size(); ++j) {
        const bool mid = std::fabs(body.stations[idx[j]].x_m - x_mid) < 1e-9;
        if (j % step != 0 && j + 1 != idx.size() && !mid) continue;
        const auto& s = body.stations[idx[j]];
        if (s.y_m.empty()) continue;
        // Body instance on this half: the centreline body shows one side; an off-centre body both of its
        // sides.
        const double yc = sign * body.y_centre_m;
        const int sides = body.y_centre_m > 0.0 ? 2 : 1;
        for (int side = 0; side < sides; ++side) {
          const double dir = body.y_centre_m > 0.0 ? (side == 0 ? 1.0 : -1.0) : sign;
          svg << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << (mid ? 2.0 : 1.0)
              << "\" points=\"";
          for (size_t k = 0; k < s.y_m.size(); ++k)
            svg << X(yc + dir * s.y_m[k]) << ',' << Z(s.z_m[k]) << ' ';
          svg << "\"/>\n";
        }
      }
    }
  }
  svg << "</svg>\n";
  WriteFileAtomically(path, svg.str());
}

}  // namespace hullopt::io
