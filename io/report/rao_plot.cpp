#include "io/report/rao_plot.h"

#include <cmath>

#include "io/report/rao_axis_labels.h"

namespace hullopt::io {

PlotFigure RaoFigure(const std::vector<sk::RaoTable>& curves, const std::vector<std::string>& labels,
                     double length_m, const std::string& title, const MeasuredRao* measured) {
  PlotFigure fig;
  fig.title = title;
  fig.columns = 4;
  fig.footnote =
      "Head seas. Heave |x3|/A, pitch |x5|/(kA), k = ω²/g; phases relative to the wave crest at the CG, lead "
      "positive; pitch positive bow-down.";
  const char* dof_name[2] = {"Heave", "Pitch"};
  const char* amp_label[2] = {kHeaveRaoLabel, kPitchRaoLabel};
  for (int axis = 0; axis < 2; ++axis) {  // 0: ω_e, 1: λ/L
    for (int dof = 0; dof < 2; ++dof) {
      for (int phase = 0; phase < 2; ++phase) {
        PlotPanel& p =
            fig.AddPanel(std::string(dof_name[dof]) + (phase ? " phase" : " magnitude"),
                         axis == 0 ? "ω_e [rad/s]" : "λ/L [-]", phase ? "phase [deg]" : amp_label[dof]);
        p.y_include_zero = !phase;
        // One legend per row (the same curves in every panel).
        if (dof != 0 || phase) p.legend = LegendPlace::kNone;
        if (phase) {
          p.y_min = -180;
          p.y_max = 180;
        }
        for (std::size_t c = 0; c < curves.size(); ++c) {
          const auto& t = curves[c];
          std::vector<double> x, y;
          for (std::size_t i = 0; i < t.omega_rad_s.size(); ++i) {
            const double w = t.omega_rad_s[i];
            x.push_back(axis == 0 ? t.omega_e_rad_s[i] : 2 * M_PI * t.g_m_s2 / (w * w) / length_m);
            const auto v = dof == 0 ? t.heave[i] : t.pitch[i];
            y.push_back(phase ? std::arg(v) * 180 / M_PI : std::abs(v));
          }
          p.series.push_back(PlotSeries::Line(c < labels.size() ? labels[c] : "", x, y));
          if (phase) p.series.back().wrap_period = 360.0;
        }
        if (measured) {
          const auto& y = dof == 0 ? (phase ? measured->heave_phase_deg : measured->heave_amp)
                                   : (phase ? measured->pitch_phase_deg : measured->pitch_amp);
          auto s = PlotSeries::Markers(measured->label, axis == 0 ? measured->omega_e_rad_s : measured->lambda_over_L, y);
          s.color = "#000000";
          s.hollow_markers = true;
          p.series.push_back(s);
        }
      }
    }
  }
  return fig;
}

}  // namespace hullopt::io
