#pragma once
// One design after evaluation: what the writers of msi.csv, summary.json and the seakeeping plots need.
#include <map>
#include <optional>
#include <string>

#include "seakeeping/motions/rao_table.h"
#include "seas/design_evaluation.h"
#include "seas/passenger_positions.h"
#include "seas/resolution_check.h"

namespace hullopt::io {

struct EvaluatedDesign {
  std::string name;                          ///< design name (msi.csv `design` column)
  std::string group;                         ///< plot panel, e.g. "catamaran"; empty = one panel for all
  std::map<std::string, double> parameters;  ///< e.g. Fr, Cvp, B_over_T: x axes of the MSI-vs-parameter plots
  sk::RaoTable rao;
  sk::HullExtent hull;
  sk::DesignEvaluation evaluation;  ///< sk::EvaluateDesign(rao, hull, seas, ...)
  /// How to widen the RAO frequency range, for warnings: names the key that sets it (solver.frequencies of the
  /// design config) or the RAO file to recompute.
  std::string frequency_advice;
  /// The design re-run at a finer strip resolution (resolution_check: enabled); absent when not checked.
  std::optional<sk::ResolutionCheck> resolution;
};

}  // namespace hullopt::io
