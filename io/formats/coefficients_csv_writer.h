#pragma once
// coefficients.csv: the heave–pitch coefficients of `hullopt coefficients`, one row per frequency, after '#'
// lines stating the conventions (sk::HeadSeaCoefficients). Columns:
//   omega_e_rad_s, omega_rad_s, lambda_over_L, omega_e_sqrt_L_over_g,
//   A33_kg, B33_kg_per_s, A35_kg_m, B35_kg_m_per_s, A53_kg_m, B53_kg_m_per_s, A55_kg_m2, B55_kg_m2_per_s,
//   C33_N_per_m, C35_N_per_rad, C53_N, C55_N_m_per_rad,
//   then for F3 [N per m of wave amplitude] and F5 [N m per m]: total, Froude–Krylov (FK), diffraction (diff)
//   and the Cs damping part (Cs), each as _amp and _phase_deg: F3_amp_N_per_m, F3_phase_deg, F3_FK_amp_N_per_m,
//   ..., F5_Cs_phase_deg.
// Phases in degrees in (−180, 180], lead positive, relative to the wave crest at the CG.
#include <string>
#include <vector>

#include "seakeeping/motions/rao_solver.h"

namespace hullopt::io {

/// The file text; notes are extra '#' lines. length_m [m] is the L of λ/L and ω_e √(L/g). Throws
/// std::domain_error naming the frequency if any value is not finite (never writes NaN).
std::string FormatCoefficientsCsv(const sk::CoefficientTable& table, double length_m,
                                  const std::vector<std::string>& notes);

/// Writes FormatCoefficientsCsv to path. Throws InputError if the file cannot be written.
void WriteCoefficientsCsv(const std::string& path, const sk::CoefficientTable& table, double length_m,
                          const std::vector<std::string>& notes);

}  // namespace hullopt::io
