#include "io/report/campaign_plots.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "io/report/design_variable_label.h"
#include "io/report/svg_plot.h"

namespace hullopt::io {
namespace {
std::string PlotPath(const std::string& dir, const std::string& name) { return dir + "/" + name; }
}  // namespace

void WriteOptimizePlots(const std::string& dir, const std::vector<opt::EvaluationRecord>& records,
                        const std::vector<std::string>& names, const std::vector<double>& lower,
                        const std::vector<double>& upper, const std::string& objective_label) {
  std::vector<double> ef, f, ei, fi, eb, fb;
  double best = NAN;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& r = records[i];
    if (r.result.produced) {
      (r.feasible ? ef : ei).push_back(static_cast<double>(i));
      (r.feasible ? f : fi).push_back(r.result.objective);
    }
    if (r.feasible && !(r.result.objective >= best)) best = r.result.objective;
    if (std::isfinite(best)) {
      eb.push_back(static_cast<double>(i));
      fb.push_back(best);
    }
  }
  PlotFigure conv;
  conv.title = "Optimisation history";
  conv.footnote = "evaluation 0 is the base design; hollow markers: designs violating a constraint";
  PlotPanel& p = conv.AddPanel("Objective", "evaluation", objective_label);
  // Early evaluations are often orders of magnitude worse than the optimum: log axis when that is the case.
  double lo = INFINITY, hi = -INFINITY;
  for (const auto* v : {&f, &fi})
    for (double y : *v) {
      lo = std::min(lo, y);
      hi = std::max(hi, y);
    }
  if (lo > 0 && hi > 100 * lo) p.y_scale = AxisScale::kLog;
  p.series.push_back(PlotSeries::Markers("feasible", ef, f));
  p.series.back().marker_size_px = 4;
  auto infeasible = PlotSeries::Markers("infeasible", ei, fi);
  infeasible.hollow_markers = true;
  infeasible.marker_size_px = 4;
  p.series.push_back(infeasible);
  p.series.push_back(PlotSeries::Line("best feasible so far", eb, fb));
  WriteSvg(conv, PlotPath(dir, "convergence.svg"));

  PlotFigure vars;
  vars.title = "Design variables during the optimisation";
  for (std::size_t j = 0; j < names.size(); ++j) {
    std::vector<double> e, v;
    for (std::size_t i = 0; i < records.size(); ++i) {
      e.push_back(static_cast<double>(i));
      v.push_back(records[i].x[j]);
    }
    PlotPanel& q = vars.AddPanel(DesignVariableName(names[j]), "evaluation", DesignVariableAxisLabel(names[j]));
    q.y_min = lower[j];
    q.y_max = upper[j];
    auto s = PlotSeries::LineMarkers("", e, v);
    s.marker_size_px = 3;
    s.line_width_px = 0.8;
    q.series.push_back(s);
    q.legend = LegendPlace::kNone;
  }
  WriteSvg(vars, PlotPath(dir, "variables.svg"));
}

void WriteExplorePlots(const std::string& dir, const std::vector<opt::EvaluationRecord>& records,
                       const std::vector<std::string>& names, const std::string& objective_label) {
  PlotFigure fig;
  fig.title = "Objective against each design variable";
  fig.footnote = "markers: samples (hollow: violating a constraint); line: partial dependence (binned mean)";
  for (std::size_t j = 0; j < names.size(); ++j) {
    std::vector<double> xf, yf, xi, yi;
    for (const auto& r : records) {
      if (!r.result.produced) continue;
      (r.feasible ? xf : xi).push_back(r.x[j]);
      (r.feasible ? yf : yi).push_back(r.result.objective);
    }
    PlotPanel& p = fig.AddPanel(DesignVariableName(names[j]), DesignVariableAxisLabel(names[j]), objective_label);
    p.pad_fraction = 0.06;
    auto s = PlotSeries::Markers("samples", xf, yf);
    s.marker_size_px = 4;
    p.series.push_back(s);
    if (!xi.empty()) {
      auto h = PlotSeries::Markers("infeasible", xi, yi);
      h.hollow_markers = true;
      h.marker_size_px = 4;
      p.series.push_back(h);
    }
    // Partial dependence: mean objective in equal-count bins of x_j.
    const std::size_t n = xf.size();
    if (n >= 4) {
      std::vector<std::size_t> order(n);
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return xf[a] < xf[b]; });
      const std::size_t bins = std::max<std::size_t>(2, static_cast<std::size_t>(std::sqrt(double(n))));
      std::vector<double> bx, by;
      for (std::size_t b = 0; b < bins; ++b) {
        const std::size_t lo = b * n / bins, hi = (b + 1) * n / bins;
        if (hi <= lo) continue;
        double sx = 0, sy = 0;
        for (std::size_t k = lo; k < hi; ++k) {
          sx += xf[order[k]];
          sy += yf[order[k]];
        }
        bx.push_back(sx / (hi - lo));
        by.push_back(sy / (hi - lo));
      }
      p.series.push_back(PlotSeries::Line("partial dependence", bx, by));
    }
  }
  WriteSvg(fig, PlotPath(dir, "scatter.svg"));
}

}  // namespace hullopt::io
