// `hullopt evaluate CONFIG --out DIR`: rms accelerations and motion sickness incidence of one or more designs
// in a list of head seas; writes msi.csv, summary.json and the seakeeping plots.
//
// RAOs are computed by the time-domain strip solver from a design config (hull, speed, solver, mass), or read
// from rao.csv files (the `hullopt rao` output):
//
//   hull: {...}; speed: {...}; solver: {Cs: ...}; mass: {...}   # one design computed here ...
//   name: npl5b                              # optional, default: the config file's stem
//
//   designs:                                 # ... or several, each a design config file
//     - { config: davis-holloway-2003/hull04_DUT372.yaml, name: DUT372, group: catamaran, Cs: 0.024 }
//
// Paths are relative to the folder of the config that names them (io/config/config_path.h).
//
//   rao_csv: out/rao/rao.csv                 # one design ...
//   name: delft372                           # optional, default: the file's parent folder or stem
//   hull_extent: { cg_to_transom_m: 1.41, cg_to_bow_m: 1.59 }
//
//   designs:                                 # ... or several
//     - { name: hull4, group: catamaran, rao_csv: a.csv, cg_to_transom_m: 20, cg_to_bow_m: 25,
//         parameters: { Fr: 0.8, Cvp: 0.6, B_over_T: 2.0 } }
//
//   speed: { kn: 40 }                        # optional check of the speed implied by the RAO files
//   water: { g_m_s2: 9.81 }                  # optional
//   seas: [...]; msi: {...}; positions: { points: [...] }   (io/config/seas_config.h)
//   operability: {...}                     # scatter diagram and criteria (io/config/operability_config.h); its
//                                            # polar: block (a design computed here) adds operability_polar.csv
//                                            # and .svg: speeds x headings in oblique seas
//   report: { plots: true }
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "app/commands.h"
#include "app/output_options.h"
#include "app/design_resolution_check.h"
#include "evaluation/oblique_design.h"
#include "evaluation/operability_polar.h"
#include "evaluation/validity_envelope.h"
#include "io/config/design_defaults.h"
#include "io/config/design_config.h"
#include "app/output_dir.h"
#include "app/run_checks.h"
#include "io/config/config_path.h"
#include "evaluation/seakeeping_criteria.h"
#include "io/formats/criteria_csv.h"
#include "io/report/evaluation_report.h"
#include "io/report/html_report.h"
#include "io/report/operability_polar_plot.h"
#include "io/report/verdict_report.h"
#include "io/formats/input_error.h"
#include "io/formats/rao_table_csv.h"
#include "io/config/resolution_check_config.h"
#include "evaluation/design_resolution_check.h"
#include "io/config/seas_config.h"
#include "io/config/operability_config.h"
#include "io/formats/operability_output.h"
#include "io/config/water_config.h"
#include "io/config/yaml_map.h"
#include "seakeeping/motions/rao_checks.h"
#include "seas/design_evaluation.h"
#include "seas/resolution_check.h"

