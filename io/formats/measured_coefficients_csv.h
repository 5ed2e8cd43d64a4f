#pragma once
// Measured forced-oscillation coefficients and restrained-model wave loads (the Delft 372 tables of
// data/delft372, SOURCE.md) for comparison with `hullopt coefficients`.
//
// Forced heave file: columns Fn, trim_sinkage, omega_nondim_sqrtLg (ω_e √(L/g)), A33_kg, A53_kg_m,
// B33_kg_per_s, B53_kg_m_per_s. Forced pitch file: Fn, trim_sinkage, omega_nondim_sqrtLg, A55_kg_m2, A35_kg_m,
// B55_kg_m2_per_s, B35_kg_m_per_s. Wave loads: Fn, lambda_over_L, wave_amp_mm, F3a_N, F3_phase_deg, F5a_Nm,
// F5_phase_deg and an optional `note` (a row with a note is a doubtful row and is left out). Fields may be
// quoted ("a, b"); other columns are ignored; blank lines and '#' lines are skipped. All values are as
// printed: dimensional, whole model, the report's own signs and phase reference (docs/coefficients.md states
// how they relate to hullopt's).
#include <string>
#include <vector>

namespace hullopt::io {

struct MeasuredCoefficientRow {
  double Fn = 0.0;
  std::string trim_sinkage;      ///< "zero" or the attitude label of the file
  double omega_nondim = 0.0;     ///< ω_e √(L/g)
  double a_diag = 0.0, a_cross = 0.0;  ///< A33, A53 (heave file) or A55, A35 (pitch file)
  double b_diag = 0.0, b_cross = 0.0;  ///< B33, B53 or B55, B35
};

struct MeasuredWaveLoadRow {
  double Fn = 0.0, lambda_over_L = 0.0, wave_amp_m = 0.0;
  double F3_N = 0.0, F3_phase_deg = 0.0, F5_N_m = 0.0, F5_phase_deg = 0.0;
};

/// dof 3: the forced heave file; dof 5: the forced pitch file. Throws InputError "file:line: column 'c' = v:
/// rule" for a missing column, a wrong field count or a non-numeric or non-finite value, and "file: ..." for
/// a missing or empty file.
std::vector<MeasuredCoefficientRow> ReadForcedOscillationCsv(const std::string& file, int dof);

/// Rows with a non-empty `note` are skipped; *skipped (if given) counts them. Throws as above, and for an
/// amplitude or wave amplitude <= 0.
std::vector<MeasuredWaveLoadRow> ReadRestrainedWaveLoadCsv(const std::string& file, int* skipped = nullptr);

/// Measured points in hullopt's axes and units (per unit wave amplitude for the loads); x = ω_e √(L/g).
/// Empty vectors = not measured.
struct MeasuredCoefficientPoints {
  std::string label;
  std::vector<double> heave_x, A33, B33, A53, B53;  ///< forced heave
  std::vector<double> pitch_x, A55, B55, A35, B35;  ///< forced pitch
  std::vector<double> load_x, F3_amp, F3_phase_deg, F5_amp, F5_phase_deg;  ///< restrained model
};

/// The measured rows of one speed (|Fn − Fn_run| <= 0.005) and attitude label (e.g. "zero") in hullopt's axes
/// and phase reference (MeasuredConvention below), loads divided by each run's wave amplitude, wave loads
/// placed at ω_e √(L/g) of their λ/L at speed U. Any of the row lists may be empty.
MeasuredCoefficientPoints MeasuredPointsForSpeed(const std::vector<MeasuredCoefficientRow>& heave,
                                                 const std::vector<MeasuredCoefficientRow>& pitch,
                                                 const std::vector<MeasuredWaveLoadRow>& loads, double Fn,
                                                 const std::string& trim_sinkage, double speed_m_s,
                                                 double g_m_s2, double length_m);

}  // namespace hullopt::io
