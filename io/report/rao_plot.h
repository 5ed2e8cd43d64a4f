#pragma once
// rao.svg: heave and pitch RAO magnitude and phase against encounter frequency and against λ/L, optionally
// with measured points (markers) over the computed curves.
#include <string>
#include <vector>

#include "io/report/svg_plot.h"
#include "seakeeping/motions/rao_table.h"

namespace hullopt::io {

/// Measured RAO points to overlay, drawn against both ω_e [rad/s] and λ/L (NaN phase = not measured).
struct MeasuredRao {
  std::string label;  ///< legend text, e.g. "tank, van 't Veer (1998)"
  std::vector<double> omega_e_rad_s, lambda_over_L, heave_amp, heave_phase_deg, pitch_amp, pitch_phase_deg;
};

/// 8 panels: heave/pitch × magnitude/phase × (ω_e, λ/L). length_m [m] is the L of λ/L. Curves may be several
/// (e.g. two methods); labels name them.
PlotFigure RaoFigure(const std::vector<sk::RaoTable>& curves, const std::vector<std::string>& labels,
                     double length_m, const std::string& title, const MeasuredRao* measured = nullptr);

}  // namespace hullopt::io
