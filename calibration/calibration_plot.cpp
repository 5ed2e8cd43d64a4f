#include "calibration/calibration_plot.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "io/report/rao_axis_labels.h"

namespace hullopt::calib {
namespace {

const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

std::string PlotNumber(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

}  // namespace

io::PlotFigure CalibrationPlot(const std::vector<opt::CalibrationCase>& cases, const CsCalibrationResult& r,
                           double Cs_initial) {
  bool all_l = true;
  for (const auto& c : cases)
    for (const auto& p : c.points) all_l = all_l && p.has_lambda_over_L;
  auto xof = [&](const opt::TankRaoPoint& p) { return all_l ? p.lambda_over_L : p.omega_e_rad_s; };

  io::PlotFigure fig;
  fig.title = "Cs calibration (" + ToString(r.mode) + "): measured vs computed RAOs";
  fig.footnote = "Head seas, k = ω²/g. Circles: measured. Dashed: Cs_initial = " + PlotNumber(Cs_initial) +
                 ". Solid: fitted Cs. Computed at the measured points.";
  fig.columns = 2;
  const std::string xlabel = all_l ? "λ/L [-]" : "ω_e [rad/s]";
  for (int q = 0; q < 2; ++q) {
    io::PlotPanel& panel =
        fig.AddPanel(q == 0 ? "heave" : "pitch", xlabel, q == 0 ? io::kHeaveRaoLabel : io::kPitchRaoLabel);
    panel.y_include_zero = true;
    panel.legend = io::LegendPlace::kAuto;
    for (std::size_t c = 0; c < cases.size(); ++c) {
      const auto& pts = cases[c].points;
      std::vector<std::size_t> order(pts.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(),
                [&](std::size_t a, std::size_t b) { return xof(pts[a]) < xof(pts[b]); });
      std::vector<double> x, meas, before, after;
      for (std::size_t i : order) {
        x.push_back(xof(pts[i]));
        meas.push_back(q == 0 ? pts[i].heave_amp : pts[i].pitch_amp);
        before.push_back(
            std::abs(q == 0 ? r.predictions_before[c].heave[i] : r.predictions_before[c].pitch[i]));
        after.push_back(std::abs(q == 0 ? r.predictions_after[c].heave[i] : r.predictions_after[c].pitch[i]));
      }
      const std::string colour = kColours[c % 6];
      io::PlotSeries m = io::PlotSeries::Markers(cases[c].label + " measured", x, meas);
      m.hollow_markers = true;
      m.color = colour;
      io::PlotSeries b = io::PlotSeries::Line(cases[c].label + " Cs " + PlotNumber(Cs_initial), x, before);
      b.dash = "6 4";
      b.color = colour;
      b.line_width_px = 1.2;
      io::PlotSeries a = io::PlotSeries::Line(
          cases[c].label + " Cs " + PlotNumber(r.case_Cs[c]) + " ± " + PlotNumber(r.case_Cs_std_error[c]), x, after);
      a.color = colour;
      panel.series.push_back(m);
      panel.series.push_back(b);
      panel.series.push_back(a);
    }
  }
  return fig;
}

}  // namespace hullopt::calib
