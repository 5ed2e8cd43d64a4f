#include "io/report/rao_plot.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "io/report/rao_axis_labels.h"

namespace hullopt::io {
namespace {

/// Below this share of its peak an RAO no longer matters to any response: the ω_e axis ends where every curve
/// has fallen below it for good (rather than at the end of the frequency table).
constexpr double kShownRaoFraction = 0.01;

std::vector<double> UnwrappedPhaseDeg(const std::vector<std::complex<double>>& v) {
  std::vector<double> out;
  double offset = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double p = std::arg(v[i]) * 180.0 / M_PI;
    if (i > 0) {
      const double prev = out.back() - offset;
      if (p - prev > 180.0) offset -= 360.0;
      if (p - prev < -180.0) offset += 360.0;
    }
    out.push_back(p + offset);
  }
  return out;
}

// The highest ω_e at which heave or pitch of any curve is still at kShownRaoFraction of its peak, one table
// step further (so the fall-off shows), capped at the table's end.
double ShownOmegaEMax(const std::vector<sk::RaoTable>& curves) {
  double we_max = 0.0;
  for (const auto& t : curves) {
    for (const auto* v : {&t.heave, &t.pitch}) {
      double peak = 0.0;
      for (const auto& c : *v) peak = std::max(peak, std::abs(c));
      std::size_t last = 0;
      for (std::size_t i = 0; i < v->size(); ++i)
        if (std::abs((*v)[i]) >= kShownRaoFraction * peak) last = i;
      last = std::min(last + 1, t.omega_e_rad_s.size() - 1);
      we_max = std::max(we_max, t.omega_e_rad_s[last]);
    }
  }
  return we_max;
}

// The lowest ω (longest wave) below which heave and pitch of every curve stay within kShownRaoFraction of their
// peaks of the long-wave limit |RAO| = 1 (the ship follows the wave), one table step further, for the λ/L axis.
double ShownOmegaMin(const std::vector<sk::RaoTable>& curves) {
  double w_min = std::numeric_limits<double>::infinity();
  for (const auto& t : curves) {
    for (const auto* v : {&t.heave, &t.pitch}) {
      double peak = 0.0;
      for (const auto& c : *v) peak = std::max(peak, std::abs(c));
      // Nothing away from the limit: no cap (the table's lowest ω).
      std::size_t first = 0;
      for (std::size_t i = v->size(); i-- > 0;)
        if (std::fabs(std::abs((*v)[i]) - 1.0) >= kShownRaoFraction * peak) first = i;
      first = first > 0 ? first - 1 : 0;
      w_min = std::min(w_min, t.omega_rad_s[first]);
    }
  }
  return w_min;
}

}  // namespace

