#pragma once
// Reading measured head-sea RAOs (docs/file-formats.md, tank RAO CSV): a header with at least `Fn`, either
// `omega_e_rad_s` or `lambda_over_L` (or both), `heave_rao` (|x3|/A [m/m]) and `pitch_rao`
// (|x5|/(kA) [rad/rad]);
// optional `heave_phase_deg` and `pitch_phase_deg` (lead positive, relative to the wave crest at the CG; an
// empty cell means "not measured"). Other columns are ignored; blank lines and lines starting with '#' are
// skipped.
#include <string>
#include <vector>

#include "optimizer/tank_rao_data.h"

namespace hullopt::io {

/// Reads one file. Throws InputError "file:line: column 'name' = value: rule" for a missing column, a row
/// with the wrong number of fields, a non-numeric or non-finite value, a negative RAO, Fn or frequency <= 0,
/// and "file: ..." for a missing or empty file (no header, or no data rows).
std::vector<opt::TankRaoPoint> ReadTankRaoCsv(const std::string& file);

/// Groups rows into one case per config speed, in the order of speeds_Fn. A row matches a speed when
/// |Fn − Fn_config| <= Fn_tolerance. Throws InputError naming the row (file:line) whose Fn is not a config
/// speed, and naming a config speed that has no rows. Labels are "Fn 0.75" or "<hull> Fn 0.75".
std::vector<opt::CalibrationCase> GroupTankRaoBySpeed(const std::vector<opt::TankRaoPoint>& points,
                                                      const std::vector<double>& speeds_Fn,
                                                      const std::string& hull_name, double hull_parameter,
                                                      double Fn_tolerance = 0.005);

}  // namespace hullopt::io
