#include "io/report/coefficients_plot.h"

#include <cmath>
#include <complex>
#include <functional>

namespace hullopt::io {

PlotFigure CoefficientsFigure(const std::vector<sk::CoefficientTable>& curves,
                              const std::vector<std::string>& labels, double length_m, const std::string& title,
                              const MeasuredCoefficientPoints* m) {
  PlotFigure fig;
  fig.title = title;
  fig.columns = 4;
  fig.panel_width_px = 380;
  fig.panel_height_px = 280;
  fig.footnote =
      "Head seas; origin at the CG, heave up, pitch bow-down; F per unit wave amplitude, phase relative to the "
      "wave crest at the CG, lead positive. B includes the Cs damping. Dashed: Froude–Krylov part.";
  using Get = std::function<double(const sk::HeadSeaCoefficients&)>;
  struct Panel {
    std::string title, unit;
    Get get;
    const std::vector<double>* mx;
    const std::vector<double>* my;
    Get fk;  // optional second (dashed) curve
    bool phase;
  };
  static const std::vector<double> none;
  auto X = [&](const std::vector<double> MeasuredCoefficientPoints::*x) -> const std::vector<double>* {
    return m ? &(m->*x) : &none;
  };
  auto phase = [](std::complex<double> z) { return std::arg(z) * 180.0 / M_PI; };
  const std::vector<Panel> panels = {
      {"A33", "[kg]", [](const auto& c) { return c.A(0, 0); }, X(&MeasuredCoefficientPoints::heave_x),
       X(&MeasuredCoefficientPoints::A33), nullptr, false},
      {"B33", "[kg/s]", [](const auto& c) { return c.B(0, 0); }, X(&MeasuredCoefficientPoints::heave_x),
       X(&MeasuredCoefficientPoints::B33), nullptr, false},
      {"A55", "[kg m²]", [](const auto& c) { return c.A(1, 1); }, X(&MeasuredCoefficientPoints::pitch_x),
       X(&MeasuredCoefficientPoints::A55), nullptr, false},
      {"B55", "[kg m²/s]", [](const auto& c) { return c.B(1, 1); }, X(&MeasuredCoefficientPoints::pitch_x),
       X(&MeasuredCoefficientPoints::B55), nullptr, false},
      {"A35 (heave force / pitch)", "[kg m]", [](const auto& c) { return c.A(0, 1); },
       X(&MeasuredCoefficientPoints::pitch_x), X(&MeasuredCoefficientPoints::A35), nullptr, false},
      {"A53 (pitch moment / heave)", "[kg m]", [](const auto& c) { return c.A(1, 0); },
       X(&MeasuredCoefficientPoints::heave_x), X(&MeasuredCoefficientPoints::A53), nullptr, false},
      {"B35", "[kg m/s]", [](const auto& c) { return c.B(0, 1); }, X(&MeasuredCoefficientPoints::pitch_x),
       X(&MeasuredCoefficientPoints::B35), nullptr, false},
      {"B53", "[kg m/s]", [](const auto& c) { return c.B(1, 0); }, X(&MeasuredCoefficientPoints::heave_x),
       X(&MeasuredCoefficientPoints::B53), nullptr, false},
      {"|F3|", "[N/m]", [](const auto& c) { return std::abs(c.Exciting(0)); },
       X(&MeasuredCoefficientPoints::load_x), X(&MeasuredCoefficientPoints::F3_amp),
       [](const auto& c) { return std::abs(c.froude_krylov[0]); }, false},
      {"F3 phase", "[deg]", [phase](const auto& c) { return phase(c.Exciting(0)); },
       X(&MeasuredCoefficientPoints::load_x), X(&MeasuredCoefficientPoints::F3_phase_deg),
       [phase](const auto& c) { return phase(c.froude_krylov[0]); }, true},
      {"|F5|", "[N m/m]", [](const auto& c) { return std::abs(c.Exciting(1)); },
       X(&MeasuredCoefficientPoints::load_x), X(&MeasuredCoefficientPoints::F5_amp),
       [](const auto& c) { return std::abs(c.froude_krylov[1]); }, false},
      {"F5 phase", "[deg]", [phase](const auto& c) { return phase(c.Exciting(1)); },
       X(&MeasuredCoefficientPoints::load_x), X(&MeasuredCoefficientPoints::F5_phase_deg),
       [phase](const auto& c) { return phase(c.froude_krylov[1]); }, true},
  };
  const char* palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
  for (const auto& pd : panels) {
    PlotPanel& p = fig.AddPanel(pd.title, "ω_e √(L/g) [-]", pd.title + " " + pd.unit);
    p.y_include_zero = !pd.phase;
    // One legend for the figure (the same curves and points in every panel).
    if (&pd != &panels.front()) p.legend = LegendPlace::kNone;
    if (pd.phase) {
      p.y_min = -180;
      p.y_max = 180;
    }
    for (std::size_t c = 0; c < curves.size(); ++c) {
      std::vector<double> x, y, yfk;
      for (const auto& r : curves[c].rows) {
        x.push_back(r.omega_e_rad_s * std::sqrt(length_m / curves[c].g_m_s2));
        y.push_back(pd.get(r));
        if (pd.fk) yfk.push_back(pd.fk(r));
      }
      auto s = PlotSeries::Line(c < labels.size() ? labels[c] : "", x, y);
      s.color = palette[c % 4];
      if (pd.phase) s.wrap_period = 360.0;
      p.series.push_back(s);
      if (pd.fk) {
        auto f = PlotSeries::Line("", x, yfk);
        f.color = palette[c % 4];
        f.dash = "6 3";
        f.line_width_px = 1.0;
        if (pd.phase) f.wrap_period = 360.0;
        p.series.push_back(f);
      }
    }
    if (m && !pd.my->empty()) {
      auto s = PlotSeries::Markers(m->label, *pd.mx, *pd.my);
      s.hollow_markers = true;
      s.color = "#000000";
      p.series.push_back(s);
    }
  }
  return fig;
}

}  // namespace hullopt::io
