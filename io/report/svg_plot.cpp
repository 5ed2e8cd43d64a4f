#include "io/report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Tableau-10: distinct, print- and colour-blind-tolerant; beyond 10 series the colours repeat dashed.
const char* const kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
constexpr int kPaletteSize = 10;
const char* const kFont = "DejaVu Sans, Helvetica, Arial, sans-serif";
constexpr double kTickFont = 12.0;
constexpr double kLabelFont = 12.5;
constexpr double kTitleFont = 13.5;
constexpr double kLegendFont = 12.0;
constexpr double kFigureTitleFont = 16.0;
constexpr double kFootnoteFont = 11.0;
constexpr double kFootnoteLine = 14.0;  // [px] line spacing of a footnote over several lines
// Average advance of a DejaVu Sans glyph as a fraction of the font size (for layout estimates only).
constexpr double kCharWidth = 0.58;

// Panel interior margins [px] within its cell.
constexpr double kMarginLeft = 72.0, kMarginRight = 18.0, kMarginTop = 30.0, kMarginBottom = 50.0;

std::string Escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

int CodePoints(const std::string& s) {
  int n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

double TextWidth(const std::string& s, double font) { return CodePoints(s) * kCharWidth * font; }

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

// One axis: maps data values to pixels and knows its ticks.
struct Axis {
  AxisScale scale = AxisScale::kLinear;
  double lo = 0.0, hi = 1.0;  // data range shown
  double p0 = 0.0, p1 = 1.0;  // pixel positions of lo and hi
  struct Tick {
    double value;
    std::string label;  // empty = minor (grid only)
  };
  std::vector<Tick> ticks;

  double T(double v) const { return scale == AxisScale::kLog ? std::log10(v) : v; }
  double Map(double v) const { return p0 + (T(v) - T(lo)) / (T(hi) - T(lo)) * (p1 - p0); }
  bool Usable(double v) const { return std::isfinite(v) && (scale == AxisScale::kLinear || v > 0.0); }
};

std::string LogLabel(int k) {
  if (k >= -3 && k <= 4) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", std::pow(10.0, k));
    return buf;
  }
  // "10" with superscript exponent; the tspan is emitted verbatim (already escaped).
  return "10<tspan dy=\"-5\" font-size=\"8\">" + std::string(k < 0 ? "−" : "") + std::to_string(std::abs(k)) +
         "</tspan>";
}

void BuildAxis(Axis* axis, AxisScale scale, double data_lo, double data_hi, double fixed_lo, double fixed_hi,
               bool include_zero, double pad) {
  axis->scale = scale;
  axis->ticks.clear();
  if (scale == AxisScale::kLinear) {
    if (pad > 0.0 && std::isfinite(data_lo) && std::isfinite(data_hi)) {
      const double span = data_hi > data_lo ? data_hi - data_lo : std::max(std::abs(data_lo), 1.0);
      const bool was_non_negative = data_lo >= 0.0;
      data_lo -= pad * span;
      data_hi += pad * span;
      if (was_non_negative && data_lo < 0.0) data_lo = 0.0;  // do not invent negative values
    }
    double lo = std::isfinite(fixed_lo) ? fixed_lo : data_lo;
    double hi = std::isfinite(fixed_hi) ? fixed_hi : data_hi;
    if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
    if (include_zero && !std::isfinite(fixed_lo)) lo = std::min(lo, 0.0);
    if (include_zero && !std::isfinite(fixed_hi)) hi = std::max(hi, 0.0);
    if (hi <= lo) {
      const double widen = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
      lo -= widen, hi += widen;
    }
    auto ticks = NiceLinearTicks(lo, hi);
    const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : hi - lo;
    axis->lo = std::isfinite(fixed_lo) ? fixed_lo : ticks.front();
    axis->hi = std::isfinite(fixed_hi) ? fixed_hi : ticks.back();
    const double eps = 1e-9 * (axis->hi - axis->lo);
    for (double t : ticks)
      if (t >= axis->lo - eps && t <= axis->hi + eps) axis->ticks.push_back({t, FormatTick(t, step)});
    return;
  }
  double lo = std::isfinite(fixed_lo) && fixed_lo > 0 ? fixed_lo : data_lo;
  double hi = std::isfinite(fixed_hi) && fixed_hi > 0 ? fixed_hi : data_hi;
  if (!(lo > 0.0) || !(hi > 0.0) || !std::isfinite(lo) || !std::isfinite(hi)) lo = 1.0, hi = 10.0;
  if (hi <= lo) lo /= 2.0, hi *= 2.0;
  int k0 = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  int k1 = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (k1 == k0) ++k1;
  axis->lo = std::isfinite(fixed_lo) && fixed_lo > 0 ? fixed_lo : std::pow(10.0, k0);
  axis->hi = std::isfinite(fixed_hi) && fixed_hi > 0 ? fixed_hi : std::pow(10.0, k1);
  const bool few_decades = (k1 - k0) <= 2;
  const double rel = 1e-9;
  for (int k = k0; k <= k1; ++k) {
    for (int m = 1; m <= 9; ++m) {
      const double v = m * std::pow(10.0, k);
      if (v < axis->lo * (1 - rel) || v > axis->hi * (1 + rel)) continue;
      std::string label;
      if (m == 1) {
        label = LogLabel(k);
      } else if (few_decades && (m == 2 || m == 5) && k >= -3 && k <= 4) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", v);
        label = buf;
      }
      axis->ticks.push_back({v, label});
    }
  }
}

