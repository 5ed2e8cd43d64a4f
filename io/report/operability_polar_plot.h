#pragma once
// The operability polar as naval architects read it: the ship's bow up, the direction the waves come from as
// the angle (head seas, β = 180°, at the top; beam seas from starboard, β = 90°, on the right; following
// seas at the bottom), the speed as the radius, and each (speed, heading) cell an annular sector coloured by
// its operability (red 0 % → yellow 50 % → green 100 %) with its value printed. Cells not computed (encounter
// frequency <= 0) are grey and hatched. Headings all within [0°, 180°] are mirrored to the port side (a
// port–starboard symmetric hull), which the figure says. Drawn directly in SVG: io/report/svg_plot.h has
// Cartesian axes only.
#include <string>
#include <vector>

#include "evaluation/operability_polar.h"

namespace hullopt::io {

/// The polar as an SVG document. notes: lines under the figure (criteria, scatter diagram).
std::string RenderOperabilityPolarSvg(const eval::OperabilityPolar& polar, const std::string& title,
                                      const std::vector<std::string>& notes);
/// Writes it atomically; throws InputError if it cannot be written.
void WriteOperabilityPolarSvg(const std::string& path, const eval::OperabilityPolar& polar,
                              const std::string& title, const std::vector<std::string>& notes);

}  // namespace hullopt::io
