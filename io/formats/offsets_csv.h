#pragma once
// Offsets CSV (docs/file-formats.md): header x_m,y_m,z_m (further columns ignored), one row per point, the
// points of one station consecutive from the keel (y = 0) up to the deck edge; x from the AP forward, z from
// the baseline up, y >= 0 half-breadth. The design draught comes from the config.
#include <string>

#include "parametric_hull/hull_form.h"

namespace hullopt::io {

/// Reads one demihull's stations. draught_m [m] is used to check that every wetted station crosses the
/// waterline. Throws InputError "file:line: rule" for a missing file, a bad header, a malformed row (fewer
/// than 3 fields), a non-numeric or non-finite value, y < 0, a station not starting on the centreline, z
/// decreasing along a station, stations out of order or repeated, a station with fewer than 2 points, a
/// wetted station whose top is below the waterline (no waterline crossing), or no wetted station at all.
hull::Demihull ReadOffsetsCsv(const std::string& path, double draught_m);

/// Writes every body of the hull: columns x_m,y_m,z_m,body,y_centre_m (x from AP, y from the body's own
/// centreline, z from the baseline). Throws InputError if the file cannot be written.
void WriteOffsetsCsv(const std::string& path, const hull::HullForm& hull);

}  // namespace hullopt::io
