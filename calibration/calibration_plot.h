#pragma once
// Measured vs computed RAOs before and after the Cs fit: a heave and a pitch panel drawn with
// io/report/svg_plot.
#include <string>
#include <vector>

#include "io/report/svg_plot.h"
#include "calibration/fit/cs_calibration.h"

namespace hullopt::calib {

/// Per case: measured magnitudes (hollow circles), computed at Cs_initial (dashed) and at the fitted Cs
/// (solid), at the measured points, against λ/L when every case has it, else ω_e [rad/s].
io::PlotFigure CalibrationPlot(const std::vector<opt::CalibrationCase>& cases, const CsCalibrationResult& r,
                           double Cs_initial);

}  // namespace hullopt::calib
