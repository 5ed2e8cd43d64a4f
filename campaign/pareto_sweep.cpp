#include "campaign/pareto_sweep.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <vector>

#include "io/config/config_path.h"
#include "io/formats/history_csv.h"
#include "io/formats/input_error.h"
#include "io/report/svg_plot.h"
#include "io/config/yaml_map.h"

namespace hullopt::campaign {
namespace {

// The anchor's minimum is approached by the local algorithm only to its tolerance: the first limit sits this
// fraction above it so the first point's start (the anchor) is feasible with margin.
constexpr double kAnchorMargin = 1e-3;
// Starts per point (optimize.pareto.starts): run 0 from the previous point, the others at random points.
constexpr int kDefaultPointStarts = 4;

struct Best {
  double objective = NAN;
  nlohmann::json best;  // summary.json "best"
};

Best ReadBest(const std::string& dir) {
  std::ifstream f(dir + "/summary.json");
  if (!f) throw io::InputError(dir + "/summary.json: missing after the run");
  const nlohmann::json s = nlohmann::json::parse(f);
  if (s["best_objective"].is_null()) throw io::InputError(dir + ": the run found no feasible design");
  return {s["best_objective"].get<double>(), s["best"]};
}

// One feasible evaluation of a point's log.
struct Record {
  double objective = NAN;
  double q = NAN;         // the swept quantity
  std::vector<double> x;  // the variables, in the log's column order
  std::string source;     // the point folder
  long evaluation = -1;
};

std::string PointName(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "point_%02d", k);
  return name;
}

// Appends the feasible, evaluated rows of history.csv to *out (the names of its design variables go to
// *names). The file is read as a campaign reads it on resume, so a damaged row is refused with its line.
void ReadFeasible(const std::string& path, const std::string& source, const std::string& quantity,
                  std::vector<std::string>* names, std::vector<Record>* out) {
  const io::HistoryLayout layout = io::ReadHistoryLayout(path);
  const auto q = std::find(layout.quantities.begin(), layout.quantities.end(), quantity);
  if (q == layout.quantities.end()) throw io::InputError(path + ": no column '" + quantity + "'");
  const auto iq = static_cast<std::size_t>(q - layout.quantities.begin());
  *names = layout.variables;
  for (const io::HistoryRow& row : io::ReadHistory(path, layout).rows) {
    const opt::EvaluationRecord& rec = row.record;
    if (!rec.feasible || !rec.result.produced) continue;
    Record r;
    r.objective = rec.result.objective;
    r.q = row.reported[iq];
    if (!std::isfinite(r.objective) || !std::isfinite(r.q)) continue;
    r.x = rec.x;
    r.source = source;
    r.evaluation = row.evaluation;
    out->push_back(std::move(r));
  }
}

double ReadBaselineObjective(const std::string& dir) {
  std::ifstream f(dir + "/summary.json");
  const nlohmann::json s = nlohmann::json::parse(f);
  return s["baseline_objective"].is_number() ? s["baseline_objective"].get<double>() : NAN;
}

std::string ObjectiveAxis(const std::string& measure) {
  if (measure == "rms_accel") return "objective rms accel [g]";
  if (measure == "downtime_pct") return "objective: time criterion not met [%]";
  if (measure == "scatter_msi") return "objective scatter-weighted MSI [%]";
  return "objective MSI [%]";
}

}  // namespace

bool HasParetoSweep(const std::string& config_file) {
  try {
    const YAML::Node raw = YAML::LoadFile(config_file);
    return raw.IsMap() && raw["optimize"] && raw["optimize"].IsMap() && raw["optimize"]["pareto"];
  } catch (const YAML::Exception&) {
    return false;  // the ordinary path reports the file's problem with its line
  }
}

