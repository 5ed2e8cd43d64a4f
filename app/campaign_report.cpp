#include "app/campaign_report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/output_dir.h"
#include "app/single_design.h"
#include "evaluation/seakeeping_criteria.h"
#include "io/report/bodyplan_svg.h"
#include "io/formats/criteria_csv.h"
#include "io/report/evaluation_report.h"
#include "io/report/html_report.h"
#include "io/report/rao_plot.h"
#include "io/report/verdict_report.h"
#include "io/config/yaml_map.h"

namespace hullopt::app {
namespace {


SingleDesign Evaluate(const std::string& file, const std::string& name, const std::string& command) {
  io::YamlMap root = io::YamlMap::LoadFile(file);
  return EvaluateSingleDesign(root, name, command, /*strict=*/false);
}

}  // namespace

void WriteCampaignReport(const std::string& out, const std::string& command, const std::string& config_file,
                         const std::vector<std::string>& campaign_warnings,
                         const std::vector<std::string>& active_set) {
  // A campaign over an analytic objective has no hull: no design to report.
  if (!io::YamlMap::LoadFile(config_file).Has("hull")) return;
  const SingleDesign base = Evaluate(config_file, "baseline", command);
  const SingleDesign best = Evaluate(OutPath(out, "best.yaml"), "best", command);
  io::HtmlReport r("hullopt " + command + ": baseline and best design");
  r.Paragraph("Campaign config " + config_file + "; best design from best.yaml in " + out +
              ". Both designs evaluated once for this report on the design frequency grid; the campaign's "
              "objective values are in summary.json and history.csv.");
  r.Heading("Warnings");
  std::vector<std::string> warnings = campaign_warnings;
  for (const auto* s : {&base, &best}) {
    io::EvaluatedDesign d = s->evaluated;
    for (const auto& w : io::EvaluationWarnings({d})) warnings.push_back(w);
  }
  r.List(warnings, "No warnings.");
  r.Heading("Defaults taken (both designs)");
  r.List(base.notes, "No defaults taken.");

  // The verdict of both designs: the baseline is the reference the best is judged against.
  const eval::CriteriaSet& criteria = io::DefaultCriteria();
  auto judge = [&](const SingleDesign& s) {
    return eval::JudgeDesign(s.evaluated.rao, s.evaluated.hull, s.evaluated.evaluation,
                             eval::BowGeometryOf(s.design), criteria, s.options.response);
  };
  const eval::SeakeepingVerdict vbase = judge(base), vbest = judge(best);
  io::AddVerdictSection(r, criteria, {{"baseline", &vbase}, {"best", &vbest}});

  if (command == "optimize") {
    r.Heading("Active set at the best design");
    r.List(active_set, "No design variable at a bound and no constraint active: the optimum is interior.");
    if (!active_set.empty())
      r.Paragraph("A bound's gain is a one-sided finite difference: the best design re-evaluated with the "
                  "variable 1 % of its range beyond the bound (negative = a lower objective). A constraint's gain "
                  "is not computed; an optimize run with the limit moved gives it.");
  }

  r.Heading("Hydrostatics and variables");
  const auto& hb = base.design.hydrostatics;
  const auto& hs = best.design.hydrostatics;
  auto row = [](const std::string& q, double a, double b, const std::string& unit) {
    return std::vector<std::string>{q, io::FormatNumber(a), io::FormatNumber(b), unit};
  };
  r.Table({"quantity", "baseline", "best", "unit"},
          {row("L", hb.L_m, hs.L_m, "m"), row("B", hb.B_m, hs.B_m, "m"), row("T", hb.T_m, hs.T_m, "m"),
           row("L/B", hb.L_m / hb.B_m, hs.L_m / hs.B_m, "-"), row("B/T", hb.B_m / hb.T_m, hs.B_m / hs.T_m, "-"),
           row("displacement", hb.displacement_t, hs.displacement_t, "t"), row("Cb", hb.Cb, hs.Cb, "-"),
           row("Cp", hb.Cp, hs.Cp, "-"), row("Cwp", hb.Cwp, hs.Cwp, "-"), row("Cvp", hb.Cvp, hs.Cvp, "-"),
           row("LCB", hb.LCB_pct_L, hs.LCB_pct_L, "% L"), row("LCF", hb.LCF_pct_L, hs.LCF_pct_L, "% L"),
           row("Fn", base.evaluated.parameters.at("Fr"), best.evaluated.parameters.at("Fr"), "-")});

  r.Heading("Body plans");
  io::WriteBodyPlanSvg(OutPath(out, "baseline_bodyplan.svg"), base.design.hull, "baseline");
  io::WriteBodyPlanSvg(OutPath(out, "best_bodyplan.svg"), best.design.hull, "best");
  r.SvgRow({io::ReadSvgFile(OutPath(out, "baseline_bodyplan.svg")), io::ReadSvgFile(OutPath(out, "best_bodyplan.svg"))},
           {"baseline", "best"});
  r.Heading("Heave and pitch RAOs (lambda/L on the baseline's L)");
  io::WriteSvg(io::RaoFigure({base.evaluated.rao, best.evaluated.rao}, {"baseline", "best"}, hb.L_m,
                             "RAOs: baseline and best"),
               OutPath(out, "baseline_vs_best_rao.svg"));
  r.Svg(io::ReadSvgFile(OutPath(out, "baseline_vs_best_rao.svg")));

  r.Heading("Accelerations and MSI per sea and position");
  std::vector<std::vector<std::string>> rows;
  const auto& sb = base.evaluated.evaluation.seas;
  const auto& ss = best.evaluated.evaluation.seas;
  for (std::size_t i = 0; i < sb.size() && i < ss.size(); ++i) {
    auto add = [&](const sk::PositionResult& a, const sk::PositionResult& b) {
      rows.push_back({a.position, io::FormatNumber(sb[i].sea.Hs_m, 3), io::FormatNumber(sb[i].Tz_s, 3), io::FormatNumber(a.rms_accel_g), io::FormatNumber(b.rms_accel_g),
                      io::FormatNumber(a.msi_pct, 3), io::FormatNumber(b.msi_pct, 3)});
    };
    for (std::size_t p = 0; p < sb[i].positions.size() && p < ss[i].positions.size(); ++p)
      add(sb[i].positions[p], ss[i].positions[p]);
    add(sb[i].mean, ss[i].mean);
  }
  r.Table({"position", "Hs [m]", "Tz [s]", "baseline rms [g]", "best rms [g]", "baseline MSI [%]", "best MSI [%]"},
          rows);

  r.Heading("Convergence and variables");
  for (const char* f : {"convergence.svg", "variables.svg", "scatter.svg"})
    if (std::filesystem::exists(OutPath(out, f))) r.Svg(io::ReadSvgFile(OutPath(out, f)));
  io::WriteHtmlReport(OutPath(out, "report.html"), r);
}

}  // namespace hullopt::app
