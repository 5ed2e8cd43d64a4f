// hullopt design CONFIG --out DIR: one hull (parametric, offsets or STL) through hydrostatics, RAOs,
// accelerations and MSI with the defaults of io/config/design_defaults.h, and report.html.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "app/commands.h"
#include "app/output_options.h"
#include "app/single_design.h"
#include "app/output_dir.h"
#include "app/run_checks.h"
#include "evaluation/seakeeping_criteria.h"
#include "io/formats/criteria_csv.h"
#include "io/config/design_config.h"
#include "io/report/bodyplan_svg.h"
#include "io/report/evaluation_report.h"
#include "io/report/html_report.h"
#include "io/formats/hydrostatics_json.h"
#include "io/formats/input_error.h"
#include "io/formats/rao_csv_writer.h"
#include "io/report/rao_plot.h"
#include "io/report/verdict_report.h"
#include "io/config/yaml_map.h"

namespace hullopt::app {
namespace {


void AddReport(const std::string& out, const std::string& config, const YAML::Node& resolved,
               const eval::DesignCase& dc, const io::EvaluatedDesign& d, const std::vector<std::string>& notes,
               const std::vector<std::string>& warnings, const eval::SeakeepingVerdict& verdict) {
  io::HtmlReport r("hullopt design: " + d.name);
  r.Paragraph("Config " + config + "; hull at " + io::FormatNumber(SpeedKnots(dc)) + " kn (U " +
              io::FormatNumber(dc.speed_m_s) + " m/s, Fn " + io::FormatNumber(d.parameters.at("Fr"), 3) + "), head seas.");
  r.Heading("Warnings");
  r.List(warnings, "No warnings.");
  r.Heading("Defaults taken (config.resolved.yaml holds their values)");
  r.List(notes, "No defaults taken.");
  io::AddVerdictSection(r, io::DefaultCriteria(), {{d.name, &verdict}});
  const auto& h = dc.hydrostatics;
  r.Heading("Hydrostatics and mass");
  r.Table({"quantity", "value", "unit"},
          {{"L (waterline)", io::FormatNumber(h.L_m), "m"}, {"B", io::FormatNumber(h.B_m), "m"}, {"T", io::FormatNumber(h.T_m), "m"},
           {"displacement", io::FormatNumber(h.displacement_t), "t"}, {"Cb", io::FormatNumber(h.Cb, 3), "-"}, {"Cp", io::FormatNumber(h.Cp, 3), "-"},
           {"Cm", io::FormatNumber(h.Cm, 3), "-"}, {"Cwp", io::FormatNumber(h.Cwp, 3), "-"}, {"Cvp", io::FormatNumber(h.Cvp, 3), "-"},
           {"LCB", io::FormatNumber(h.LCB_pct_L, 3), "% L fwd of midships"}, {"LCF", io::FormatNumber(h.LCF_pct_L, 3), "% L fwd of midships"},
           {"mass", io::FormatNumber(dc.mass.mass_kg / 1000.0), "t"}, {"LCG", io::FormatNumber(dc.mass.lcg_m_from_ap), "m from AP"},
           {"k_yy", io::FormatNumber(dc.mass.kyy_m), "m"}, {"KG", io::FormatNumber(dc.mass.kg_m), "m"}});
  r.Heading("Body plan");
  r.Svg(io::ReadSvgFile(OutPath(out, "bodyplan.svg")));
  r.Heading("Heave and pitch RAOs");
  r.Svg(io::ReadSvgFile(OutPath(out, "rao.svg")));
  r.Heading("Accelerations and MSI per sea and position");
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : d.evaluation.seas) {
    auto add = [&](const sk::PositionResult& p) {
      rows.push_back({p.position, io::FormatNumber(s.sea.Hs_m, 3), io::FormatNumber(s.Tz_s, 3),
                      std::isfinite(p.x_from_cg_m) ? io::FormatNumber(p.x_from_cg_m) : "", io::FormatNumber(p.rms_accel_g),
                      io::FormatNumber(p.rms_accel_g / s.sea.Hs_m), io::FormatNumber(p.msi_pct, 3)});
    };
    for (const auto& p : s.positions) add(p);
    add(s.mean);
  }
  r.Table({"position", "Hs [m]", "Tz [s]", "x from CG [m]", "rms accel [g]", "rms accel per Hs [g/m]", "MSI [%]"},
          rows);
  for (const char* f : {"accel_per_m.svg", "msi_vs_Hs.svg"})
    if (std::filesystem::exists(OutPath(out, f))) r.Svg(io::ReadSvgFile(OutPath(out, f)));
  r.Heading("Inputs (config.resolved.yaml: every default filled in)");
  YAML::Emitter e;
  e << resolved;
  r.Preformatted(e.c_str());
  io::WriteHtmlReport(OutPath(out, "report.html"), r);
}

void RunDesign(const std::string& config, const std::string& out) {
  io::YamlMap root = io::YamlMap::LoadFile(config);
  const std::string name = io::ParseDesignName(root, std::filesystem::path(config).stem().string());
  SingleDesign sd = EvaluateSingleDesign(root, name, "design", true,
                                         [&] { CheckOutputDirConfig(out, "design", root.resolved()); });
  const eval::DesignCase& dc = sd.design;
  io::EvaluatedDesign& d = sd.evaluated;
  const sk::EvaluationOptions& options = sd.options;
  const std::vector<std::string>& notes = sd.notes;
  PrepareOutputDir(out, "design", config, root.resolved());
  io::HydrostaticsReport rep;
  rep.hs = hull::ComputeHydrostatics(dc.hull, dc.water.rho_kg_m3, dc.mass.kg_m);
  rep.rho_kg_m3 = dc.water.rho_kg_m3;
  rep.g_m_s2 = dc.water.g_m_s2;
  rep.speed_m_s = dc.speed_m_s;
  rep.warnings = dc.input_warnings;
  rep.adjustments = dc.hull.adjustments;
  io::WriteHydrostaticsJson(OutPath(out, "hydrostatics.json"), dc.hull, rep);
  const auto& h = dc.hydrostatics;
  std::ostringstream title;
  title << dc.hull.type << " - L " << io::FormatNumber(h.L_m) << " m, B " << io::FormatNumber(h.B_m) << " m, T " << io::FormatNumber(h.T_m) << " m, "
        << io::FormatNumber(h.displacement_t) << " t";
  const bool plots = !NoPlotsGiven();  // --no-plots: the numbers only
  if (plots) io::WriteBodyPlanSvg(OutPath(out, "bodyplan.svg"), dc.hull, title.str());
  std::ostringstream about;
  about << "speed U = " << dc.speed_m_s << " m/s (Fn " << d.parameters.at("Fr") << "), method "
        << eval::MethodName(dc.solver.rao.method) << ", " << dc.solver.rao.sections << " sections x "
        << dc.solver.rao.panels << " panels, Cs = " << dc.solver.cs();
  std::vector<std::string> header = {"hull: " + name, about.str()};
  for (const auto& w : d.rao.warnings) header.push_back("warning: " + w);
  try {
    io::WriteRaoCsv(OutPath(out, "rao.csv"), d.rao, h.L_m, header);
  } catch (const std::domain_error& e) {
    throw io::InputError(config + ": design '" + name + "': " + e.what());
  }
  // A short title: the figure is drawn at full size in report.html only if the title fits its two columns.
  std::ostringstream plot_title;
  plot_title << "RAOs at U " << io::FormatNumber(dc.speed_m_s) << " m/s (Fn " << io::FormatNumber(d.parameters.at("Fr"), 3) << "), "
             << dc.solver.rao.sections << " x " << dc.solver.rao.panels << ", Cs " << dc.solver.cs();
  if (plots)
    io::WriteSvg(io::RaoFigure({d.rao}, {eval::MethodName(dc.solver.rao.method)}, h.L_m, plot_title.str()),
                 OutPath(out, "rao.svg"));
  const std::vector<io::EvaluatedDesign> designs = {d};
  io::EvaluationReportOptions report;
  report.plots = plots;
  report.plot_parameters.clear();  // one design: no MSI-vs-parameter plots
  io::WriteEvaluationOutputs(out, designs, options, report);
  // EvaluationWarnings holds the RAO table's warnings already: each is listed and printed once.
  const std::vector<std::string> warnings = io::EvaluationWarnings(designs, report);
  eval::SeakeepingVerdict verdict;
  try {
    verdict = eval::JudgeDesign(d.rao, d.hull, d.evaluation, eval::BowGeometryOf(dc), io::DefaultCriteria(),
                                options.response);
  } catch (const std::invalid_argument& e) {
    throw io::InputError(config + ": design '" + name + "': seakeeping criteria: " + e.what());
  }
  if (plots) AddReport(out, config, root.resolved(), dc, d, notes, warnings, verdict);
  for (const auto& n : notes) std::cerr << "hullopt: note: " << n << "\n";
  for (const auto& w : warnings) std::cerr << "hullopt: warning: " << w << "\n";
  Say("%-8s %6s %6s %10s %10s %10s %8s\n", "design", "Hs_m", "Tz_s", "fwd_g/m", "lcg_g/m", "transom_g/m",
      "MSI_%");
  for (const auto& s : d.evaluation.seas)
    Say("%-8s %6.2f %6.2f %10.4f %10.4f %10.4f %8.1f\n", name.c_str(), s.sea.Hs_m, s.Tz_s,
        s.positions[0].rms_accel_g / s.sea.Hs_m, s.positions[1].rms_accel_g / s.sea.Hs_m,
        s.positions[2].rms_accel_g / s.sea.Hs_m, s.mean.msi_pct);
  Say("verdict: %s\n", io::VerdictLine(name, io::DefaultCriteria(), verdict).c_str());
  Say(plots ? "wrote hydrostatics.json, bodyplan.svg, rao.csv, rao.svg, msi.csv, summary.json, report.html to %s\n"
            : "wrote hydrostatics.json, rao.csv, msi.csv, summary.json to %s\n",
      out.c_str());
}

}  // namespace

void AddDesignCommand(CLI::App& app) {
  AddConfigCommand(app,
                   {"design",
                    "one hull through hydrostatics, RAOs, accelerations and MSI with documented defaults "
                    "(report.html)",
                    "YAML config with a hull: map (any hull config or a campaign's best.yaml)"},
                   RunDesign);
}

}  // namespace hullopt::app
