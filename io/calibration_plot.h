#pragma once
// Measured vs computed RAOs before and after the Cs fit, as an SVG with a heave and a pitch panel. A minimal,
// self-contained writer: the general io/svg_plot (branch `seas`) was not on main when this was written.
#include <string>
#include <vector>

#include "optimizer/cs_calibration.h"

namespace hullopt::io {

/// SVG text: per case, measured magnitudes (circles), computed at Cs_initial (dashed) and at the fitted Cs
/// (solid), at the measured points, against λ/L when every case has it, else ω_e [rad/s].
std::string CalibrationPlotSvg(const std::vector<opt::CalibrationCase>& cases,
                               const opt::CsCalibrationResult& r, double Cs_initial);

}  // namespace hullopt::io