PlotFigure RaoFigure(const std::vector<sk::RaoTable>& curves, const std::vector<std::string>& labels,
                     double length_m, const std::string& title, const MeasuredRao* measured) {
  PlotFigure fig;
  fig.title = title;
  // Two columns keep the figure within a report page at full size, so its text is read at its set size.
  fig.columns = 2;
  fig.footnote =
      "Head seas. Heave |x3|/A, pitch |x5|/(kA), k = ω²/g; pitch positive bow-down.\n"
      "Phases relative to the wave crest at the CG, lead positive, unwrapped along frequency.\n"
      "ω_e shown up to where the RAOs fall below 1 % of their peaks; λ/L up to where they are within 1 % of "
      "their peaks of the long-wave limit 1.";
  const char* dof_name[2] = {"Heave", "Pitch"};
  const char* amp_label[2] = {kHeaveRaoLabel, kPitchRaoLabel};
  double we_max = curves.empty() ? 0.0 : ShownOmegaEMax(curves);
  if (measured)
    for (double w : measured->omega_e_rad_s)
      if (std::isfinite(w)) we_max = std::max(we_max, w);
  // λ/L at the highest ω shown (of the first curve's table): the λ/L axis starts there; it ends where the RAOs
  // have settled on the long-wave limit.
  double lambda_min = std::numeric_limits<double>::quiet_NaN(), lambda_max = lambda_min;
  if (!curves.empty() && !curves[0].omega_rad_s.empty()) {
    const double w = ShownOmegaMin(curves);
    lambda_max = 2 * M_PI * curves[0].g_m_s2 / (w * w) / length_m;
    if (measured)
      for (double l : measured->lambda_over_L)
        if (std::isfinite(l)) lambda_max = std::max(lambda_max, l);
  }
  if (!curves.empty() && !curves[0].omega_rad_s.empty()) {
    const auto& t = curves[0];
    double w_max = t.omega_rad_s.back();
    for (std::size_t i = 0; i < t.omega_rad_s.size(); ++i)
      if (t.omega_e_rad_s[i] <= we_max) w_max = t.omega_rad_s[i];
    lambda_min = 2 * M_PI * t.g_m_s2 / (w_max * w_max) / length_m;
    if (measured)
      for (double l : measured->lambda_over_L)
        if (std::isfinite(l)) lambda_min = std::min(lambda_min, l);
  }
  if (!(lambda_max > lambda_min)) lambda_max = std::numeric_limits<double>::quiet_NaN();
  // Unwrapped phases of every curve, and the first curve's for placing measured phases on the same branch.
  std::vector<std::vector<double>> heave_phase, pitch_phase;
  for (const auto& t : curves) {
    heave_phase.push_back(UnwrappedPhaseDeg(t.heave));
    pitch_phase.push_back(UnwrappedPhaseDeg(t.pitch));
  }
  for (int axis = 0; axis < 2; ++axis) {  // 0: ω_e, 1: λ/L
    for (int dof = 0; dof < 2; ++dof) {
      for (int phase = 0; phase < 2; ++phase) {
        PlotPanel& p =
            fig.AddPanel(std::string(dof_name[dof]) + (phase ? " phase" : " magnitude"),
                         axis == 0 ? "ω_e [rad/s]" : "λ/L [-]", phase ? "phase [deg]" : amp_label[dof]);
        p.y_include_zero = !phase;
        // One legend per row (the same curves in every panel).
        if (dof != 0 || phase) p.legend = LegendPlace::kNone;
        if (axis == 0 && we_max > 0.0) p.x_max = we_max;
        if (axis == 1 && std::isfinite(lambda_min)) p.x_min = lambda_min;
        if (axis == 1 && std::isfinite(lambda_max)) p.x_max = lambda_max;
        for (std::size_t c = 0; c < curves.size(); ++c) {
          const auto& t = curves[c];
          const auto& ph = dof == 0 ? heave_phase[c] : pitch_phase[c];
          std::vector<double> x, y;
          for (std::size_t i = 0; i < t.omega_rad_s.size(); ++i) {
            const double w = t.omega_rad_s[i];
            if (axis == 0 && we_max > 0.0 && t.omega_e_rad_s[i] > we_max) continue;
            const double lambda = 2 * M_PI * t.g_m_s2 / (w * w) / length_m;
            if (axis == 1 && std::isfinite(lambda_min) && lambda < lambda_min * (1 - 1e-12)) continue;
            if (axis == 1 && std::isfinite(lambda_max) && lambda > lambda_max * (1 + 1e-12)) continue;
            x.push_back(axis == 0 ? t.omega_e_rad_s[i] : lambda);
            const auto v = dof == 0 ? t.heave[i] : t.pitch[i];
            y.push_back(phase ? ph[i] : std::abs(v));
          }
          p.series.push_back(PlotSeries::Line(c < labels.size() ? labels[c] : "", x, y));
        }
        if (measured) {
          auto y = dof == 0 ? (phase ? measured->heave_phase_deg : measured->heave_amp)
                            : (phase ? measured->pitch_phase_deg : measured->pitch_amp);
          // A measured phase goes on the branch of the first curve's unwrapped phase nearest to it.
          if (phase && !curves.empty()) {
            const auto& t = curves[0];
            const auto& ph = dof == 0 ? heave_phase[0] : pitch_phase[0];
            for (std::size_t i = 0; i < y.size() && i < measured->omega_e_rad_s.size(); ++i) {
              if (!std::isfinite(y[i]) || t.omega_e_rad_s.empty()) continue;
              const auto it = std::lower_bound(t.omega_e_rad_s.begin(), t.omega_e_rad_s.end(),
                                               measured->omega_e_rad_s[i]);
              const std::size_t k = std::min<std::size_t>(it - t.omega_e_rad_s.begin(), ph.size() - 1);
              y[i] += 360.0 * std::round((ph[k] - y[i]) / 360.0);
            }
          }
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
