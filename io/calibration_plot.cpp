#include "io/calibration_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

namespace hullopt::io {
namespace {

constexpr double kPanelW = 460, kPanelH = 330, kLeft = 60, kTop = 50, kGap = 90, kBottom = 80;
const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

std::string F(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

/// Tick step of 1, 2 or 5 × 10^k giving about five intervals over [lo, hi].
double TickStep(double lo, double hi) {
  const double raw = (hi - lo) / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * mag >= raw) return m * mag;
  return 10 * mag;
}

std::string Escape(const std::string& s) {
  std::string o;
  for (char c : s) o += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return o;
}

}  // namespace

std::string CalibrationPlotSvg(const std::vector<opt::CalibrationCase>& cases,
                               const opt::CsCalibrationResult& r, double Cs_initial) {
  bool all_l = true;
  for (const auto& c : cases)
    for (const auto& p : c.points) all_l = all_l && p.has_lambda_over_L;
  auto xof = [&](const opt::TankRaoPoint& p) { return all_l ? p.lambda_over_L : p.omega_e_rad_s; };
  const std::string xlabel =
      all_l ? "wave length / ship length  λ/L [-]" : "encounter frequency  ω_e [rad/s]";

  const double width = kLeft + 2 * kPanelW + kGap + 30,
               height = kTop + kPanelH + kBottom + 22.0 * cases.size();
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<!-- hullopt calibrate: measured vs computed head-sea RAOs. heave |x3|/A [m/m], pitch |x5|/(kA) [-], "
       "k = omega^2/g. Computed values at the measured points. -->\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"" << width / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">Cs calibration ("
    << opt::ToString(r.mode) << "): measured (o), computed at Cs_initial = " << F(Cs_initial)
    << " (dashed) and at the fitted Cs (solid)</text>\n";

  for (int q = 0; q < 2; ++q) {
    const double x0 = kLeft + q * (kPanelW + kGap), y0 = kTop;
    // Ranges over everything drawn in the panel.
    double xmin = 1e300, xmax = -1e300, ymax = 0;
    for (std::size_t c = 0; c < cases.size(); ++c) {
      for (std::size_t i = 0; i < cases[c].points.size(); ++i) {
        const auto& p = cases[c].points[i];
        xmin = std::min(xmin, xof(p));
        xmax = std::max(xmax, xof(p));
        ymax =
            std::max({ymax, q == 0 ? p.heave_amp : p.pitch_amp,
                      std::abs(q == 0 ? r.predictions_before[c].heave[i] : r.predictions_before[c].pitch[i]),
                      std::abs(q == 0 ? r.predictions_after[c].heave[i] : r.predictions_after[c].pitch[i])});
      }
    }
    if (!(xmax > xmin)) {
      xmin -= 0.5;
      xmax += 0.5;
    }
    if (!(ymax > 0)) ymax = 1;
    const double xs = TickStep(xmin, xmax);
    const double xlo = std::floor(xmin / xs) * xs, xhi = std::ceil(xmax / xs) * xs;
    const double ys = TickStep(0, ymax * 1.05);
    const double yhi = std::ceil(ymax * 1.05 / ys) * ys;
    auto X = [&](double v) { return x0 + (v - xlo) / (xhi - xlo) * kPanelW; };
    auto Y = [&](double v) { return y0 + kPanelH - v / yhi * kPanelH; };

    s << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << kPanelW << "\" height=\"" << kPanelH
      << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (double t = xlo; t <= xhi + 1e-9 * xs; t += xs) {
      s << "<line x1=\"" << X(t) << "\" x2=\"" << X(t) << "\" y1=\"" << y0 << "\" y2=\"" << y0 + kPanelH
        << "\" stroke=\"#ddd\"/><text x=\"" << X(t) << "\" y=\"" << y0 + kPanelH + 16
        << "\" text-anchor=\"middle\">" << F(t) << "</text>\n";
    }
    for (double t = 0; t <= yhi + 1e-9 * ys; t += ys) {
      s << "<line x1=\"" << x0 << "\" x2=\"" << x0 + kPanelW << "\" y1=\"" << Y(t) << "\" y2=\"" << Y(t)
        << "\" stroke=\"#ddd\"/><text x=\"" << x0 - 6 << "\" y=\"" << Y(t) + 4 << "\" text-anchor=\"end\">"
        << F(t) << "</text>\n";
    }
    s << "<text x=\"" << x0 + kPanelW / 2 << "\" y=\"" << y0 + kPanelH + 36 << "\" text-anchor=\"middle\">"
      << xlabel << "</text>\n";
    s << "<text x=\"" << x0 + kPanelW / 2 << "\" y=\"" << y0 - 8
      << "\" text-anchor=\"middle\" font-size=\"14\">"
      << (q == 0 ? "heave |x3|/A [m/m]" : "pitch |x5|/(kA) [-]") << "</text>\n";

    for (std::size_t c = 0; c < cases.size(); ++c) {
      const char* col = kColours[c % 6];
      const auto& pts = cases[c].points;
      std::vector<std::size_t> order(pts.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(),
                [&](std::size_t a, std::size_t b) { return xof(pts[a]) < xof(pts[b]); });
      for (int stage = 0; stage < 2; ++stage) {
        const opt::RaoPrediction& pr = stage == 0 ? r.predictions_before[c] : r.predictions_after[c];
        s << "<polyline fill=\"none\" stroke=\"" << col << "\" stroke-width=\"" << (stage == 0 ? 1.2 : 2.0)
          << "\"" << (stage == 0 ? " stroke-dasharray=\"6,4\"" : "") << " points=\"";
        for (std::size_t i : order)
          s << X(xof(pts[i])) << "," << Y(std::abs(q == 0 ? pr.heave[i] : pr.pitch[i])) << " ";
        s << "\"/>\n";
      }
      for (std::size_t i : order) {
        s << "<circle cx=\"" << X(xof(pts[i])) << "\" cy=\""
          << Y(q == 0 ? pts[i].heave_amp : pts[i].pitch_amp) << "\" r=\"3.5\" fill=\"white\" stroke=\"" << col
          << "\" stroke-width=\"1.5\"/>\n";
      }
    }
  }
  // Legend: one line per case with its fitted Cs.
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const double y = kTop + kPanelH + 62 + 22.0 * c;
    s << "<line x1=\"" << kLeft << "\" x2=\"" << kLeft + 30 << "\" y1=\"" << y - 4 << "\" y2=\"" << y - 4
      << "\" stroke=\"" << kColours[c % 6] << "\" stroke-width=\"2\"/><text x=\"" << kLeft + 38 << "\" y=\""
      << y << "\">" << Escape(cases[c].label) << ": Cs = " << F(r.case_Cs[c]) << " ± "
      << F(r.case_Cs_std_error[c]) << " (1σ); rms residual " << F(r.rms_residual_before) << " → "
      << F(r.rms_residual) << " (all cases)</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace hullopt::io
