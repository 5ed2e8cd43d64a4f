#include "io/report/seakeeping_plots.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>

#include "io/report/design_variable_label.h"
#include "io/report/rao_axis_labels.h"
#include "seas/point_response.h"

namespace hullopt::io {
namespace {

std::string PlotNumber(double v, const char* format = "%g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string SeaLabel(const sk::SeaEvaluation& s) {
  return "Hs " + PlotNumber(s.sea.Hs_m) + " m, Tz " + PlotNumber(s.Tz_s, "%.3g") + " s";
}

// A design's number: the one its name starts with (the study's "12_TRIa"), else its place in the list. Every
// plot uses it, so a design keeps its number when others before it are left out.
int DesignNumber(size_t i, const EvaluatedDesign& d) {
  size_t n = 0;
  while (n < d.name.size() && n < 6 && std::isdigit(static_cast<unsigned char>(d.name[n]))) ++n;
  return n > 0 ? std::stoi(d.name.substr(0, n)) : static_cast<int>(i + 1);
}

// Legend label: the design's name, prefixed by its number unless the name carries it.
std::string Numbered(size_t i, const EvaluatedDesign& d) {
  if (!d.name.empty() && std::isdigit(static_cast<unsigned char>(d.name[0]))) return d.name;
  return std::to_string(DesignNumber(i, d)) + " " + d.name;
}

// Groups in order of first appearance.
std::vector<std::string> Groups(const std::vector<EvaluatedDesign>& designs) {
  std::vector<std::string> groups;
  for (const auto& d : designs)
    if (std::find(groups.begin(), groups.end(), d.group) == groups.end()) groups.push_back(d.group);
  return groups;
}

// "forward (x = 10.8 m)": a position with where it is.
std::string PositionLabel(const sk::PositionResult& p) {
  return (p.position == "lcg" ? std::string("LCG") : p.position) + " (x = " + PlotNumber(p.x_from_cg_m, "%.3g") + " m)";
}

std::string GroupTitle(const std::string& group, const std::string& what) {
  return group.empty() ? what : what + " — " + group;
}

std::string DesignList(const std::vector<EvaluatedDesign>& designs) {
  std::string s = "Designs: ";
  for (size_t i = 0; i < designs.size(); ++i) s += (i ? ", " : "") + Numbered(i, designs[i]);
  return s;
}

}  // namespace

size_t ReferenceSeaIndex(const std::vector<sk::SeaEvaluation>& seas) {
  size_t best = 0;
  for (size_t i = 1; i < seas.size(); ++i)
    if (seas[i].sea.Hs_m > seas[best].sea.Hs_m) best = i;
  return best;
}

PlotFigure EncounterSpectraFigure(const std::vector<sk::WaveSpectrum>& spectra, double U, double g) {
  PlotFigure fig;
  fig.title = "Head-sea encounter spectra at " + PlotNumber(U / (1852.0 / 3600.0), "%.3g") + " kn";
  fig.panel_width_px = 620.0;
  fig.panel_height_px = 380.0;
  auto& p = fig.AddPanel("", "encounter frequency ω_e [rad/s]", "S_ζ(ω_e) [m²s/rad]");
  p.legend = LegendPlace::kTopRight;
  double we_max = 0.0;
  for (const auto& s : spectra) we_max = std::max(we_max, 2.6 * sk::PeakEncounterFrequency(s, U, g));
  for (const auto& s : spectra) {
    const auto samples = sk::HeadSeaEncounterSpectrum(s, U, g, 0.0, we_max, 500);
    std::vector<double> x, y;
    for (const auto& e : samples) x.push_back(e.omega_e), y.push_back(e.wave);
    p.series.push_back(PlotSeries::Line(sk::SpectrumName(s.sea().spectrum) + " Hs " + PlotNumber(s.Hs_m()) +
                                            " m, Tz " + PlotNumber(s.Tz_s(), "%.3g") + " s: peak " +
                                            PlotNumber(sk::PeakEncounterFrequency(s, U, g), "%.2f") + " rad/s",
                                        x, y));
  }
  p.y_include_zero = true;
  p.x_min = 0.0;
  fig.footnote = "S_ζ(ω_e) = S_ζ(ω)/(1 + 2ωU/g), ω_e = ω + ω²U/g (cf. Davis & Holloway 2003, Fig. 7)";
  return fig;
}

PlotFigure RaoFigure(const std::vector<EvaluatedDesign>& designs) {
  PlotFigure fig;
  // Show the frequencies the seas excite: up to 2.5× the highest modal encounter frequency evaluated.
  double we_max = 0.0;
  for (const auto& d : designs)
    for (const auto& s : d.evaluation.seas) we_max = std::max(we_max, 2.5 * s.peak_omega_e_rad_s);
  // Ending the axis on a tick: the next nice value above.
  if (we_max > 0.0) we_max = NiceLinearTicks(0.0, we_max).back();
  fig.title = "Heave and pitch RAOs in head seas";
  fig.columns = 2;
  for (const auto& group : Groups(designs)) {
    auto& heave = fig.AddPanel(GroupTitle(group, "Heave"), "encounter frequency ω_e [rad/s]", kHeaveRaoLabel);
    heave.legend = LegendPlace::kNone;
    heave.y_include_zero = true;
    if (we_max > 0.0) heave.x_min = 0.0, heave.x_max = we_max;
    PlotPanel pitch;
    pitch.title = GroupTitle(group, "Pitch");
    pitch.x_label = "encounter frequency ω_e [rad/s]";
    pitch.y_label = kPitchRaoLabel;
    pitch.legend = LegendPlace::kOutsideRight;
    pitch.y_include_zero = true;
    pitch.x_min = heave.x_min, pitch.x_max = heave.x_max;
    for (size_t i = 0; i < designs.size(); ++i) {
      const auto& d = designs[i];
      if (d.group != group) continue;
      std::vector<double> h, q;
      for (size_t k = 0; k < d.rao.heave.size(); ++k)
        h.push_back(std::abs(d.rao.heave[k])), q.push_back(std::abs(d.rao.pitch[k]));
      heave.series.push_back(PlotSeries::Line(Numbered(i, d), d.rao.omega_e_rad_s, h));
      pitch.series.push_back(PlotSeries::Line(Numbered(i, d), d.rao.omega_e_rad_s, q));
    }
    fig.panels.push_back(pitch);
  }
  fig.footnote = "cf. Davis & Holloway 2003, Figs. 8–9 (RAO per wave amplitude; pitch per wave slope kA)";
  return fig;
}

PlotFigure AccelerationPerMetreFigure(const std::vector<EvaluatedDesign>& designs, size_t sea) {
  PlotFigure fig;
  std::string sea_label = designs.empty() || sea >= designs[0].evaluation.seas.size()
                              ? ""
                              : SeaLabel(designs[0].evaluation.seas[sea]);
  fig.title = "Rms vertical acceleration per metre of wave height, " + sea_label;
  const char* names[] = {"forward", "LCG", "transom"};
  const MarkerShape shapes[] = {MarkerShape::kTriangle, MarkerShape::kCircle, MarkerShape::kSquare};
  for (const auto& group : Groups(designs)) {
    auto& p = fig.AddPanel(GroupTitle(group, "Rms acceleration per metre"), "design", "σ_a / Hs [g/m]");
    p.legend = LegendPlace::kOutsideRight;
    p.y_include_zero = true;
    std::vector<double> x, y[3];
    for (size_t i = 0; i < designs.size(); ++i) {
      const auto& d = designs[i];
      if (d.group != group || sea >= d.evaluation.seas.size()) continue;
      const auto& s = d.evaluation.seas[sea];
      x.push_back(static_cast<double>(DesignNumber(i, d)));
      for (int k = 0; k < 3; ++k) y[k].push_back(s.positions[k].rms_accel_g / s.sea.Hs_m);
      p.x_ticks.push_back(x.back());
    }
    if (!x.empty()) p.x_min = x.front() - 0.5, p.x_max = x.back() + 0.5;
    for (int k = 0; k < 3; ++k) {
      auto series = PlotSeries::LineMarkers(names[k], x, y[k]);
      series.marker = shapes[k];
      series.line_width_px = 1.0;
      series.dash = "3 3";
      p.series.push_back(series);
    }
  }
  fig.footnote = DesignList(designs) + " (cf. Davis & Holloway 2003, Fig. 10)";
  return fig;
}

namespace {

// A figure of one panel per design (titled with its number and name), y axis from zero; draw(p, d) adds the
// design's series to its panel.
PlotFigure PanelPerDesignFigure(const std::vector<EvaluatedDesign>& designs, const std::string& title,
                                double panel_width_px, double panel_height_px, const std::string& x_label,
                                const std::string& y_label,
                                const std::function<void(PlotPanel& p, const EvaluatedDesign& d)>& draw) {
  PlotFigure fig;
  fig.title = title;
  fig.panel_width_px = panel_width_px;
  fig.panel_height_px = panel_height_px;
  for (size_t i = 0; i < designs.size(); ++i) {
    auto& p = fig.AddPanel(Numbered(i, designs[i]), x_label, y_label);
    p.y_include_zero = true;
    draw(p, designs[i]);
  }
  return fig;
}

}  // namespace

PlotFigure AccelerationPerMetreVsHsFigure(const std::vector<EvaluatedDesign>& designs) {
  PlotFigure fig = PanelPerDesignFigure(
      designs, "Rms vertical acceleration per metre of wave height vs Hs", 380.0, 290.0, "Hs [m]",
      "σ_a / Hs [g/m]", [](PlotPanel& p, const EvaluatedDesign& d) {
        if (d.evaluation.seas.empty()) return;
        const auto& positions = d.evaluation.seas[0].positions;
        for (size_t k = 0; k < positions.size(); ++k) {
          std::vector<double> x, y;
          for (const auto& s : d.evaluation.seas) {
            x.push_back(s.sea.Hs_m);
            y.push_back(k < s.positions.size() ? s.positions[k].rms_accel_g / s.sea.Hs_m : NAN);
          }
          p.series.push_back(PlotSeries::LineMarkers(PositionLabel(positions[k]), x, y));
        }
      });
  fig.footnote = "x: position forward of the CG";
  return fig;
}

PlotFigure MsiAlongHullFigure(const std::vector<EvaluatedDesign>& designs) {
  PlotFigure fig = PanelPerDesignFigure(
      designs, "Motion sickness incidence at each position along the hull", 420.0, 300.0,
      "position x forward of the CG [m]", "MSI [%]", [](PlotPanel& p, const EvaluatedDesign& d) {
        p.pad_fraction = 0.08;
        const size_t ref = d.evaluation.seas.empty() ? 0 : ReferenceSeaIndex(d.evaluation.seas);
        for (size_t k = 0; k < d.evaluation.seas.size(); ++k) {
          const auto& s = d.evaluation.seas[k];
          std::vector<const sk::PositionResult*> along;
          for (const auto& r : s.positions) along.push_back(&r);
          std::stable_sort(along.begin(), along.end(),
                           [](const auto* a, const auto* b) { return a->x_from_cg_m < b->x_from_cg_m; });
          std::vector<double> x, y;
          std::vector<std::string> names;
          for (const auto* r : along) {
            x.push_back(r->x_from_cg_m);
            y.push_back(r->msi_pct);
            names.push_back(k == ref ? (r->position == "lcg" ? "LCG" : r->position) : "");
          }
          auto series = PlotSeries::LineMarkers(SeaLabel(s), x, y);
          series.line_width_px = 1.0;
          series.point_labels = names;
          p.series.push_back(series);
        }
      });
  fig.footnote = "Positions named in the sea of largest Hs; MSI as in msi.csv (model and exposure in summary.json)";
  return fig;
}

PlotFigure MsiVsHsFigure(const std::vector<EvaluatedDesign>& designs) {
  PlotFigure fig;
  fig.title = "Motion sickness incidence vs wave height (mean of forward, LCG, transom)";
  for (const auto& group : Groups(designs)) {
    auto& p = fig.AddPanel(GroupTitle(group, "MSI"), "Hs [m]", "MSI [%]");
    p.y_include_zero = true;
    p.legend = LegendPlace::kTopLeft;
    for (size_t i = 0; i < designs.size(); ++i) {
      const auto& d = designs[i];
      if (d.group != group) continue;
      std::vector<double> x, y;
      for (const auto& s : d.evaluation.seas) x.push_back(s.sea.Hs_m), y.push_back(s.mean.msi_pct);
      p.series.push_back(PlotSeries::LineMarkers(Numbered(i, d), x, y));
    }
  }
  fig.footnote = "cf. Davis & Holloway 2003, Fig. 11";
  return fig;
}

PlotFigure MsiVsParameterFigure(const std::vector<EvaluatedDesign>& designs, const std::string& parameter,
                                const std::string& axis_label, size_t sea) {
  PlotFigure fig;
  std::string sea_label = designs.empty() || sea >= designs[0].evaluation.seas.size()
                              ? ""
                              : SeaLabel(designs[0].evaluation.seas[sea]);
  fig.title = "Mean MSI in " + sea_label + " vs " + DesignVariableName(parameter);
  fig.panel_width_px = 560.0;
  fig.panel_height_px = 380.0;
  auto& p = fig.AddPanel("", axis_label, "MSI [%]");
  p.pad_fraction = 0.08;
  const MarkerShape shapes[] = {MarkerShape::kCircle, MarkerShape::kSquare, MarkerShape::kTriangle,
                                MarkerShape::kDiamond};
  int g = 0;
  for (const auto& group : Groups(designs)) {
    std::vector<double> x, y;
    std::vector<std::string> labels;
    for (size_t i = 0; i < designs.size(); ++i) {
      const auto& d = designs[i];
      const auto it = d.parameters.find(parameter);
      if (d.group != group || it == d.parameters.end() || sea >= d.evaluation.seas.size()) continue;
      x.push_back(it->second);
      y.push_back(d.evaluation.seas[sea].mean.msi_pct);
      labels.push_back(std::to_string(DesignNumber(i, d)));
    }
    if (x.empty()) continue;
    auto s = PlotSeries::Markers(group.empty() ? "designs" : group, x, y);
    s.marker = shapes[g++ % 4];
    s.point_labels = labels;
    p.series.push_back(s);
  }
  fig.footnote = DesignList(designs);
  return fig;
}

}  // namespace hullopt::io
