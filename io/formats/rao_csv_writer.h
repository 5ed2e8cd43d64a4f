#pragma once
// rao.csv (docs/file-formats.md): columns exactly
//   omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg
// after '#' comment lines stating the conventions. heave_amp = |X3|/A [m/m], pitch_amp = |X5|/(kA) [rad/rad],
// k = ω²/g; phases in degrees in (−180, 180], lead positive, relative to the wave crest at the CG.
#include <string>
#include <vector>

#include "seakeeping/motions/oblique_strip_theory.h"
#include "seakeeping/motions/rao_table.h"

namespace hullopt::io {

/// The file text. notes: extra comment lines (hull, speed, method, Cs, ...), written after the conventions.
/// length_m [m] is the L of λ/L. Throws std::domain_error naming the row's frequencies if any value is not
/// finite (never writes NaN), std::invalid_argument if the table's columns differ in length or L <= 0.
std::string FormatRaoCsv(const sk::RaoTable& table, double length_m, const std::vector<std::string>& notes);

/// Writes FormatRaoCsv to path. Throws InputError if the file cannot be written.
void WriteRaoCsv(const std::string& path, const sk::RaoTable& table, double length_m,
                 const std::vector<std::string>& notes);

/// rao.csv of `hullopt rao` with solver.headings_deg (docs/file-formats.md): one row per (heading,
/// frequency), heading-major, columns exactly
///   wave_direction_deg,omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg,
///   sway_amp,sway_phase_deg,roll_amp,roll_phase_deg,yaw_amp,yaw_phase_deg
/// (the oblique axes of docs/conventions.md: sway + to port, roll + starboard down, yaw + bow to port;
/// translations per A, rotations per kA). Same throws as FormatRaoCsv.
std::string FormatObliqueRaoCsv(const sk::ObliqueStripResult& result, double speed_m_s, double g_m_s2,
                                double length_m, const std::vector<std::string>& notes);

/// Writes FormatObliqueRaoCsv to path. Throws InputError if the file cannot be written.
void WriteObliqueRaoCsv(const std::string& path, const sk::ObliqueStripResult& result, double speed_m_s,
                        double g_m_s2, double length_m, const std::vector<std::string>& notes);

}  // namespace hullopt::io
