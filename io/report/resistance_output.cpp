#include "io/report/resistance_output.h"

#include <cmath>
#include <fstream>
#include <iomanip>

#include "io/formats/input_error.h"
#include "io/config/speed_config.h"

namespace hullopt::io {

void WriteResistanceCsv(const std::string& path, const std::vector<res::ResistanceAtSpeed>& rows,
                        const std::vector<std::string>& header) {
  std::ofstream f(path);
  if (!f) throw InputError("cannot write " + path);
  for (const auto& h : header) f << "# " << h << "\n";
  f << "speed_kn,speed_m_s,Fn,Re,C_F,S_m2,R_F_kN,R_V_kN,R_W_kN,R_H_kN,R_T_kN,C_W,C_T,P_E_kW,transom_Fn,"
       "wave_tail_bound_kN,warning\n";
  f << std::setprecision(8);
  for (const auto& r : rows) {
    const double v[] = {r.U_m_s / kMetresPerSecondPerKnot, r.U_m_s, r.Fn, r.Re, r.C_F, r.S_m2, r.R_F_N / 1e3,
                        r.R_V_N / 1e3, r.R_W_N / 1e3, r.R_H_N / 1e3, r.R_T_N / 1e3, r.C_W, r.C_T, r.P_E_W / 1e3,
                        r.transom_Fn, r.wave_tail_bound_N / 1e3};
    for (double x : v) {
      if (!std::isfinite(x)) throw InputError(path + ": a non-finite resistance value at U = " + std::to_string(r.U_m_s) + " m/s");
      f << x << ",";
    }
    std::string w = r.warning;
    for (char& c : w)
      if (c == ',') c = ';';
    f << w << "\n";
  }
  if (!f) throw InputError("cannot write " + path);
}

PlotFigure ResistanceFigure(const std::vector<res::ResistanceAtSpeed>& rows, const std::string& title,
                            const std::string& footnote) {
  std::vector<double> kn, fn, rf, rv, rw, rh, rt, pe, ct, cv, cw;
  for (const auto& r : rows) {
    kn.push_back(r.U_m_s / kMetresPerSecondPerKnot);
    fn.push_back(r.Fn);
    rf.push_back(r.R_F_N / 1e3);
    rv.push_back(r.R_V_N / 1e3);
    rw.push_back(r.R_W_N / 1e3);
    rh.push_back(r.R_H_N / 1e3);
    rt.push_back(r.R_T_N / 1e3);
    pe.push_back(r.P_E_W / 1e3);
    ct.push_back(r.C_T * 1e3);
    cv.push_back(r.R_V_N / r.R_T_N * r.C_T * 1e3);
    cw.push_back(r.C_W * 1e3);
  }
  PlotFigure fig;
  fig.title = title;
  fig.footnote = footnote;
  PlotPanel& a = fig.AddPanel("Resistance components", "speed [kn]", "R [kN]");
  a.y_include_zero = true;
  a.series.push_back(PlotSeries::LineMarkers("R_T", kn, rt));
  a.series.push_back(PlotSeries::Line("(1+k) R_F", kn, rv));
  a.series.push_back(PlotSeries::Line("R_W (Michell)", kn, rw));
  a.series.push_back(PlotSeries::Line("R_h (dry transom)", kn, rh));
  PlotPanel& b = fig.AddPanel("Effective power", "speed [kn]", "P_E [kW]");
  b.y_include_zero = true;
  b.series.push_back(PlotSeries::LineMarkers("P_E = R_T U", kn, pe));
  PlotPanel& c = fig.AddPanel("Coefficients on ½ρU²S", "Fn [-]", "C × 1000");
  c.y_include_zero = true;
  c.series.push_back(PlotSeries::LineMarkers("C_T", fn, ct));
  c.series.push_back(PlotSeries::Line("(1+k) C_F", fn, cv));
  c.series.push_back(PlotSeries::Line("C_W", fn, cw));
  return fig;
}

}  // namespace hullopt::io