void ExtendRange(double v, double* lo, double* hi) {
  if (!std::isfinite(*lo) || v < *lo) *lo = v;
  if (!std::isfinite(*hi) || v > *hi) *hi = v;
}

struct Style {
  std::string color;
  std::string dash;
};

Style SeriesStyle(const PlotSeries& s, int index) {
  Style st;
  st.color = s.color.empty() ? kPalette[index % kPaletteSize] : s.color;
  st.dash = s.dash.empty() && s.color.empty() && index >= kPaletteSize ? "7 3" : s.dash;
  return st;
}

std::string Marker(MarkerShape shape, double x, double y, double size, const std::string& color,
                   bool hollow) {
  const double r = size / 2.0;
  const std::string fill = hollow ? "#ffffff" : color;
  const std::string paint = " fill=\"" + fill + "\" stroke=\"" + color + "\" stroke-width=\"1.3\"";
  std::ostringstream o;
  switch (shape) {
    case MarkerShape::kCircle:
      o << "<circle cx=\"" << Num(x) << "\" cy=\"" << Num(y) << "\" r=\"" << Num(r) << "\"" << paint << "/>";
      break;
    case MarkerShape::kSquare:
      o << "<rect x=\"" << Num(x - r * 0.9) << "\" y=\"" << Num(y - r * 0.9) << "\" width=\"" << Num(1.8 * r)
        << "\" height=\"" << Num(1.8 * r) << "\"" << paint << "/>";
      break;
    case MarkerShape::kTriangle:
      o << "<polygon points=\"" << Num(x) << "," << Num(y - 1.1 * r) << " " << Num(x - r) << ","
        << Num(y + 0.75 * r) << " " << Num(x + r) << "," << Num(y + 0.75 * r) << "\"" << paint << "/>";
      break;
    case MarkerShape::kDiamond:
      o << "<polygon points=\"" << Num(x) << "," << Num(y - 1.15 * r) << " " << Num(x + 1.0 * r) << ","
        << Num(y) << " " << Num(x) << "," << Num(y + 1.15 * r) << " " << Num(x - 1.0 * r) << "," << Num(y)
        << "\"" << paint << "/>";
      break;
    case MarkerShape::kCross:
      o << "<path d=\"M" << Num(x - r) << " " << Num(y - r) << "L" << Num(x + r) << " " << Num(y + r) << "M"
        << Num(x - r) << " " << Num(y + r) << "L" << Num(x + r) << " " << Num(y - r) << "\" stroke=\""
        << color << "\" stroke-width=\"1.8\" fill=\"none\"/>";
      break;
    case MarkerShape::kPlus:
      o << "<path d=\"M" << Num(x - r) << " " << Num(y) << "L" << Num(x + r) << " " << Num(y) << "M" << Num(x)
        << " " << Num(y - r) << "L" << Num(x) << " " << Num(y + r) << "\" stroke=\"" << color
        << "\" stroke-width=\"1.8\" fill=\"none\"/>";
      break;
  }
  return o.str();
}

struct LegendEntry {
  std::string label;
  bool band = false;
  const PlotSeries* series = nullptr;
  Style style;
  std::string band_color;
};

double LegendWidth(const std::vector<LegendEntry>& entries) {
  double w = 0.0;
  for (const auto& e : entries) w = std::max(w, TextWidth(e.label, kLegendFont));
  return w + 46.0;
}
constexpr double kLegendRow = 16.0;
// [px] free space a legend inside the plot area keeps around it from any drawn point or line.
constexpr double kLegendClearance = 4.0;
double LegendHeight(const std::vector<LegendEntry>& entries) { return entries.size() * kLegendRow + 8.0; }

