#pragma once
// Seakeeping criteria and the verdict of a design against them: per sea state, each criterion's value at its
// location, its limit, whether it holds and the margin. The criteria are data (data/criteria/*.csv, read by
// io/formats/criteria_csv.h); this is the computation. Head seas, linear: rms vertical accelerations and MSI from the
// design evaluation, slamming and deck-wetness probabilities from the relative motion at the bow
// (seas/relative_motion.h) with the draught and freeboard of the hull at the station (at rest, even keel).
#include <string>
#include <vector>

#include "evaluation/design_case.h"
#include "seas/design_evaluation.h"

namespace hullopt::eval {

enum class CriterionQuantity {
  kRmsVerticalAcceleration,  ///< [g]
  kMsi,                      ///< [%]
  kSlammingProbability,      ///< [-] per encounter, Ochi
  kDeckWetnessProbability    ///< [-] per encounter
};

/// The quantity's name in criteria files: rms_vertical_acceleration, msi, slamming_probability,
/// deck_wetness_probability.
std::string CriterionQuantityName(CriterionQuantity q);
/// The unit a criteria file must give for the quantity: g, %, -.
std::string CriterionQuantityUnit(CriterionQuantity q);
/// false for an unknown name.
bool ParseCriterionQuantity(const std::string& name, CriterionQuantity* q);

struct SeakeepingCriterion {
  std::string name;  ///< e.g. fp_vertical_acceleration
  CriterionQuantity quantity = CriterionQuantity::kRmsVerticalAcceleration;
  /// fp, x_over_L=V (0 ≤ V ≤ 1, from the AP), forward, lcg, transom, a user position, or mean. MSI only at a
  /// passenger position or mean; probabilities only at fp or x_over_L=V.
  std::string location;
  double limit = 0.0;  ///< in the quantity's unit, > 0 (probabilities ≤ 1)
  std::string source;  ///< where the limit comes from, for reports
  /// The rules above; the error names the criterion, the field and the rule.
  bool IsValid(std::string* error) const;
};

struct CriteriaSet {
  std::string title;  ///< e.g. "NORDFORSK 1987 (fast small craft)"
  std::string file;   ///< where it was read from, for reports
  std::vector<SeakeepingCriterion> criteria;
};

/// Keel and deck-edge heights of the main body along its length, for the draught and freeboard at a station.
/// Empty (known() false) for a design known only by its RAOs: the probability criteria are then not judged.
struct BowGeometry {
  std::vector<double> x_over_L;   ///< [-] station positions from the AP, increasing
  std::vector<double> keel_z_m;   ///< [m] lowest point of each station above the baseline
  std::vector<double> deck_z_m;   ///< [m] deck edge (top of the station contour) above the baseline
  double waterline_z_m = 0.0;     ///< [m] design waterline above the baseline
  double length_m = 0.0;          ///< [m] L (AP to FP)
  bool known() const { return x_over_L.size() >= 2; }
  /// Draught and freeboard at x/L (linear between stations, the end values beyond), [m]; either may be ≤ 0
  /// (a station clear of the water, a deck edge below the waterline).
  double DraughtAt(double x_over_L) const;
  double FreeboardAt(double x_over_L) const;
};
/// The main body's geometry of a design (at rest, even keel).
BowGeometry BowGeometryOf(const DesignCase& design);

struct CriterionCheck {
  double x_from_cg_m = 0.0;   ///< [m] NaN for mean
  double value = 0.0;         ///< in the criterion's unit; NaN when not judged
  bool judged = true;         ///< false: the value could not be computed (reason in note)
  bool met = false;
  /// (limit − value)/limit [-]: > 0 holds with that fraction to spare, < 0 exceeds by it.
  double margin = 0.0;
  double events_per_hour = 0.0;  ///< [1/h] probabilities: slams or wet decks per hour; else 0
  std::string note;              ///< e.g. "draught 0.41 m, v_th 1.9 m/s"
};

struct SeaVerdict {
  double Hs_m = 0.0, Tz_s = 0.0;
  std::vector<CriterionCheck> checks;  ///< one per criterion, in the set's order
  bool all_met = false;                ///< every judged criterion holds
};

struct SeakeepingVerdict {
  std::vector<SeaVerdict> seas;  ///< in the order of the evaluation's seas
  /// Highest Hs of the sea list up to which every sea meets every judged criterion [m]; 0 when the first fails.
  double limiting_Hs_m = 0.0;
};

/// Judges a design (its RAO table, extent, evaluation in its seas, bow geometry) against the criteria.
/// Throws std::invalid_argument for an invalid criterion or a location the design does not have.
SeakeepingVerdict JudgeDesign(const sk::RaoTable& rao, const sk::HullExtent& hull,
                              const sk::DesignEvaluation& evaluation, const BowGeometry& geometry,
                              const CriteriaSet& criteria, const sk::ResponseOptions& response = {});

}  // namespace hullopt::eval
