#pragma once
// Body plan as naval architects draw it: looking from ahead, ship centreline in the middle, sections aft of
// midships on the left half, forward of midships on the right half, design waterline and baseline marked. For
// multihulls every body is drawn at its lateral position (a catamaran shows the aft sections in the left
// demihull and the forward sections in the right one).
#include <string>

#include "parametric_hull/hull_form.h"

namespace hullopt::io {

/// Writes the SVG; throws InputError if it cannot be written.
void WriteBodyPlanSvg(const std::string& path, const hull::HullForm& hull, const std::string& title);

}  // namespace hullopt::io