// A rectangle in pixels.
struct Box {
  double x0, y0, x1, y1;
  bool Contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
  bool Intersects(const Box& b) const { return x0 <= b.x1 && b.x0 <= x1 && y0 <= b.y1 && b.y0 <= y1; }
};

struct Point {
  double x, y;
};

// Liang–Barsky: cuts the segment a–b to the box; false when no part of it lies inside.
bool ClipSegment(const Box& box, Point* a, Point* b) {
  const double dx = b->x - a->x, dy = b->y - a->y;
  double t0 = 0.0, t1 = 1.0;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a->x - box.x0, box.x1 - a->x, a->y - box.y0, box.y1 - a->y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) {
      if (t > t1) return false;
      t0 = std::max(t0, t);
    } else {
      if (t < t0) return false;
      t1 = std::min(t1, t);
    }
  }
  const Point a0 = *a;
  *a = {a0.x + t0 * dx, a0.y + t0 * dy};
  *b = {a0.x + t1 * dx, a0.y + t1 * dy};
  return true;
}

// The line of a series in pixels, as runs of joined points cut to the plot area: a run ends at a skipped point,
// where the line leaves the area and at a wrap of a periodic series (drawn out to the edge and in again).
std::vector<std::vector<Point>> LineRuns(const PlotSeries& s, const Axis& ax, const Axis& ay, const Box& area) {
  std::vector<std::vector<Point>> runs;
  const size_t n = std::min(s.x.size(), s.y.size());
  const bool wraps = s.wrap_period > 0.0 && ay.scale == AxisScale::kLinear;
  bool open = false;  // the last run ends where the next segment may continue
  auto add = [&](double xa, double ya, double xb, double yb) {
    Point a{ax.Map(xa), ay.Map(ya)}, b{ax.Map(xb), ay.Map(yb)};
    if (!ClipSegment(area, &a, &b)) {
      open = false;
      return;
    }
    if (open && !runs.empty() && std::abs(runs.back().back().x - a.x) < 1e-6 &&
        std::abs(runs.back().back().y - a.y) < 1e-6) {
      runs.back().push_back(b);
    } else {
      runs.push_back({a, b});
    }
    // Continue only if the segment ended at its own end point (not cut at the edge).
    open = std::abs(b.x - ax.Map(xb)) < 1e-6 && std::abs(b.y - ay.Map(yb)) < 1e-6;
  };
  bool have_prev = false;
  double px = 0, py = 0;
  for (size_t k = 0; k < n; ++k) {
    if (!ax.Usable(s.x[k]) || !ay.Usable(s.y[k])) {
      have_prev = false, open = false;
      continue;
    }
    const double x = s.x[k], y = s.y[k];
    if (have_prev) {
      const double turns = wraps ? std::round((y - py) / s.wrap_period) : 0.0;
      if (turns != 0.0) {
        add(px, py, x, y - turns * s.wrap_period);  // out through one edge ...
        open = false;
        add(px, py + turns * s.wrap_period, x, y);  // ... and in through the other
      } else {
        add(px, py, x, y);
      }
    }
    px = x, py = y, have_prev = true;
  }
  return runs;
}

// Markers drawn: only points inside the axis ranges.
std::vector<std::pair<size_t, Point>> MarkerPoints(const PlotSeries& s, const Axis& ax, const Axis& ay,
                                                   const Box& area) {
  std::vector<std::pair<size_t, Point>> pts;
  const size_t n = std::min(s.x.size(), s.y.size());
  const double tol = 0.01;  // [px] round-off of the edge ticks
  const Box grown{area.x0 - tol, area.y0 - tol, area.x1 + tol, area.y1 + tol};
  for (size_t k = 0; k < n; ++k) {
    if (!ax.Usable(s.x[k]) || !ay.Usable(s.y[k])) continue;
    const Point p{ax.Map(s.x[k]), ay.Map(s.y[k])};
    if (grown.Contains(p.x, p.y)) pts.push_back({k, p});
  }
  return pts;
}

// A point label: text (10 px font) beside its marker, above-right unless that leaves the plot area or
// overlaps a label placed before, then below-right, above-left, below-left.
struct PointLabel {
  double x, y;  // baseline start
  std::string text;
  Box box;
};

