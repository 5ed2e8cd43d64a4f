#include "io/report/bodyplan_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {
// At most this many sections per half of the drawing (more become an unreadable blur).
constexpr int kMaxSectionsPerHalf = 11;
// Layout [px]: a gutter on the left for the waterline and baseline labels (so they never meet a section),
// the right margin, room above the drawing for the headings and the row of station numbers, and room below
// for the scale bar.
constexpr double kBodyplanWidth = 960, kMaxHeight = 640, kLabelGutter = 130, kRightMargin = 40, kBottomMargin = 60;
constexpr double kStationFont = 9.5;
constexpr double kTop = 96;
constexpr double kCharWidth = 0.6;  // average glyph advance / font size (layout estimate)

std::string BodyplanNumber(double v, const char* format = "%.4g") {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// Station number on the 0 (AP) to 10 (FP) scale; one decimal unless whole.
std::string StationNumber(double x_m, double length_m) {
  const double s = length_m > 0.0 ? 10.0 * x_m / length_m : 0.0;
  return std::abs(s - std::round(s)) < 0.05 ? BodyplanNumber(std::round(s), "%.0f") : BodyplanNumber(s, "%.1f");
}

// A bar length of 1, 2 or 5 × 10^k metres close to a fifth of the drawing's width.
double ScaleBarMetres(double drawing_width_m) {
  const double target = drawing_width_m / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(target)));
  const double f = target / mag;
  return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * mag;
}

