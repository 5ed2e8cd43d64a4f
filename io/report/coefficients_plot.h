#pragma once
// coefficients.svg: A33, B33, A55, B55, A35, A53, B35, B53 and the exciting heave force and pitch moment
// (amplitude and phase, with the Froude–Krylov part) against ω_e √(L/g), optionally with measured points.
#include <string>
#include <vector>

#include "io/formats/measured_coefficients_csv.h"
#include "io/report/svg_plot.h"
#include "seakeeping/motions/rao_solver.h"

namespace hullopt::io {

/// One curve per table (labels name them; e.g. two methods). length_m [m] is the L of ω_e √(L/g).
PlotFigure CoefficientsFigure(const std::vector<sk::CoefficientTable>& curves,
                              const std::vector<std::string>& labels, double length_m, const std::string& title,
                              const MeasuredCoefficientPoints* measured = nullptr);

}  // namespace hullopt::io