std::vector<PointLabel> PlacePointLabels(const PlotPanel& panel, const Axis& ax, const Axis& ay, const Box& area) {
  std::vector<PointLabel> placed;
  for (const auto& s : panel.series)
    for (const auto& [k, p] : MarkerPoints(s, ax, ay, area)) {
      if (k >= s.point_labels.size() || s.point_labels[k].empty()) continue;
      const std::string& text = s.point_labels[k];
      const double w = TextWidth(text, 10.0);
      const Point offsets[] = {{6.0, -6.0}, {6.0, 14.0}, {-6.0 - w, -6.0}, {-6.0 - w, 14.0}};
      PointLabel best{};
      for (int c = 0; c < 4; ++c) {
        const double bx = p.x + offsets[c].x, by = p.y + offsets[c].y;
        PointLabel l{bx, by, text, {bx, by - 10.0, bx + w, by + 2.0}};
        if (c == 0) best = l;
        // Inside the plot area (widened as the markers' clip path), clear of the labels placed before.
        bool free = l.box.x0 >= area.x0 - 6.0 && l.box.x1 <= area.x1 + 6.0 && l.box.y0 >= area.y0 - 6.0 &&
                    l.box.y1 <= area.y1 + 6.0;
        for (const auto& q : placed) free = free && !q.box.Intersects(l.box);
        if (free) {
          best = l;
          break;
        }
      }
      placed.push_back(best);
    }
  return placed;
}

// How many drawn items (line segments, markers, point labels) of the panel a box covers.
int CountCovered(const PlotPanel& panel, const Axis& ax, const Axis& ay, const Box& area, const Box& box) {
  int count = 0;
  for (const auto& s : panel.series) {
    if (s.line)
      for (const auto& run : LineRuns(s, ax, ay, area))
        for (size_t i = 1; i < run.size(); ++i) {
          Point a = run[i - 1], b = run[i];
          count += ClipSegment(box, &a, &b);
        }
    for (const auto& kp : MarkerPoints(s, ax, ay, area)) {
      const Point& p = kp.second;
      const double r = s.markers ? 0.5 * s.marker_size_px : 0.0;
      if (s.markers && box.Intersects({p.x - r, p.y - r, p.x + r, p.y + r})) ++count;
    }
  }
  for (const auto& l : PlacePointLabels(panel, ax, ay, area)) count += box.Intersects(l.box);
  return count;
}

// Where a panel's plot area, axes and legend go within its cell.
struct PanelLayout {
  double left = 0, top = 0, right = 0, bottom = 0;
  Axis ax, ay;
  std::vector<LegendEntry> legend;
  bool legend_shown = false, legend_outside = false;
  double legend_x = 0, legend_y = 0, legend_w = 0, legend_h = 0;
  Box Area() const { return {left, top, right, bottom}; }
};