struct StationLabel {
  double x, y;  // anchor: the top of the section line [px]
  std::string text;
  double station;  // x / L × 10: the order of the labels
  int half;        // 0 aft (left), 1 forward (right)
  const char* colour;
};

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
  const double drawing_w = kBodyplanWidth - kLabelGutter - kRightMargin;
  const double scale = std::min(drawing_w / (2.0 * std::max(ymax, 1e-9)),
                                (kMaxHeight - kTop - kBottomMargin) / std::max(zmax - zmin, 1e-9));
  const double H = kTop + kBottomMargin + scale * (zmax - zmin) + 10;  // as tall as the drawing needs
  const double cx = kLabelGutter + drawing_w / 2;
  auto X = [&](double y) { return cx + scale * y; };
  auto Z = [&](double z) { return H - kBottomMargin - scale * (z - zmin); };
  const double x_mid = hull.bodies.empty() || hull.bodies[0].stations.empty()
                           ? 0.0
                           : 0.5 * (hull.bodies[0].stations.front().x_m + hull.bodies[0].stations.back().x_m);
  const double length_m = hull.length_m > 0.0 ? hull.length_m
                          : hull.bodies.empty() || hull.bodies[0].stations.empty()
                              ? 0.0
                              : hull.bodies[0].stations.back().x_m - hull.bodies[0].stations.front().x_m;

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kBodyplanWidth << "\" height=\"" << H
      << "\" viewBox=\"0 0 " << kBodyplanWidth << ' ' << H
      << "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << kLabelGutter << "\" y=\"28\" font-size=\"18\">" << title << "</text>\n";
  svg << "<text x=\"" << kLabelGutter
      << "\" y=\"50\" font-size=\"13\" fill=\"#1f4e9c\">aft sections (AP to midships)</text>\n";
  svg << "<text x=\"" << kBodyplanWidth - kRightMargin
      << "\" y=\"50\" font-size=\"13\" text-anchor=\"end\" fill=\"#b02a2a\">forward sections (midships to "
         "FP)</text>\n";
  svg << "<text x=\"" << cx << "\" y=\"50\" font-size=\"11\" text-anchor=\"middle\" fill=\"#555\">station "
         "numbers: 0 = AP, 10 = FP</text>\n";
  // Centreline, baseline, design waterline; their labels in the gutter left of every section.
  const double line_x0 = kLabelGutter - 12, line_x1 = kBodyplanWidth - kRightMargin / 2;
  svg << "<line x1=\"" << cx << "\" y1=\"" << kTop - 8 << "\" x2=\"" << cx << "\" y2=\"" << H - kBottomMargin + 10
      << "\" stroke=\"#888\" stroke-dasharray=\"8 4 2 4\"/>\n";
  svg << "<line x1=\"" << line_x0 << "\" y1=\"" << Z(0) << "\" x2=\"" << line_x1 << "\" y2=\"" << Z(0)
      << "\" stroke=\"#888\"/>\n<text class=\"bl-label\" x=\"" << line_x0 - 4 << "\" y=\"" << Z(0) + 4
      << "\" font-size=\"12\" text-anchor=\"end\" fill=\"#555\">BL</text>\n";
  svg << "<line x1=\"" << line_x0 << "\" y1=\"" << Z(hull.draught_m) << "\" x2=\"" << line_x1 << "\" y2=\""
      << Z(hull.draught_m) << "\" stroke=\"#0a8a3a\" stroke-width=\"1.5\"/>\n<text class=\"dwl-label\" x=\""
      << line_x0 - 4 << "\" y=\"" << Z(hull.draught_m) + 4
      << "\" font-size=\"12\" text-anchor=\"end\" fill=\"#0a8a3a\">DWL T = " << BodyplanNumber(hull.draught_m)
      << " m</text>\n";

  std::vector<StationLabel> labels;
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
          svg << "<polyline class=\"section\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\""
              << (mid ? 2.0 : 1.0) << "\" points=\"";
          for (size_t k = 0; k < s.y_m.size(); ++k)
            svg << X(yc + dir * s.y_m[k]) << ',' << Z(s.z_m[k]) << ' ';
          svg << "\"/>\n";
        }
        // The number at the top of the outboard side, of the first body only (the others repeat it).
        if (&body == &hull.bodies.front()) {
          size_t top = 0;
          for (size_t k = 1; k < s.z_m.size(); ++k)
            if (s.z_m[k] > s.z_m[top]) top = k;
          labels.push_back({X(yc + sign * s.y_m[top]), Z(s.z_m[top]), StationNumber(s.x_m, length_m),
                            length_m > 0.0 ? 10.0 * s.x_m / length_m : 0.0, half, colour});
        }
      }
    }
  }
  // Station numbers in a row above the drawing, each joined by a leader to the top of its section: where
  // sections end close together their numbers are spread apart (clusters of touching labels are centred on
  // their sections).
  // In station order, fullest (midships) outboard on each half: the order in which the section tops mostly
  // lie, and readable where they end together.
  std::sort(labels.begin(), labels.end(), [](const StationLabel& a, const StationLabel& b) {
    return a.half != b.half ? a.half < b.half : a.station > b.station;
  });
  struct Cluster {
    size_t first, last;  // labels [first, last]
    double width, offset_sum;  // total width with gaps; sum of (anchor − label centre offset in the cluster)
    double Start() const { return offset_sum / double(last - first + 1); }
  };
  const double gap = 4.0;
  auto width = [&](const StationLabel& l) { return kCharWidth * kStationFont * l.text.size() + gap; };
  std::vector<Cluster> clusters;
  for (size_t i = 0; i < labels.size(); ++i) {
    const double w = width(labels[i]);
    clusters.push_back({i, i, w, labels[i].x - w / 2});
    while (clusters.size() > 1) {
      Cluster& prev = clusters[clusters.size() - 2];
      const Cluster& cur = clusters.back();
      if (prev.Start() + prev.width <= cur.Start()) break;
      // Merge: every member's anchor minus its centre offset from the merged start, averaged.
      double offset_sum = prev.offset_sum, along = prev.width;
      for (size_t k = cur.first; k <= cur.last; ++k) {
        const double wk = width(labels[k]);
        offset_sum += labels[k].x - (along + wk / 2);
        along += wk;
      }
      prev = {prev.first, cur.last, along, offset_sum};
      clusters.pop_back();
    }
  }
  const double drawing_top = Z(zmax), label_y = drawing_top - 22;
  for (const auto& c : clusters) {
    double x = std::clamp(c.Start(), double(kLabelGutter), kBodyplanWidth - kRightMargin - c.width);
    for (size_t k = c.first; k <= c.last; ++k) {
      const auto& l = labels[k];
      const double w = width(l), centre = x + w / 2;
      svg << "<line class=\"station-leader\" x1=\"" << centre << "\" y1=\"" << label_y + 3 << "\" x2=\"" << l.x
          << "\" y2=\"" << l.y - 2 << "\" stroke=\"" << l.colour << "\" stroke-width=\"0.5\" stroke-opacity=\"0.6\"/>"
          << "<text class=\"station-number\" x=\"" << centre << "\" y=\"" << label_y << "\" font-size=\""
          << kStationFont << "\" text-anchor=\"middle\" fill=\"" << l.colour << "\">" << l.text << "</text>\n";
      x += w;
    }
  }
  // Scale bar under the drawing, right-aligned.
  const double bar_m = ScaleBarMetres(2.0 * ymax);
  const double bar_px = bar_m * scale, bar_x1 = kBodyplanWidth - kRightMargin, bar_x0 = bar_x1 - bar_px;
  const double bar_y = H - 22;
  svg << "<g class=\"scale-bar\"><line x1=\"" << bar_x0 << "\" y1=\"" << bar_y << "\" x2=\"" << bar_x1
      << "\" y2=\"" << bar_y << "\" stroke=\"#222\" stroke-width=\"2\"/>";
  for (double x : {bar_x0, 0.5 * (bar_x0 + bar_x1), bar_x1})
    svg << "<line x1=\"" << x << "\" y1=\"" << bar_y - 5 << "\" x2=\"" << x << "\" y2=\"" << bar_y + 5
        << "\" stroke=\"#222\" stroke-width=\"1.2\"/>";
  svg << "<text x=\"" << bar_x0 << "\" y=\"" << bar_y + 16 << "\" font-size=\"11\" text-anchor=\"middle\">0</text>"
      << "<text x=\"" << bar_x1 << "\" y=\"" << bar_y + 16 << "\" font-size=\"11\" text-anchor=\"middle\">"
      << BodyplanNumber(bar_m) << " m</text></g>\n";
  svg << "</svg>\n";
  WriteFileAtomically(path, svg.str());
}

}  // namespace hullopt::io
