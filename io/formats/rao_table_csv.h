#pragma once
// Reading a rao.csv (the `hullopt rao` output, docs/file-formats.md) back into a RaoTable:
//   omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg
// Columns are found by name (any order, extra columns ignored, lines starting with '#' skipped); heave_amp is
// |x3|/A, pitch_amp |x5|/(kA), phases in degrees (lead positive). The speed is recovered from
// ω_e = ω + ω²U/g and must be the same on every row.
#include <string>

#include "seakeeping/motions/rao_table.h"

namespace hullopt::io {

/// Throws io::InputError "file:line: ..." for a missing file, a missing column, a non-numeric or non-finite
/// value, fewer than 2 rows, ω not increasing, or rows that imply different speeds.
sk::RaoTable ReadRaoTableCsv(const std::string& path, double g_m_s2 = 9.81);

}  // namespace hullopt::io