std::string RunParetoSweep(const std::string& config_file, const std::string& out_dir,
                    const std::function<void(const std::string&, const std::string&)>& run_optimize) {
  YAML::Node raw = YAML::LoadFile(config_file);
  // Strict read of the pareto block itself (the rest is read by each run).
  io::YamlMap root(raw, "", config_file, YAML::Node(YAML::NodeType::Map));
  io::YamlMap block = root.Map("optimize");
  io::YamlMap p = block.Map("pareto");
  const std::string quantity = p.Choice("quantity", {"P_E_kW", "R_T_kN", "R_W_kN"}, "P_E_kW");
  const int points = p.Integer("points", 8);
  if (points < 2) p.Fail("points", "a Pareto sweep needs at least 2 points");
  if (points > 100) p.Fail("points", "at most 100 points");
  const bool has_from = p.Has("from");
  const double from_given = p.Number("from", 0.0);
  const double to = p.Number("to");
  if (has_from && !(to > from_given)) p.Fail("to", "must be > from");
  const int starts = p.Integer("starts", kDefaultPointStarts);
  if (starts < 1 || starts > 1000) p.Fail("starts", "must lie in [1, 1000]");
  p.Finish();
  const std::string unit = quantity.substr(quantity.rfind('_') + 1);
  const std::string base = quantity.substr(0, quantity.rfind('_'));
  const std::string key = base + "_max_" + unit;  // e.g. P_E_max_kW limits P_E_kW
  if (raw["optimize"]["constraints"] && raw["optimize"]["constraints"][key])
    p.Fail("quantity", "the campaign already constrains " + key + "; the sweep sets it");
  const std::string measure = raw["optimize"]["objective"] && raw["optimize"]["objective"]["measure"]
                                  ? raw["optimize"]["objective"]["measure"].as<std::string>()
                                  : "msi";
  if (measure == quantity) p.Fail("quantity", "the campaign objective is already " + quantity);
  std::filesystem::create_directories(out_dir);
  raw["optimize"].remove("pareto");
  // The generated configs live in out_dir: a file the config names by a relative path is named absolutely.
  if (raw["operability"] && raw["operability"]["scatter_csv"])
    raw["operability"]["scatter_csv"] =
        io::ResolveConfigPath(raw["operability"]["scatter_csv"].as<std::string>(), config_file);
  const int seed = raw["optimize"]["seed"] ? raw["optimize"]["seed"].as<int>() : 1;

  // 1. Anchor: minimise the quantity.
  YAML::Node anchor = YAML::Clone(raw);
  anchor["optimize"]["objective"] = YAML::Node(YAML::NodeType::Map);
  anchor["optimize"]["objective"]["measure"] = quantity;
  const std::string anchor_dir = out_dir + "/anchor";
  std::filesystem::create_directories(anchor_dir);
  const std::string anchor_cfg = out_dir + "/anchor.yaml";
  {
    std::ofstream f(anchor_cfg);
    f << "# hullopt optimize — Pareto anchor: minimise " << quantity << " (generated from " << config_file << ")\n"
      << anchor << "\n";
  }
  run_optimize(anchor_cfg, anchor_dir);
  Best prev = ReadBest(anchor_dir);
  const double qmin = prev.objective;
  const double from = has_from ? from_given : qmin * (1.0 + kAnchorMargin);
  if (from < qmin)
    throw io::InputError(config_file + ": key 'optimize.pareto.from': " + std::to_string(from) +
                         " is below the smallest " + quantity + " the anchor run found (" + std::to_string(qmin) + ")");
  if (!(to > from))
    throw io::InputError(config_file + ": key 'optimize.pareto.to': must be above " + std::to_string(from));

  // Every feasible evaluation of every point's log (feasible for its own limit, so for any limit its quantity
  // satisfies): the front point for a limit is the best of them whose quantity is within it.
  const double tol = raw["optimize"]["feasibility_tol"] ? raw["optimize"]["feasibility_tol"].as<double>() : 1e-6;
  std::vector<Record> archive;
  std::vector<std::string> variable_names;
  auto best_within = [&](double limit) -> const Record* {
    const Record* b = nullptr;
    for (const Record& r : archive)
      if ((r.q - limit) / std::fabs(limit) <= tol && (!b || r.objective < b->objective)) b = &r;
    return b;
  };
  std::vector<double> limits, run_best;
  const nlohmann::json anchor_variables = prev.best["variables"];
  double anchor_objective = NAN;
  for (int k = 1; k <= points; ++k) {
    const double eps = from + (to - from) * (k - 1) / (points - 1);
    limits.push_back(eps);
    YAML::Node c = YAML::Clone(raw);
    c["optimize"]["constraints"][key] = eps;
    // Start: the best design known for the previous limit (the anchor for the first point), feasible here.
    if (const Record* r = k > 1 ? best_within(limits[k - 2]) : nullptr)
      for (size_t v = 0; v < variable_names.size(); ++v) c["optimize"]["start"][variable_names[v]] = r->x[v];
    else
      for (auto it = anchor_variables.begin(); it != anchor_variables.end(); ++it)
        c["optimize"]["start"][it.key()] = it.value().get<double>();
    // Run 0 continues from that start; runs 1.. start at seeded random points of the box, other ones for every
    // point, and escape the local minimum run 0 may stop in.
    c["optimize"]["starts"] = starts;
    c["optimize"]["seed"] = seed + k - 1;
    const std::string name = PointName(k);
    const std::string dir = out_dir + "/" + name, cfg = out_dir + "/" + name + ".yaml";
    {
      std::ofstream f(cfg);
      f << "# hullopt optimize — Pareto point " << k << ": " << key << " = " << eps << " (generated from "
        << config_file << ")\n" << c << "\n";
    }
    std::filesystem::create_directories(dir);
    run_optimize(cfg, dir);
    run_best.push_back(ReadBest(dir).objective);
    if (k == 1) anchor_objective = ReadBaselineObjective(dir);  // point 1's base design is the anchor's best
    ReadFeasible(dir + "/history.csv", name, quantity, &variable_names, &archive);
  }

  std::ofstream csv(out_dir + "/pareto.csv");
  csv << "point,limit_" << quantity << ",objective," << quantity << ",run_dir,evaluation,run_best_objective";
  for (const auto& v : variable_names) csv << "," << v;
  csv << "\n" << std::setprecision(10);
  csv << "anchor,," << anchor_objective << "," << qmin << ",anchor,,";
  for (const auto& v : variable_names) csv << "," << anchor_variables[v].get<double>();
  csv << "\n";
  std::vector<double> fq, fo;
  for (int k = 1; k <= points; ++k) {
    const Record* r = best_within(limits[k - 1]);
    if (!r) throw io::InputError(out_dir + "/" + PointName(k) + ": no feasible design for the limit");
    csv << PointName(k) << "," << std::to_string(limits[k - 1]) << "," << r->objective << "," << r->q << ","
        << r->source << "," << r->evaluation << "," << run_best[k - 1];
    for (double x : r->x) csv << "," << x;
    csv << "\n";
    fq.push_back(r->q);
    fo.push_back(r->objective);
    // front_NN.yaml: point k's config started at its front design (re-evaluated as the run's baseline).
    YAML::Node c = YAML::LoadFile(out_dir + "/" + PointName(k) + ".yaml");
    for (size_t v = 0; v < variable_names.size(); ++v) c["optimize"]["start"][variable_names[v]] = r->x[v];
    c["optimize"]["starts"] = 1;
    std::ofstream f(out_dir + "/front_" + PointName(k).substr(6) + ".yaml");
    f << "# hullopt optimize — Pareto front point " << k << " (" << key << " = " << limits[k - 1]
      << "), started at its design: " << r->source << "/history.csv evaluation " << r->evaluation << "\n"
      << c << "\n";
  }
  csv.close();
  io::PlotFigure fig;
  fig.title = "Pareto front (ε-constraint on " + quantity + ")";
  fig.footnote = "each point: the best feasible design of the sweep with " + key + " <= ε; anchor: minimum " + quantity;
  io::PlotPanel& pn = fig.AddPanel("", quantity, ObjectiveAxis(measure));
  pn.series.push_back(io::PlotSeries::LineMarkers("front", fq, fo));
  pn.series.push_back(io::PlotSeries::Markers("anchor (min " + quantity + ")", {qmin}, {anchor_objective}));
  io::WriteSvg(fig, out_dir + "/pareto.svg");
  char line[200];
  std::snprintf(line, sizeof line, "pareto: %d points of %s %.6g..%.6g; wrote pareto.csv, pareto.svg and anchor/, point_NN/ in ",
                points, quantity.c_str(), from, to);
  return line + out_dir;
}

}  // namespace hullopt::campaign
