#pragma once
// The seakeeping verdict in report.html (design, evaluate, optimize, explore): the criteria with their
// sources, a summary of the Hs up to which each design meets each criterion, and per design a matrix of
// criteria × seas with the value, the margin to the limit and whether it holds.
#include <string>
#include <vector>

#include "evaluation/seakeeping_criteria.h"
#include "io/report/html_report.h"

namespace hullopt::io {

struct JudgedDesign {
  std::string name;
  const eval::SeakeepingVerdict* verdict = nullptr;
};

/// Highest Hs [m] up to which every sea meets criterion c (0 when the lowest sea fails; NaN when not judged).
double CriterionLimitingHs(const eval::SeakeepingVerdict& v, std::size_t c);

/// One line per design: "NAME meets every criterion up to Hs X m; fails: ...", for stderr and lists.
std::string VerdictLine(const std::string& name, const eval::CriteriaSet& set, const eval::SeakeepingVerdict& v);

/// Appends the verdict section: heading, the criteria table, the summary table (designs × criteria:
/// limiting Hs; with one or two designs a verdict line each above it) and, when `matrices`, one criteria ×
/// seas matrix per design.
void AddVerdictSection(HtmlReport& report, const eval::CriteriaSet& set, const std::vector<JudgedDesign>& designs,
                       bool matrices = true);

}  // namespace hullopt::io
