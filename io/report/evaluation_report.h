#pragma once
// Outputs of `hullopt evaluate` for a set of evaluated designs (docs/file-formats.md):
//   msi.csv       columns exactly design,Hs_m,Tz_s,position,x_from_cg_m,rms_accel_g,msi_pct; per design, per
//                 sea: forward, lcg, transom, user points, then mean (mean of the three standard positions;
//                 its x_from_cg_m is empty)
//   summary.json  conventions, MSI options, per design and sea: periods, peak ω_e, truncation, positions
//                 (rms g, g per m of Hs, MSI, characteristic frequency), mean MSI; warnings
//   plots         encounter_spectra.svg (Fig. 7), raos.svg (Figs. 8–9), accel_per_m.svg (Fig. 10),
//                 accel_per_m_vs_Hs.svg, msi_vs_Hs.svg (Fig. 11), msi_vs_<parameter>.svg (Figs. 12–14)
// The caller only supplies RaoTables: evaluate each with sk::EvaluateDesign, fill EvaluatedDesign, call
// WriteEvaluationOutputs.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "io/report/evaluated_design.h"

namespace hullopt::io {

struct EvaluationReportOptions {
  bool plots = true;
  /// Parameters (key in EvaluatedDesign::parameters, axis label) for the MSI-vs-parameter plots; a plot is
  /// written when at least one design has the parameter.
  std::vector<std::pair<std::string, std::string>> plot_parameters = {
      {"Fr", "Froude number Fr [-]"},
      {"Cvp", "vertical prismatic coefficient Cvp [-]"},
      {"B_over_T", "B/T [-]"}};
  /// A truncated wave-energy fraction above this is reported as a warning [-].
  double truncation_warning_fraction = 0.01;
};

/// The summary.json block of a resolution check (seas/resolution_check.h), fields as named there.
nlohmann::json ResolutionCheckJson(const sk::ResolutionCheck& r);

/// Writes msi.csv. Throws io::InputError if the file cannot be written.
void WriteMsiCsv(const std::string& path, const std::vector<EvaluatedDesign>& designs);
/// The summary.json document.
nlohmann::json EvaluationSummaryJson(const std::vector<EvaluatedDesign>& designs,
                                     const sk::EvaluationOptions& options,
                                     const std::vector<std::string>& warnings);
/// One line per design and sea whose RAO table leaves out more than the threshold of the wave energy.
std::vector<std::string> EvaluationWarnings(const std::vector<EvaluatedDesign>& designs,
                                            const EvaluationReportOptions& report = {});
/// Writes msi.csv, summary.json and (report.plots) the SVG plots into the existing folder dir. Returns the
/// names of the files written. Throws io::InputError on a write failure or an empty design list.
std::vector<std::string> WriteEvaluationOutputs(const std::string& dir,
                                                const std::vector<EvaluatedDesign>& designs,
                                                const sk::EvaluationOptions& options,
                                                const EvaluationReportOptions& report = {});

}  // namespace hullopt::io