// outside: the legend goes outside whatever the data (the figure's column was widened for it).
PanelLayout LayoutPanel(const PlotPanel& panel, double cx, double cy, double w, double h, bool outside = false) {
  PanelLayout L;
  // Data ranges.
  const bool xlog = panel.x_scale == AxisScale::kLog, ylog = panel.y_scale == AxisScale::kLog;
  double xlo = kNaN, xhi = kNaN, ylo = kNaN, yhi = kNaN;
  for (const auto& s : panel.series) {
    const size_t n = std::min(s.x.size(), s.y.size());
    for (size_t i = 0; i < n; ++i) {
      const double x = s.x[i], y = s.y[i];
      if (!std::isfinite(x) || !std::isfinite(y) || (xlog && x <= 0) || (ylog && y <= 0)) continue;
      ExtendRange(x, &xlo, &xhi);
      ExtendRange(y, &ylo, &yhi);
    }
  }
  for (const auto& b : panel.bands) {
    if (std::isfinite(b.y_low) && (!ylog || b.y_low > 0)) ExtendRange(b.y_low, &ylo, &yhi);
    if (std::isfinite(b.y_high) && (!ylog || b.y_high > 0)) ExtendRange(b.y_high, &ylo, &yhi);
  }
  for (size_t i = 0; i < panel.series.size(); ++i) {
    const auto& s = panel.series[i];
    if (!s.label.empty()) L.legend.push_back({s.label, false, &s, SeriesStyle(s, static_cast<int>(i)), ""});
  }
  for (const auto& b : panel.bands)
    if (!b.label.empty()) L.legend.push_back({b.label, true, nullptr, {}, b.color});
  L.legend_shown = !L.legend.empty() && panel.legend != LegendPlace::kNone;
  L.legend_w = LegendWidth(L.legend), L.legend_h = LegendHeight(L.legend);

  L.left = cx + kMarginLeft, L.top = cy + kMarginTop, L.bottom = cy + h - kMarginBottom;
  L.right = cx + w - kMarginRight;
  auto& ax = L.ax;
  auto& ay = L.ay;
  BuildAxis(&ax, panel.x_scale, xlo, xhi, panel.x_min, panel.x_max, false, panel.pad_fraction);
  if (!panel.x_ticks.empty()) {
    ax.ticks.clear();
    for (size_t i = 0; i < panel.x_ticks.size(); ++i) {
      const double t = panel.x_ticks[i];
      if (!ax.Usable(t) || t < std::min(ax.lo, ax.hi) || t > std::max(ax.lo, ax.hi)) continue;
      char buf[32];
      std::snprintf(buf, sizeof buf, "%g", t);
      ax.ticks.push_back({t, i < panel.x_tick_labels.size() ? Escape(panel.x_tick_labels[i]) : buf});
    }
  }
  BuildAxis(&ay, panel.y_scale, ylo, yhi, panel.y_min, panel.y_max, panel.y_include_zero, panel.pad_fraction);
  ax.p0 = L.left, ax.p1 = L.right;
  ay.p0 = L.bottom, ay.p1 = L.top;
  if (!L.legend_shown) return L;

  // Inside the plot area where it covers nothing, else outside on the right.
  L.legend_outside = outside || panel.legend == LegendPlace::kOutsideRight;
  if (!L.legend_outside) {
    const double inset = 8.0, lw = L.legend_w, lh = L.legend_h;
    struct Candidate {
      LegendPlace place;
      double x, y;
    };
    std::vector<Candidate> candidates = {
        {LegendPlace::kTopRight, L.right - inset - lw, L.top + inset},
        {LegendPlace::kTopLeft, L.left + inset, L.top + inset},
        {LegendPlace::kBottomRight, L.right - inset - lw, L.bottom - inset - lh},
        {LegendPlace::kBottomLeft, L.left + inset, L.bottom - inset - lh},
        {LegendPlace::kAuto, 0.5 * (L.left + L.right - lw), L.top + inset},
        {LegendPlace::kAuto, 0.5 * (L.left + L.right - lw), L.bottom - inset - lh}};
    std::stable_partition(candidates.begin(), candidates.end(),
                          [&](const Candidate& c) { return c.place == panel.legend; });
    bool found = false;
    for (const auto& c : candidates) {
      const Box box{c.x, c.y, c.x + lw, c.y + lh};
      if (c.x < L.left || c.y < L.top || box.x1 > L.right || box.y1 > L.bottom) continue;  // does not fit
      const Box clear{box.x0 - kLegendClearance, box.y0 - kLegendClearance, box.x1 + kLegendClearance,
                      box.y1 + kLegendClearance};
      if (CountCovered(panel, ax, ay, L.Area(), clear) == 0) {
        L.legend_x = c.x, L.legend_y = c.y, found = true;
        break;
      }
    }
    L.legend_outside = !found;
  }
  if (L.legend_outside) {
    L.right -= L.legend_w + 10.0;
    ax.p1 = L.right;
    L.legend_x = L.right + 10.0, L.legend_y = L.top;
  }
  return L;
}

void DrawLegendSample(std::ostringstream& o, const LegendEntry& e, double x, double y) {
  if (e.band) {
    o << "<rect x=\"" << Num(x) << "\" y=\"" << Num(y - 5) << "\" width=\"26\" height=\"10\" fill=\""
      << e.band_color << "\" fill-opacity=\"0.25\" stroke=\"" << e.band_color
      << "\" stroke-opacity=\"0.6\"/>";
    return;
  }
  const PlotSeries& s = *e.series;
  if (s.line) {
    o << "<line x1=\"" << Num(x) << "\" y1=\"" << Num(y) << "\" x2=\"" << Num(x + 26) << "\" y2=\"" << Num(y)
      << "\" stroke=\"" << e.style.color << "\" stroke-width=\"" << Num(s.line_width_px) << "\"";
    if (!e.style.dash.empty()) o << " stroke-dasharray=\"" << e.style.dash << "\"";
    o << "/>";
  }
  if (s.markers) o << Marker(s.marker, x + 13, y, s.marker_size_px, e.style.color, s.hollow_markers);
}


