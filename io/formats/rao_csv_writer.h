#pragma once
// rao.csv (docs/file-formats.md): columns exactly
//   omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg
// after '#' comment lines stating the conventions. heave_amp = |X3|/A [m/m], pitch_amp = |X5|/(kA) [rad/rad],
// k = ω²/g; phases in degrees in (−180, 180], lead positive, relative to the wave crest at the CG.
#include <string>
#include <vector>

#include "seakeeping/motions/rao_table.h"

namespace hullopt::io {

/// The file text. notes: extra comment lines (hull, speed, method, Cs, ...), written after the conventions.
/// length_m [m] is the L of λ/L. Throws std::domain_error naming the row's frequencies if any value is not
/// finite (never writes NaN), std::invalid_argument if the table's columns differ in length or L <= 0.
std::string FormatRaoCsv(const sk::RaoTable& table, double length_m, const std::vector<std::string>& notes);

/// Writes FormatRaoCsv to path. Throws InputError if the file cannot be written.
void WriteRaoCsv(const std::string& path, const sk::RaoTable& table, double length_m,
                 const std::vector<std::string>& notes);

}  // namespace hullopt::io