namespace hullopt::app {
namespace {

constexpr double kKnot = 1852.0 / 3600.0;  // [m/s]

std::string DefaultName(const std::string& csv) {
  namespace fs = std::filesystem;
  const fs::path p(csv);
  const std::string parent = p.parent_path().filename().string();
  return p.stem() == "rao" && !parent.empty() ? parent : p.stem().string();
}

struct DesignInput {
  io::EvaluatedDesign design;
  std::string where;  // config location for messages
  std::optional<eval::DesignCase> computed;  // the design when its RAOs are computed here (for the resolution check)
  std::vector<double> omega_rad_s;            // its wave frequencies
  double cs_override = -1.0;
  // A design read and checked, built once the whole evaluation config has been read (BuildPendingDesigns).
  std::optional<io::ParsedDesign> pending;
  YAML::Node pending_resolved;                // its config's resolved tree (the run-cost estimate)
  std::string pending_file, pending_label;    // its config file; the cost check's label
  std::vector<std::string> pending_warnings;  // flags of the evaluation's overrides, appended once built
  std::optional<double> kxx_m;                // mass.kxx_m (the operability polar's roll)
  bool roll_damping = false;                  // solver.roll_damping: ikeda (the polar's viscous roll damping)
  double roll_amplitude_deg = 5.0;            // solver.roll_amplitude_deg
};

// A design whose RAOs are computed here by the strip solver from `dc` (read from `file`, whose resolved config
// is `resolved`): checked now, its RAOs computed by ComputePendingRaos once the whole evaluation config has
// been read, so that an error anywhere in it is reported before the strip work.
void SetComputedDesign(const eval::DesignCase& dc, const YAML::Node& resolved, const std::string& file,
                       const std::string& cost_label, double cs_override, DesignInput* in) {
  in->omega_rad_s = eval::SeaFrequencies(dc);
  CheckRunCost(cost_label, io::StripWorkFromResolved(resolved, static_cast<long>(in->omega_rad_s.size())));
  in->computed = dc;
  in->cs_override = cs_override;
  in->design.rao.speed_m_s = dc.speed_m_s;
  in->design.frequency_advice = eval::SeaFrequencyAdvice(dc, file);
  in->design.hull = dc.Extent();
  for (const auto& [k, v] : dc.Parameters()) in->design.parameters.emplace(k, v);  // the list's own kept
}

// A design of the `designs` list given by its own config file (root = that file's map).
void LoadComputedDesign(io::YamlMap& root, const std::string& file, DesignInput* in, double cs_override) {
  in->pending = io::ParseDesign(root, file, in->design.name);
  if (root.Has("compare")) root.Skip("compare");  // measured data drawn by rao/coefficients, not used here
  root.Finish();
  in->pending_resolved = root.resolved();
  in->pending_file = file;
  in->pending_label = "evaluate: design '" + in->design.name + "'";
  in->cs_override = cs_override;
}

// The designs read by LoadComputedDesign, built (hull, mass, running attitude) once everything is read.
void BuildPendingDesigns(std::vector<DesignInput>* inputs) {
  for (auto& in : *inputs) {
    if (!in.pending) continue;
    const eval::DesignCase dc = io::BuildParsedDesign(*in.pending);
    SetComputedDesign(dc, in.pending_resolved, in.pending_file, in.pending_label, in.cs_override, &in);
    for (auto& w : in.pending_warnings) in.computed->input_warnings.push_back(std::move(w));
    in.pending.reset();
  }
}

// The seas and points refine each computed design's grid (solver.adaptive_grid) until its MSI converges.
void ComputePendingRaos(const std::vector<sk::WaveSpectrum>& spectra, const std::vector<sk::PassengerPosition>& points,
                        const sk::EvaluationOptions& options, std::vector<DesignInput>* inputs) {
  for (auto& in : *inputs) {
    if (!in.computed) continue;
    const eval::GridSeas seas{spectra, in.design.hull, points, options};
    in.design.rao = eval::ComputeDesignRaos(*in.computed, in.omega_rad_s, in.cs_override, &seas);
  }
}

DesignInput ReadDesign(io::YamlMap& m, double g, bool single) {
  DesignInput in;
  if (!single && m.Has("config")) {
    in.where = m.Where("config");
    const std::string file = io::ConfigFilePath(m, "config");  // its own paths resolve beside it
    in.design.name = m.String("name", std::filesystem::path(file).stem().string());
    in.design.group = m.String("group", "");
    const double cs = m.Has("Cs") ? m.Number("Cs") : -1.0;
    if (m.Has("Cs") && cs < 0) m.Fail("Cs", "must be >= 0");
    if (m.Has("Cs")) io::RefuseOutsideEnvelope(m, "Cs", eval::EnvelopeQuantity::kDampingCs, cs);
    io::YamlMap params = m.MapOrEmpty("parameters");
    for (const auto& key : params.Keys()) in.design.parameters[key] = params.Number(key);
    params.Finish();
    io::YamlMap design_root = io::YamlMap::LoadFile(file);
    LoadComputedDesign(design_root, file, &in, cs);
    if (m.Has("Cs"))  // the override's flag, as the design's own solver.Cs is flagged when it is read
      for (const auto& f : eval::CheckEnvelopeValue(eval::EnvelopeQuantity::kDampingCs, cs, "Cs"))
        in.pending_warnings.push_back(f.message);
    if (std::abs(g - design_root.resolved()["water"]["g_m_s2"].as<double>(g)) > 1e-9)
      throw io::InputError(in.where + ": the design's g differs from the evaluation's water.g_m_s2");
    return in;
  }
  in.where = m.Where("rao_csv");
  const std::string csv = io::ConfigFilePath(m, "rao_csv");
  in.design.name = m.String("name", DefaultName(csv));
  if (in.design.name.empty()) m.Fail("name", "must not be empty");
  if (!single) {
    in.design.group = m.String("group", "");
    in.design.hull.cg_to_transom_m = m.Number("cg_to_transom_m");
    in.design.hull.cg_to_bow_m = m.Number("cg_to_bow_m");
    io::YamlMap params = m.MapOrEmpty("parameters");
    for (const auto& key : params.Keys()) in.design.parameters[key] = params.Number(key);
    params.Finish();
  } else {
    io::YamlMap ext = m.Map("hull_extent");
    in.design.hull.cg_to_transom_m = ext.Number("cg_to_transom_m");
    in.design.hull.cg_to_bow_m = ext.Number("cg_to_bow_m");
    ext.Finish();
  }
  std::string error;
  if (!in.design.hull.IsValid(&error)) throw io::InputError(in.where + ": " + error);
  in.design.rao = io::ReadRaoTableCsv(csv, g);
  in.design.rao.warnings = sk::RaoResonanceWarnings(in.design.rao);
  in.design.frequency_advice = "recompute " + csv + " over a wider range (hullopt rao, solver.frequencies)";
  return in;
}

// The blocks after the designs: seas, msi, positions, operability, resolution_check, report; then every key
// of root must have been read (root.Finish()).
struct EvaluateBlocks {
  std::vector<sk::SeaState> seas;
  sk::EvaluationOptions options;
  std::vector<sk::PassengerPosition> points;
  std::string points_where;  // "config:line: key 'positions.points'"
  io::OperabilityConfig operability;
  io::ResolutionCheckConfig resolution;
  io::EvaluationReportOptions report;
};

EvaluateBlocks ReadEvaluateBlocks(io::YamlMap& root) {
  EvaluateBlocks b;
  b.seas = io::ReadSeas(root);
  b.options.msi = io::ReadMsiOptions(root);
  io::YamlMap positions = root.MapOrEmpty("positions");
  // Points are checked against each design's hull once the designs are built (designs differ in length).
  b.points = io::ReadPassengerPoints(positions, nullptr);
  b.points_where = positions.Where("points");
  positions.Finish();
  b.operability = io::ParseOperability(root, b.points);
  b.resolution = io::ReadResolutionCheck(root);
  io::YamlMap report_map = root.MapOrEmpty("report");
  b.report.plots = report_map.Boolean("plots", true) && !NoPlotsGiven();
  report_map.Finish();
  root.Finish();
  return b;
}

double ReadSpeedCheck(io::YamlMap& root) {
  if (!root.Has("speed")) return NAN;
  io::YamlMap s = root.Map("speed");
  double u = NAN;
  if (s.Has("kn")) u = s.Number("kn") * kKnot;
  if (s.Has("m_s")) u = s.Number("m_s");
  if (s.Has("Fn")) s.Skip("Fn");  // needs the hull length: checked on the solver path
  s.Finish();
  return u;
}

void Run(const std::string& config_file, const std::string& out_dir) {
  const auto t0 = std::chrono::steady_clock::now();
  io::YamlMap root = io::YamlMap::LoadFile(config_file);
  double g = 9.81;
  std::vector<std::string> water_flags;  // validity-envelope flags of a water block read here (RAO files)
  if (!root.Has("hull")) {  // with a hull, water is read with the design
    io::YamlMap water = root.MapOrEmpty("water");
    g = water.Number("g_m_s2", 9.81);
    io::RefuseOutsideEnvelope(water, "g_m_s2", eval::EnvelopeQuantity::kGravity, g);
    eval::EnvelopeInput env;
    env.g_m_s2 = g;
    if (water.Has("rho_kg_m3")) {
      env.rho_kg_m3 = water.Number("rho_kg_m3");
      io::RefuseOutsideEnvelope(water, "rho_kg_m3", eval::EnvelopeQuantity::kWaterDensity, env.rho_kg_m3);
    }
    for (const auto& f : eval::CheckEnvelope(env)) water_flags.push_back(f.message);
    water.Finish();
  }
  const double speed_check = root.Has("hull") ? NAN : ReadSpeedCheck(root);

  const bool single = root.Has("rao_csv"), multi = root.Has("designs"), computed = root.Has("hull");
  if ((single ? 1 : 0) + (multi ? 1 : 0) + (computed ? 1 : 0) != 1)
    throw io::InputError(config_file +
                         ": give exactly one of 'hull' (one design computed by the strip solver), 'rao_csv' "
                         "(one design's RAOs from a file) or 'designs' (a list)");

  std::vector<DesignInput> inputs;
  // operability.polar computes roll: the design's KG is required and mass.kxx_m may be given.
  io::DesignReadOptions read;
  {
    const YAML::Node op = root.raw()["operability"];
    read.roll = op && op.IsMap() && op["polar"];
  }
  if (computed) {
    std::vector<std::string> notes;
    io::SkipCampaignBlocks(root, &notes);
    io::FillDefaultSeas(root, &notes);
    {
      // The whole config as written, checked before the default frequency grid builds the hull (a separate
      // record of keys and resolved values; the read below fills them).
      io::YamlMap check(root.raw(), "", config_file, YAML::Node(YAML::NodeType::Map));
      io::SkipCampaignBlocks(check, nullptr);
      io::ParseDesignName(check, "design");
      io::ParseDesign(check, config_file, "design", read);
      ReadEvaluateBlocks(check);
    }
    io::FillDefaultFrequencies(root, &notes);
    for (const auto& n : notes) std::cerr << "hullopt: note: " << n << "\n";
    DesignInput in;
    in.where = root.Where("hull");
    // Recorded in config.resolved.yaml, so that a re-run keeps the design's name.
    in.design.name = io::ParseDesignName(root, std::filesystem::path(config_file).stem().string());
    in.pending = io::ParseDesign(root, config_file, in.design.name, read);
    in.kxx_m = in.pending->kxx_m;
    in.roll_damping = in.pending->roll_damping == "ikeda";
    in.roll_amplitude_deg = in.pending->roll_amplitude_deg;
    in.pending_resolved = root.resolved();
    in.pending_file = config_file;
    in.pending_label = "evaluate";
    inputs.push_back(in);
  } else if (single) {
    inputs.push_back(ReadDesign(root, g, true));
  } else {
    for (io::YamlMap& d : root.ListOfMaps("designs")) {
      inputs.push_back(ReadDesign(d, g, false));
      d.Finish();
    }
  }
  for (size_t i = 0; i < inputs.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (inputs[i].design.name == inputs[j].design.name)
        throw io::InputError(inputs[i].where + ": design name '" + inputs[i].design.name + "' is used twice");
  const EvaluateBlocks blocks = ReadEvaluateBlocks(root);
  const std::vector<sk::SeaState>& seas = blocks.seas;
  const sk::EvaluationOptions& options = blocks.options;
  const std::vector<sk::PassengerPosition>& points = blocks.points;
  const io::OperabilityConfig& operability = blocks.operability;
  const io::ResolutionCheckConfig& resolution = blocks.resolution;
  if (operability.polar.present && !computed)
    throw io::InputError(operability.polar.where +
                         ": the polar computes the motions in oblique seas, so it needs the design's hull here "
                         "(hull: ...), not RAO files");
  const io::EvaluationReportOptions& report = blocks.report;

  // The whole config has been read and checked: now the designs are built (hull, mass, running attitude).
  BuildPendingDesigns(&inputs);
  if (std::isfinite(speed_check)) {
    for (const auto& in : inputs) {
      const double u = in.design.rao.speed_m_s;
      if (std::abs(u - speed_check) > 0.01 * speed_check + 0.01) {
        char buf[256];
        std::snprintf(buf, sizeof buf, ": the RAO file implies %.3f m/s (%.2f kn) but speed is %.3f m/s", u,
                      u / kKnot, speed_check);
        throw io::InputError(in.where + buf);
      }
    }
  }
  for (const auto& in : inputs) {
    for (const auto& p : points) {
      std::string error;
      if (!sk::IsValidPassengerPosition(p, in.design.hull, &error))
        throw io::InputError(blocks.points_where + ": design '" + in.design.name + "': " + error);
    }
  }
  if (operability.polar.present) {  // the polar's own strip work: a solve per speed over all its headings
    const DesignInput& in = inputs.front();
    io::StripWork work = io::StripWorkFromResolved(in.pending_resolved, static_cast<long>(in.omega_rad_s.size()));
    work.kernels = static_cast<long>(operability.polar.speeds_kn.size());
    work.count_key = "operability.polar.speeds_kn";
    work.headings = static_cast<int>(operability.polar.options.headings_deg.size());
    CheckRunCost("evaluate: operability polar", work);
  }
  const std::vector<sk::WaveSpectrum> spectra = sk::BuildSpectra(seas);
  ComputePendingRaos(spectra, points, options, &inputs);  // the strip work, once everything has been read and checked

  std::vector<io::EvaluatedDesign> designs;
  for (auto& in : inputs) {
    try {
      in.design.evaluation = sk::EvaluateDesign(in.design.rao, in.design.hull, spectra, points, options);
    } catch (const std::invalid_argument& e) {
      throw io::InputError(in.where + ": design '" + in.design.name + "': " + e.what());
    } catch (const std::domain_error& e) {
      throw io::InputError(in.where + ": design '" + in.design.name + "': " + e.what());
    }
    for (const auto& w : water_flags) in.design.rao.warnings.push_back(w);
    for (auto& w : eval::ResponseEnvelopeWarnings(in.design.evaluation, in.computed ? in.computed->water.g_m_s2 : g))
      in.design.rao.warnings.push_back(std::move(w));
    if (resolution.enabled && in.computed)
      CheckDesignResolution(resolution, spectra, points, options, *in.computed, in.cs_override, in.where,
                            &in.design);
    if (resolution.enabled && !in.computed)
      in.design.rao.warnings.push_back("resolution check not made: RAOs read from a file (give the design's config)");
    designs.push_back(in.design);
  }

  // The operability polar: the design's method per speed over the headings, on the scatter diagram.
  std::optional<eval::OperabilityPolar> polar;
  if (operability.polar.present) {
    const DesignInput& in = inputs.front();
    eval::PolarOptions po = operability.polar.options;
    po.omega_rad_s = in.omega_rad_s;
    po.evaluation = options;
    if (in.roll_damping) {
      po.roll_damping.model = sk::RollDampingModel::kIkeda;
      po.roll_damping.roll_amplitude_rad = in.roll_amplitude_deg * M_PI / 180.0;
    }
    const double kxx = in.kxx_m ? *in.kxx_m : eval::DefaultRollRadiusOfGyration(in.computed->hull);
    try {
      polar = eval::ComputeOperabilityPolar(*in.computed, kxx, operability.diagram, operability.polar.criteria,
                                            points, po);
    } catch (const std::invalid_argument& e) {
      throw io::InputError(operability.polar.where + ": " + e.what());
    } catch (const std::domain_error& e) {
      throw io::InputError(operability.polar.where + ": " + e.what());
    }
  }

  // The roll damping's flags (the hull outside the fitted range, a multihull): in every output, each with the
  // speeds it was raised at when not all.
  std::vector<std::string> polar_flags;
  if (polar) {
    for (const auto& f : polar->flags) {
      std::string text = "operability polar: " + f.text;
      if (f.speeds_m_s.size() < operability.polar.speeds_kn.size()) {
        text += " (at";
        for (std::size_t i = 0; i < f.speeds_m_s.size(); ++i) {
          char b[32];
          std::snprintf(b, sizeof b, "%s %g", i ? "," : "", f.speeds_m_s[i] / kKnot);
          text += b;
        }
        text += " kn)";
      }
      polar_flags.push_back(text);
    }
    for (const auto& w : polar_flags) designs.front().rao.warnings.push_back(w);
  }

  std::vector<io::DesignOperability> operabilities;
  if (operability.present) {
    for (const auto& d : designs) {
      try {
        operabilities.push_back({d.name, sk::EvaluateOperability(d.rao, d.hull, operability.diagram,
                                                                 operability.criteria, points, options)});
      } catch (const std::invalid_argument& e) {
        throw io::InputError(config_file + ": key 'operability': design '" + d.name + "': " + e.what());
      }
    }
  }

  PrepareOutputDir(out_dir, "evaluate", config_file, root.resolved());
  auto files = io::WriteEvaluationOutputs(out_dir, designs, options, report);
  if (operability.present) {
    for (const auto& f : io::WriteOperabilityOutputs(out_dir, operabilities, operability.diagram,
                                                     operability.criteria, operability.scatter_csv))
      files.push_back(f);
    for (const auto& o : operabilities) {
      Say("operability %-16s weighted mean MSI %.2f %%, all criteria met %.1f %% of the time",
          o.name.c_str(), o.result.weighted_mean_msi_pct, o.result.all_criteria_time_pct);
      for (size_t k = 0; k < operability.criteria.size(); ++k)
        Say("; %s %.1f %%", operability.criteria[k].name.c_str(), o.result.criterion_time_pct[k]);
      Say("\n");
    }
  }
  if (polar) {
    io::WriteOperabilityPolarCsv(OutPath(out_dir, "operability_polar.csv"), *polar, operability.polar.criteria);
    files.push_back("operability_polar.csv");
    if (report.plots) {
      std::vector<std::string> notes = {"Operability: share of the scatter diagram " +
                                        std::filesystem::path(operability.scatter_csv).filename().string() +
                                        " (long-crested seas at each heading) with every criterion met:"};
      for (const auto& c : operability.polar.criteria) {
        char b[200];
        std::snprintf(b, sizeof b, "  %s <= %g %s%s%s", c.name.c_str(), c.limit,
                      eval::PolarQuantityUnit(c.quantity).c_str(), c.source.empty() ? "" : " - ",
                      c.source.c_str());
        notes.push_back(b);
      }
      std::string method = polar->method;
      if (!method.empty()) method[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(method[0])));
      notes.push_back(method + "; running attitude of the design speed at every speed.");
      notes.push_back("Roll damping: " + polar->roll_damping + ".");
      for (const auto& f : polar_flags) notes.push_back("Warning: " + f.substr(std::string("operability polar: ").size()));
      io::WriteOperabilityPolarSvg(OutPath(out_dir, "operability_polar.svg"), *polar,
                                   "Operability polar: " + designs.front().name, notes);
      files.push_back("operability_polar.svg");
    }
    Say("operability polar %s (share of the scatter diagram with every criterion met):\n",
        designs.front().name.c_str());
    for (const auto& c : polar->cells) {
      if (c.computed)
        Say("  %6.1f kn %6.1f deg  %5.1f %%\n", c.speed_m_s / kKnot, c.heading_deg, 100.0 * c.operability);
      else
        Say("  %6.1f kn %6.1f deg  not computed: %s\n", c.speed_m_s / kKnot, c.heading_deg, c.note.c_str());
    }
  }
  const std::vector<std::string> warnings = io::EvaluationWarnings(designs, report);
  for (const auto& w : warnings) std::cerr << "hullopt: warning: " << w << "\n";

  // report.html: the warnings, the seakeeping verdict of every design, the plots.
  const eval::CriteriaSet& criteria = io::DefaultCriteria();
  std::vector<eval::SeakeepingVerdict> verdicts;
  for (std::size_t i = 0; i < designs.size(); ++i) {
    try {
      verdicts.push_back(eval::JudgeDesign(designs[i].rao, designs[i].hull, designs[i].evaluation,
                                           inputs[i].computed ? eval::BowGeometryOf(*inputs[i].computed)
                                                              : eval::BowGeometry{},
                                           criteria, options.response));
    } catch (const std::invalid_argument& e) {
      throw io::InputError(inputs[i].where + ": design '" + designs[i].name + "': seakeeping criteria: " + e.what());
    }
  }
  if (!NoPlotsGiven()) {  // --no-plots: the numbers only
    io::HtmlReport r("hullopt evaluate: " + std::filesystem::path(config_file).filename().string());
    r.Paragraph("Config " + config_file + "; " + std::to_string(designs.size()) + " design(s) in " +
                std::to_string(seas.size()) + " head sea(s); MSI model " + sk::MsiModelName(options.msi.model) +
                ". Numbers per position are in msi.csv and summary.json.");
    r.Heading("Warnings");
    r.List(warnings, "No warnings.");
    std::vector<io::JudgedDesign> judged;
    for (std::size_t i = 0; i < designs.size(); ++i) judged.push_back({designs[i].name, &verdicts[i]});
    io::AddVerdictSection(r, criteria, judged);
    if (report.plots) {
      r.Heading("Plots");
      for (const auto& f : files)
        if (f.size() > 4 && f.substr(f.size() - 4) == ".svg")
          r.Svg(io::ReadSvgFile((std::filesystem::path(out_dir) / f).string()));
    }
    io::WriteHtmlReport((std::filesystem::path(out_dir) / "report.html").string(), r);
    files.push_back("report.html");
  }
  for (std::size_t i = 0; i < designs.size(); ++i)
    Say("verdict: %s\n", io::VerdictLine(designs[i].name, criteria, verdicts[i]).c_str());

  Say("%-16s %6s %6s %10s %10s %10s %8s\n", "design", "Hs_m", "Tz_s", "fwd_g/m", "lcg_g/m",
      "transom_g/m", "MSI_%");
  for (const auto& d : designs) {
    for (const auto& s : d.evaluation.seas) {
      const double h = s.sea.Hs_m;
      Say("%-16s %6.2f %6.2f %10.4f %10.4f %10.4f %8.1f\n", d.name.c_str(), h, s.Tz_s,
          s.positions[0].rms_accel_g / h, s.positions[1].rms_accel_g / h,
          s.positions[2].rms_accel_g / h, s.mean.msi_pct);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Say("wrote %zu files to %s (%.2f s); MSI model %s\n", files.size() + 2, out_dir.c_str(), seconds,
      sk::MsiModelName(options.msi.model).c_str());
}

}  // namespace

void AddEvaluateCommand(CLI::App& app) {
  AddConfigCommand(app,
                   {"evaluate",
                    "rms accelerations and motion sickness incidence in head seas (msi.csv, summary.json, plots)",
                    "YAML config (rao_csv or designs, seas, msi, positions)", "config", "output folder",
                    "out/evaluate"},
                   Run);
}

}  // namespace hullopt::app