void DrawPanel(std::ostringstream& o, const PlotPanel& panel, int panel_index, double cx, double cy, double w,
               double h, bool legend_outside) {
  const PanelLayout L = LayoutPanel(panel, cx, cy, w, h, legend_outside);
  const double left = L.left, top = L.top, right = L.right, bottom = L.bottom;
  const Axis& ax = L.ax;
  const Axis& ay = L.ay;
  const Box area = L.Area();

  o << "<g class=\"panel\">\n";
  // Title.
  if (!panel.title.empty())
    o << "<text x=\"" << Num(0.5 * (left + right)) << "\" y=\"" << Num(cy + 20) << "\" font-size=\""
      << kTitleFont << "\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#222\">" << Escape(panel.title)
      << "</text>\n";
  // Plot area background, grid, ticks.
  o << "<rect x=\"" << Num(left) << "\" y=\"" << Num(top) << "\" width=\"" << Num(right - left)
    << "\" height=\"" << Num(bottom - top) << "\" fill=\"#ffffff\"/>\n";
  for (const auto& t : ax.ticks) {
    const double px = ax.Map(t.value);
    const bool major = !t.label.empty();
    o << "<line x1=\"" << Num(px) << "\" y1=\"" << Num(top) << "\" x2=\"" << Num(px) << "\" y2=\""
      << Num(bottom) << "\" stroke=\"" << (major ? "#e3e3e3" : "#f2f2f2") << "\" stroke-width=\"1\"/>";
    o << "<line x1=\"" << Num(px) << "\" y1=\"" << Num(bottom) << "\" x2=\"" << Num(px) << "\" y2=\""
      << Num(bottom + (major ? 5 : 3)) << "\" stroke=\"#555\" stroke-width=\"1\"/>";
    if (major)
      o << "<text x=\"" << Num(px) << "\" y=\"" << Num(bottom + 18) << "\" font-size=\"" << kTickFont
        << "\" text-anchor=\"middle\" fill=\"#333\">" << t.label << "</text>";
    o << "\n";
  }
  for (const auto& t : ay.ticks) {
    const double py = ay.Map(t.value);
    const bool major = !t.label.empty();
    o << "<line x1=\"" << Num(left) << "\" y1=\"" << Num(py) << "\" x2=\"" << Num(right) << "\" y2=\""
      << Num(py) << "\" stroke=\"" << (major ? "#e3e3e3" : "#f2f2f2") << "\" stroke-width=\"1\"/>";
    o << "<line x1=\"" << Num(left - (major ? 5 : 3)) << "\" y1=\"" << Num(py) << "\" x2=\"" << Num(left)
      << "\" y2=\"" << Num(py) << "\" stroke=\"#555\" stroke-width=\"1\"/>";
    if (major)
      o << "<text x=\"" << Num(left - 8) << "\" y=\"" << Num(py + 4) << "\" font-size=\"" << kTickFont
        << "\" text-anchor=\"end\" fill=\"#333\">" << t.label << "</text>";
    o << "\n";
  }
  // Axis labels.
  if (!panel.x_label.empty())
    o << "<text x=\"" << Num(0.5 * (left + right)) << "\" y=\"" << Num(bottom + 38) << "\" font-size=\""
      << kLabelFont << "\" text-anchor=\"middle\" fill=\"#222\">" << Escape(panel.x_label) << "</text>\n";
  if (!panel.y_label.empty()) {
    const double yx = cx + 18, yy = 0.5 * (top + bottom);
    o << "<text x=\"" << Num(yx) << "\" y=\"" << Num(yy) << "\" font-size=\"" << kLabelFont
      << "\" text-anchor=\"middle\" fill=\"#222\" transform=\"rotate(-90 " << Num(yx) << " " << Num(yy)
      << ")\">" << Escape(panel.y_label) << "</text>\n";
  }

  // Data. Lines are cut to the plot area and clipped to it; markers (only those inside the ranges) are clipped
  // to the area widened by half a marker so that edge markers stay whole.
  const std::string clip = "clip" + std::to_string(panel_index);
  o << "<clipPath id=\"" << clip << "\"><rect x=\"" << Num(left) << "\" y=\"" << Num(top) << "\" width=\""
    << Num(right - left) << "\" height=\"" << Num(bottom - top) << "\"/></clipPath>\n";
  o << "<clipPath id=\"" << clip << "m\"><rect x=\"" << Num(left - 6) << "\" y=\"" << Num(top - 6)
    << "\" width=\"" << Num(right - left + 12) << "\" height=\"" << Num(bottom - top + 12)
    << "\"/></clipPath>\n";
  o << "<g class=\"data\">\n<g clip-path=\"url(#" << clip << ")\">\n";
  for (const auto& b : panel.bands) {
    if (!ay.Usable(b.y_low) || !ay.Usable(b.y_high)) continue;
    const double y0 = ay.Map(std::max(b.y_low, ay.lo)), y1 = ay.Map(std::min(b.y_high, ay.hi));
    o << "<rect x=\"" << Num(left) << "\" y=\"" << Num(std::min(y0, y1)) << "\" width=\"" << Num(right - left)
      << "\" height=\"" << Num(std::abs(y0 - y1)) << "\" fill=\"" << b.color
      << "\" fill-opacity=\"0.18\"/>\n";
  }
  for (size_t i = 0; i < panel.series.size(); ++i) {
    const auto& s = panel.series[i];
    if (!s.line) continue;
    const Style st = SeriesStyle(s, static_cast<int>(i));
    std::ostringstream d;
    for (const auto& run : LineRuns(s, ax, ay, area))
      for (size_t k = 0; k < run.size(); ++k) d << (k ? "L" : "M") << Num(run[k].x) << " " << Num(run[k].y);
    if (d.str().empty()) continue;
    o << "<path d=\"" << d.str() << "\" fill=\"none\" stroke=\"" << st.color << "\" stroke-width=\""
      << Num(s.line_width_px) << "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"";
    if (!st.dash.empty()) o << " stroke-dasharray=\"" << st.dash << "\"";
    o << "/>\n";
  }
  o << "</g>\n<g clip-path=\"url(#" << clip << "m)\">\n";
  for (size_t i = 0; i < panel.series.size(); ++i) {
    const auto& s = panel.series[i];
    const Style st = SeriesStyle(s, static_cast<int>(i));
    if (s.markers)
      for (const auto& kp : MarkerPoints(s, ax, ay, area))
        o << Marker(s.marker, kp.second.x, kp.second.y, s.marker_size_px, st.color, s.hollow_markers);
    o << "\n";
  }
  for (const auto& l : PlacePointLabels(panel, ax, ay, area))
    o << "<text class=\"point-label\" x=\"" << Num(l.x) << "\" y=\"" << Num(l.y)
      << "\" font-size=\"10\" fill=\"#333\">" << Escape(l.text) << "</text>";
  o << "\n";
  o << "</g>\n</g>\n";
  // Frame over the data.
  o << "<rect class=\"frame\" x=\"" << Num(left) << "\" y=\"" << Num(top) << "\" width=\"" << Num(right - left)
    << "\" height=\"" << Num(bottom - top) << "\" fill=\"none\" stroke=\"#555\" stroke-width=\"1\"/>\n";

  // Legend.
  if (L.legend_shown) {
    const double lx = L.legend_x, ly = L.legend_y;
    o << "<g class=\"legend\">";
    o << "<rect x=\"" << Num(lx) << "\" y=\"" << Num(ly) << "\" width=\"" << Num(L.legend_w) << "\" height=\""
      << Num(L.legend_h) << "\" fill=\"#ffffff\" fill-opacity=\"0.88\" stroke=\"#bbbbbb\" stroke-width=\"0.8\""
      << " rx=\"3\"/>\n";
    for (size_t i = 0; i < L.legend.size(); ++i) {
      const double ey = ly + 4.0 + kLegendRow * (i + 0.5);
      DrawLegendSample(o, L.legend[i], lx + 8, ey);
      o << "<text x=\"" << Num(lx + 40) << "\" y=\"" << Num(ey + 4) << "\" font-size=\"" << kLegendFont
        << "\" fill=\"#222\">" << Escape(L.legend[i].label) << "</text>\n";
    }
    o << "</g>\n";
  }
  o << "</g>\n";
}

}  // namespace

