#pragma once
// The seakeeping objective of a campaign: free design variables → parametric hull at fixed displacement →
// RAOs by the time-domain strip method → rms accelerations and MSI in the campaign's seas, and the calm-water
// resistance at the design speed, or the design's operability over a wave scatter diagram (seas/operability.h).
// io/config/msi_objective_config.h reads its options from a config.
//
// Quantities for constraints: L_m, B_m, T_m, B_overall_m, displacement_t, Cb, Cp, Cwp, Cvp, Fr, GM_T_m, GM_L_m,
// and the calm-water resistance at the design speed R_T_kN, R_W_kN, P_E_kW.
#include <memory>
#include <string>
#include <vector>

#include "evaluation/trial_design.h"
#include "optimizer/evaluator.h"
#include "resistance/calm_water_resistance.h"
#include "seas/design_evaluation.h"
#include "seas/operability.h"
#include "seas/resolution_check.h"

namespace hullopt::eval {

struct MsiObjectiveOptions {
  /// kScatterMsi: the scatter-weighted mean MSI [%] over `diagram` (Σ p MSI / Σ p at `position`);
  /// kDowntime: 100 - the percentage of time `criterion` is met on `diagram` [% of time], minimised.
  enum class Measure { kMsi, kRmsAccel, kEffectivePower, kScatterMsi, kDowntime };
  Measure measure = Measure::kMsi;  ///< MSI [%], rms vertical acceleration [g], P_E [kW] or operability
  int position = -1;                ///< -1: mean of the passenger positions; 0 forward, 1 LCG, 2 transom
  /// The seas of the per-sea values. For the operability measures: the diagram's cells (diagram.Sea(i)),
  /// weighted by their probabilities, and the per-sea values are the cells' MSI [%] at `position`.
  std::vector<sk::SeaState> seas;
  std::vector<double> sea_weights;  ///< one per sea, >= 0, not all 0
  sk::ScatterDiagram diagram;                      ///< operability measures only
  std::vector<sk::OperabilityCriterion> criteria;  ///< operability measures only
  int criterion = -1;                              ///< kDowntime: index into criteria; -1: all of them together
  sk::EvaluationOptions evaluation;
  res::ResistanceOptions resistance;
  /// Wave headings [deg] of measures kMsi and kRmsAccel (180 head seas, 90 beam seas from starboard) and their
  /// weights (>= 0, not all 0, normalised to sum 1; empty: equal weights). The per-sea value is Σ_h w_h v_h.
  /// Empty or {180}: head seas by the design's own solver (the time-domain strip method), bitwise the objective
  /// without headings. Any other list: every heading, 180 included, by the design's method in oblique seas
  /// (eval::SolveObliqueDesign: the time-domain strip method's periodic steady state, or the oblique-sea strip
  /// theory for solver.method strip_theory_stf; the design's Cs in heave and pitch) on eval::SeaFrequencies
  /// without adaptive refinement, the roll radius of gyration eval::DefaultRollRadiusOfGyration, potential
  /// roll damping (the vertical motions at the centreline positions of a port-starboard symmetric hull do not
  /// depend on roll), so that the headings are compared by one method. At speed a heading with encounter frequency <= 0 on the grid makes the design not
  /// produced (the config reader admits only headings in [90, 270] at speed).
  std::vector<double> headings_deg;
  std::vector<double> heading_weights;
  /// True when headings_deg asks for the oblique-sea path (anything but empty or {180}).
  bool Oblique() const;
  /// The rules of the headings and weights (each heading in [0, 360), none twice; weights one per heading,
  /// >= 0, not all 0; headings only with kMsi or kRmsAccel) and of sea_weights (one per sea, >= 0, not all 0);
  /// the error names the field and the value.
  bool IsValid(std::string* error) const;
};

/// A campaign objective whose design at x can be re-run at a finer strip resolution (the best design's check).
class ResolutionCheckable {
 public:
  virtual ~ResolutionCheckable() = default;
  /// The design at x computed at its own resolution and at factor x its sections and panels, compared on the
  /// campaign's frequencies and seas. Throws InputError when x gives no design or the check cannot be made.
  virtual sk::ResolutionCheck CheckResolution(const std::vector<double>& x, int factor,
                                              const sk::ResolutionCheckOptions& options) = 0;
};

/// The evaluator of the campaign variables `variables` (in order) about the base design; it is also a
/// ResolutionCheckable.
std::unique_ptr<opt::Evaluator> MakeMsiEvaluator(DesignBasis basis, const std::vector<std::string>& variables,
                                                 MsiObjectiveOptions options);

/// Builds the base design of an evaluator made by MakeMsiEvaluator (the config's own values, the mass of a
/// config without `mass:`) as a single design is built: its refusals (the generator, the envelope, the
/// calm-water attitude) are the config's. Called once the whole config has been read; nothing for another
/// evaluator.
void CheckBaseDesign(const opt::Evaluator& evaluator);

}  // namespace hullopt::eval
