#pragma once
// Operability of a design on a route: its MSI and rms vertical accelerations in every cell of a wave scatter
// diagram (Hs × Tz or Hs × Tp, probability of occurrence per cell), the scatter-weighted mean MSI, and the
// percentage of time each criterion is met (an MSI limit at a position, rms vertical acceleration limits at a
// position as in NORDFORSK 1987, or user limits). Head seas at the design speed, like EvaluateDesign.
#include <string>
#include <vector>

#include "seas/design_evaluation.h"

namespace hullopt::sk {

/// Largest |Σ p - 1| accepted for a scatter diagram: a table printed in parts per thousand with some 50-100
/// non-empty cells rounds each by up to 0.5 ‰, so a correct table can miss 1 by a few per mille.
constexpr double kScatterProbabilitySumTol = 0.005;

struct ScatterCell {
  double Hs_m = 0.0;         ///< [m] cell centre
  double period_s = 0.0;     ///< [s] cell centre, Tz or Tp by the diagram
  double probability = 0.0;  ///< [-] fraction of time, >= 0
};

struct ScatterDiagram {
  bool period_is_tp = false;  ///< false: the period is Tz; true: Tp
  SpectrumType spectrum = SpectrumType::kJonswap;
  double gamma = 3.3;               ///< JONSWAP peak enhancement (1 for Bretschneider)
  std::vector<ScatterCell> cells;   ///< cells with probability > 0 (empty cells may be left out)
  /// Probabilities >= 0 summing to 1 within kScatterProbabilitySumTol, at least one cell, and every cell a valid
  /// sea (Hs, the period within the spectrum's 2-25 s Tz range). Writes "cell i (Hs .., T ..): rule".
  bool IsValid(std::string* error) const;
  /// The sea state of cell i.
  SeaState Sea(size_t i) const;
};

/// One criterion: a limit on MSI [%] or on the rms vertical acceleration [g] at a position (forward, lcg,
/// transom, a user point, or mean = mean of the three standard positions).
struct OperabilityCriterion {
  std::string name;               ///< for reports, e.g. nordforsk_transit_passengers
  std::string position = "mean";
  bool is_msi = true;             ///< true: MSI [%]; false: rms vertical acceleration [g]
  double limit = 0.0;             ///< [%] or [g], > 0
};

/// NORDFORSK (1987) rms vertical acceleration limits by activity, as quoted in the seakeeping literature (e.g.
/// Faltinsen 2005, "Hydrodynamics of high-speed marine vehicles", ch. 1; not checked against the report
/// itself): light manual work 0.20 g, heavy manual work 0.15 g, intellectual work 0.10 g, transit passengers
/// 0.05 g, cruise liner 0.02 g. Returns false for another name.
bool NordforskLimit(const std::string& activity, double* rms_g);

struct CellResult {
  ScatterCell cell;
  SeaEvaluation evaluation;          ///< MSI and accelerations at every position
  std::vector<bool> criterion_met;   ///< per criterion
};

struct OperabilityResult {
  std::vector<CellResult> cells;
  double weighted_mean_msi_pct = 0.0;            ///< Σ p MSI_mean / Σ p
  std::vector<double> criterion_time_pct;        ///< per criterion: 100 Σ_met p / Σ p
  double all_criteria_time_pct = 0.0;            ///< time with every criterion met
};

/// Evaluates the design in every cell. Throws std::invalid_argument for an invalid diagram, a criterion
/// without a valid limit or at an unknown position, or what EvaluateDesign refuses.
OperabilityResult EvaluateOperability(const RaoTable& rao, const HullExtent& hull, const ScatterDiagram& diagram,
                                      const std::vector<OperabilityCriterion>& criteria,
                                      const std::vector<PassengerPosition>& user_points = {},
                                      const EvaluationOptions& options = {});

}  // namespace hullopt::sk