PlotSeries PlotSeries::Line(std::string label, std::vector<double> x, std::vector<double> y) {
  PlotSeries s;
  s.label = std::move(label), s.x = std::move(x), s.y = std::move(y);
  return s;
}
PlotSeries PlotSeries::Markers(std::string label, std::vector<double> x, std::vector<double> y) {
  PlotSeries s = Line(std::move(label), std::move(x), std::move(y));
  s.line = false, s.markers = true;
  return s;
}
PlotSeries PlotSeries::LineMarkers(std::string label, std::vector<double> x, std::vector<double> y) {
  PlotSeries s = Line(std::move(label), std::move(x), std::move(y));
  s.markers = true, s.marker_size_px = 6.0;
  return s;
}

PlotPanel::PlotPanel() : x_min(kNaN), x_max(kNaN), y_min(kNaN), y_max(kNaN) {}

PlotPanel& PlotFigure::AddPanel(std::string panel_title, std::string x_label, std::string y_label) {
  panels.emplace_back();
  panels.back().title = std::move(panel_title);
  panels.back().x_label = std::move(x_label);
  panels.back().y_label = std::move(y_label);
  return panels.back();
}

std::vector<double> NiceLinearTicks(double lo, double hi, int target) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo};
  target = std::max(target, 2);
  const double raw = (hi - lo) / (target - 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  const double nice = f < 1.5 ? 1.0 : f < 2.25 ? 2.0 : f < 3.5 ? 2.5 : f < 7.5 ? 5.0 : 10.0;
  const double step = nice * mag;
  const double i0 = std::floor(lo / step + 1e-9), i1 = std::ceil(hi / step - 1e-9);
  std::vector<double> ticks;
  for (double i = i0; i <= i1 + 0.5; i += 1.0) ticks.push_back(i * step);
  return ticks;
}

