#pragma once
// resistance.csv and resistance.svg of `hullopt resistance`.
#include <string>
#include <vector>

#include "io/report/svg_plot.h"
#include "resistance/calm_water_resistance.h"

namespace hullopt::io {

/// Writes one row per speed: speed_kn,speed_m_s,Fn,Re,C_F,S_m2,R_F_kN,R_V_kN,R_W_kN,R_H_kN,R_T_kN,C_W,C_T,
/// P_E_kW,transom_Fn,wave_tail_bound_kN,warning after `#` header lines. Throws InputError if a value is not
/// finite (never written) or the file cannot be written.
void WriteResistanceCsv(const std::string& path, const std::vector<res::ResistanceAtSpeed>& rows,
                        const std::vector<std::string>& header);

/// Two panels against speed [kn]: the resistance components [kN] and P_E [kW]; C_T, C_F(1+k), C_W against Fn.
PlotFigure ResistanceFigure(const std::vector<res::ResistanceAtSpeed>& rows, const std::string& title,
                            const std::string& footnote);

}  // namespace hullopt::io
