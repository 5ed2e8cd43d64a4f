#pragma once
// Evaluation of one design in a list of head seas: per sea and per passenger position the rms vertical
// acceleration and the MSI, and their mean over the three standard positions (forward, LCG, transom). This is
// what `hullopt evaluate` and the optimiser call with the RAOs of a design; it is cheap (one O(N) quadrature
// per sea, O(1) per position), so the 14-hull study costs milliseconds beyond the RAOs.
#include <string>
#include <vector>

#include "seas/motion_sickness.h"
#include "seas/passenger_positions.h"
#include "seas/point_response.h"
#include "seakeeping/motions/rao_table.h"
#include "seas/wave_spectrum.h"

namespace hullopt::sk {

struct EvaluationOptions {
  MsiOptions msi;
  ResponseOptions response;
  bool IsValid(std::string* error) const;
};

struct PositionResult {
  std::string position;             ///< forward, lcg, transom, a user name, or mean
  double x_from_cg_m = 0.0;         ///< [m] forward of the CG; NaN for the mean
  double rms_accel_m_s2 = 0.0;      ///< [m/s²] σ_a (mean row: mean of the three standard positions)
  double rms_accel_g = 0.0;         ///< [g] σ_a / g
  double rms_displacement_m = 0.0;  ///< [m] (mean row: mean of the three)
  double omega_char_rad_s = 0.0;    ///< [rad/s] MSI characteristic frequency (mean row: mean of the three)
  double msi_pct = 0.0;             ///< [%] (mean row: mean of the three standard positions)
};

struct SeaEvaluation {
  SeaState sea;                                 ///< as given
  double Tz_s = 0.0, Tp_s = 0.0;                ///< [s] both periods resolved
  double peak_omega_e_rad_s = 0.0;              ///< [rad/s] modal encounter frequency of the wave spectrum
  double truncated_wave_energy_fraction = 0.0;  ///< [-] wave variance outside the RAO table's range
  std::vector<PositionResult> positions;  ///< forward, lcg, transom, then user points in the given order
  PositionResult mean;                    ///< mean over forward, lcg, transom
};

struct DesignEvaluation {
  std::vector<SeaEvaluation> seas;  ///< in the order of the sea list
};

/// Evaluates one design (its RAOs at one speed) in each sea. hull gives the CG-to-transom distance (which
/// fixes the standard positions) and the bow limit for user points. Throws std::invalid_argument with a
/// one-line message for an empty sea list, an invalid sea, RAO table, hull extent, user point or options.
DesignEvaluation EvaluateDesign(const RaoTable& rao, const HullExtent& hull,
                                const std::vector<SeaState>& seas,
                                const std::vector<PassengerPosition>& user_points = {},
                                const EvaluationOptions& options = {});

/// The same with the spectra built once by the caller (optimiser loops: saves rebuilding the spectra).
DesignEvaluation EvaluateDesign(const RaoTable& rao, const HullExtent& hull,
                                const std::vector<WaveSpectrum>& spectra,
                                const std::vector<PassengerPosition>& user_points,
                                const EvaluationOptions& options);

/// Builds the spectra of a sea list; throws std::invalid_argument for an empty list or an invalid sea
/// ("seas[i]: ...").
std::vector<WaveSpectrum> BuildSpectra(const std::vector<SeaState>& seas);

}  // namespace hullopt::sk