std::string FormatTick(double v, double step) {
  if (!(step > 0.0)) step = std::abs(v) > 0 ? std::abs(v) : 1.0;
  if (std::abs(v) < 1e-9 * step) v = 0.0;
  char buf[48];
  if (std::abs(v) >= 1e6 || step < 1e-5) {
    std::snprintf(buf, sizeof buf, "%g", v);
  } else {
    int decimals = 0;
    while (decimals < 8) {
      const double scaled = step * std::pow(10.0, decimals);
      if (std::abs(scaled - std::round(scaled)) < 1e-6 * scaled) break;
      ++decimals;
    }
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  }
  std::string s = buf;
  if (!s.empty() && s[0] == '-') s = "−" + s.substr(1);  // typographic minus
  return s;
}

std::string RenderSvg(const PlotFigure& figure) {
  const int n = std::max<int>(1, static_cast<int>(figure.panels.size()));
  int cols = figure.columns > 0 ? figure.columns : (n <= 3 ? n : (n == 4 ? 2 : 3));
  cols = std::min(cols, n);
  const int rows = (n + cols - 1) / cols;
  // A column gets wider if one of its panels puts its legend outside (asked for, or no free place inside).
  std::vector<double> col_w(cols, figure.panel_width_px), col_x(cols + 1, 5.0);
  std::vector<bool> outside(figure.panels.size(), false);
  for (size_t i = 0; i < figure.panels.size(); ++i) {
    const PanelLayout L =
        LayoutPanel(figure.panels[i], 0.0, 0.0, figure.panel_width_px, figure.panel_height_px);
    const int c = static_cast<int>(i) % cols;
    outside[i] = L.legend_outside;
    if (L.legend_outside) col_w[c] = std::max(col_w[c], figure.panel_width_px + L.legend_w + 10.0);
  }
  for (int c = 0; c < cols; ++c) col_x[c + 1] = col_x[c] + col_w[c];
  const double cell_h = figure.panel_height_px;
  const double title_h = figure.title.empty() ? 6.0 : 34.0;
  // The footnote may run over several lines ('\n'), so that it does not widen the figure.
  std::vector<std::string> foot_lines;
  for (std::size_t a = 0; !figure.footnote.empty();) {
    const std::size_t b = figure.footnote.find('\n', a);
    foot_lines.push_back(figure.footnote.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) break;
    a = b + 1;
  }
  const double foot_h = foot_lines.empty() ? 6.0 : 10.0 + kFootnoteLine * static_cast<double>(foot_lines.size());
  // Wide enough for the titles (bold glyphs ~8 % wider than the layout estimate).
  const double title_w = 1.08 * TextWidth(figure.title, kFigureTitleFont) + 40.0;
  double foot_w = 0.0;
  for (const auto& l : foot_lines) foot_w = std::max(foot_w, TextWidth(l, kFootnoteFont) + 30.0);
  const double width = std::max({col_x[cols] + 5.0, title_w, foot_w});
  const double height = title_h + rows * cell_h + foot_h;

  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Num(width) << "\" height=\"" << Num(height)
    << "\" viewBox=\"0 0 " << Num(width) << " " << Num(height) << "\" font-family=\"" << kFont << "\">\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  if (!figure.title.empty())
    o << "<text x=\"" << Num(width / 2) << "\" y=\"24\" font-size=\"" << kFigureTitleFont
      << "\" font-weight=\"bold\" text-anchor=\"middle\" fill=\"#111\">" << Escape(figure.title)
      << "</text>\n";
  for (size_t i = 0; i < figure.panels.size(); ++i) {
    const int r = static_cast<int>(i) / cols, c = static_cast<int>(i) % cols;
    // A panel with its legend inside keeps the common width in a widened column (equal plot areas).
    DrawPanel(o, figure.panels[i], static_cast<int>(i), col_x[c], title_h + r * cell_h,
              outside[i] ? col_w[c] : figure.panel_width_px, cell_h, outside[i]);
  }
  for (std::size_t k = 0; k < foot_lines.size(); ++k)
    o << "<text x=\"12\" y=\"" << Num(height - 8 - kFootnoteLine * static_cast<double>(foot_lines.size() - 1 - k))
      << "\" font-size=\"" << kFootnoteFont << "\" fill=\"#666\">" << Escape(foot_lines[k]) << "</text>\n";
  o << "</svg>\n";
  return o.str();
}

void WriteSvg(const PlotFigure& figure, const std::string& path) {
  WriteFileAtomically(path, RenderSvg(figure));
}

}  // namespace hullopt::io
