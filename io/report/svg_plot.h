#pragma once
// General SVG line/scatter plots: a figure of one or more panels (subplots), each with a title, axis labels
// (put the unit in the label, e.g. "ω_e [rad/s]"), linear or log axes with nice tick labels, several series
// (line and/or markers, labelled, legend) and optional shaded reference bands (e.g. a published range).
// Measured or reference data are ordinary series drawn with markers only (PlotSeries::Markers).
//
// Usage:
//   io::PlotFigure fig;
//   fig.title = "Encounter spectra, 40 kn head seas";
//   io::PlotPanel& p = fig.AddPanel("Hs 3 m, Tz 7.5 s", "ω_e [rad/s]", "S(ω_e) [m²s/rad]");
//   p.series.push_back(io::PlotSeries::Line("JONSWAP γ=3.3", w, s));
//   io::WriteSvg(fig, "spectra.svg");
// Non-finite points (and non-positive ones on a log axis) are skipped and break the line there. Lines are cut
// at the plot area's edges (and clipped by an SVG clipPath as well); markers outside the axis ranges are not
// drawn. The data of a panel are in <g class="data">, its legend in <g class="legend">, its plot area is the
// <rect class="frame">.
#include <string>
#include <vector>

namespace hullopt::io {

enum class AxisScale { kLinear, kLog };
enum class MarkerShape { kCircle, kSquare, kTriangle, kDiamond, kCross, kPlus };
/// kAuto: the first of the corners (and top/bottom centre) where the legend box covers no drawn point or line,
/// else outside the plot area on the right. A named corner is tried first, with the same fallback.
enum class LegendPlace { kAuto, kTopRight, kTopLeft, kBottomRight, kBottomLeft, kOutsideRight, kNone };

struct PlotSeries {
  std::string label;  ///< legend text; empty = not listed in the legend
  std::vector<double> x, y;
  bool line = true;      ///< join the points with a polyline
  bool markers = false;  ///< draw a marker at each point
  MarkerShape marker = MarkerShape::kCircle;
  std::string color;  ///< CSS colour; empty = next colour of the figure palette
  std::string dash;   ///< SVG stroke-dasharray, e.g. "6 3"; empty = solid
  double line_width_px = 1.8;
  double marker_size_px = 7.0;
  bool hollow_markers = false;            ///< open markers (white fill), e.g. for measured data
  std::vector<std::string> point_labels;  ///< optional text beside each point (same length as x or empty)
  /// > 0: y is periodic with this period (360 for a phase in degrees). Where consecutive values jump by more
  /// than half a period the line runs out of the plot area to the wrap and in again from the other edge,
  /// instead of a vertical stroke across the panel.
  double wrap_period = 0.0;

  static PlotSeries Line(std::string label, std::vector<double> x, std::vector<double> y);
  static PlotSeries Markers(std::string label, std::vector<double> x, std::vector<double> y);
  static PlotSeries LineMarkers(std::string label, std::vector<double> x, std::vector<double> y);
};

/// A shaded horizontal band y_low ≤ y ≤ y_high across the panel (e.g. a published range), labelled in the
/// legend.
struct PlotBand {
  std::string label;
  double y_low = 0.0, y_high = 0.0;
  std::string color = "#9e9e9e";
};

struct PlotPanel {
  std::string title;
  std::string x_label;  ///< with unit, e.g. "Hs [m]"
  std::string y_label;
  AxisScale x_scale = AxisScale::kLinear;
  AxisScale y_scale = AxisScale::kLinear;
  /// Axis limits; NaN = from the data, widened to nice tick values.
  double x_min, x_max, y_min, y_max;
  bool y_include_zero = false;  ///< linear y axis: extend the automatic range to 0
  /// Linear automatic ranges: widen the data range by this fraction on each side before rounding to ticks,
  /// so markers do not sit on the frame (scatter plots: ~0.06).
  double pad_fraction = 0.0;
  /// Explicit x ticks (e.g. design numbers) with optional labels (same length; empty = the numbers); empty =
  /// automatic nice ticks.
  std::vector<double> x_ticks;
  std::vector<std::string> x_tick_labels;
  LegendPlace legend = LegendPlace::kAuto;
  std::vector<PlotSeries> series;
  std::vector<PlotBand> bands;
  PlotPanel();
};

struct PlotFigure {
  std::string title;     ///< over the whole figure (may be empty)
  std::string footnote;  ///< small text under the panels (source, conditions); '\n' starts a new line
  int columns = 0;       ///< panels per row; 0 = automatic (up to 3)
  double panel_width_px = 440.0;
  double panel_height_px = 320.0;
  std::vector<PlotPanel> panels;

  /// Appends a panel and returns it for filling in.
  PlotPanel& AddPanel(std::string panel_title, std::string x_label, std::string y_label);
};

/// The figure as an SVG document (UTF-8).
std::string RenderSvg(const PlotFigure& figure);
/// Writes RenderSvg(figure) to path. Throws io::InputError if the file cannot be written.
void WriteSvg(const PlotFigure& figure, const std::string& path);

/// Nice tick values covering [lo, hi] on a linear axis: about `target` ticks spaced 1, 2, 2.5 or 5 × 10^k.
std::vector<double> NiceLinearTicks(double lo, double hi, int target = 6);
/// Tick label text for value v on a linear axis with tick spacing step (no trailing noise, "−" for minus).
std::string FormatTick(double v, double step);

}  // namespace hullopt::io
