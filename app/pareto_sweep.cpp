#include "app/pareto_sweep.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <vector>

#include "io/input_error.h"
#include "io/svg_plot.h"
#include "io/yaml_map.h"

namespace hullopt::app {
namespace {

// The anchor's minimum is approached by the local algorithm only to its tolerance: the first limit sits this
// fraction above it so the first point's start (the anchor) is feasible with margin.
constexpr double kAnchorMargin = 1e-3;

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

double SeaMean(const nlohmann::json& seas, const std::vector<double>& w) {
  double s = 0, ws = 0;
  size_t i = 0;
  for (auto it = seas.begin(); it != seas.end(); ++it, ++i) {
    const double wi = i < w.size() ? w[i] : 1.0;
    s += wi * it.value().get<double>();
    ws += wi;
  }
  return s / ws;
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

void RunParetoSweep(const std::string& config_file, const std::string& out_dir,
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
  p.Finish();
  const std::string unit = quantity.substr(quantity.rfind('_') + 1);
  const std::string base = quantity.substr(0, quantity.rfind('_'));
  const std::string key = base + "_max_" + unit;  // e.g. P_E_max_kW limits P_E_kW
  if (raw["optimize"]["constraints"] && raw["optimize"]["constraints"][key])
    p.Fail("quantity", "the campaign already constrains " + key + "; the sweep sets it");
  std::vector<double> weights;
  if (raw["optimize"]["objective"] && raw["optimize"]["objective"]["sea_weights"])
    weights = raw["optimize"]["objective"]["sea_weights"].as<std::vector<double>>();
  const std::string measure = raw["optimize"]["objective"] && raw["optimize"]["objective"]["measure"]
                                  ? raw["optimize"]["objective"]["measure"].as<std::string>()
                                  : "msi";
  if (measure == quantity) p.Fail("quantity", "the campaign objective is already " + quantity);
  std::filesystem::create_directories(out_dir);
  raw["optimize"].remove("pareto");

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

  std::ofstream csv(out_dir + "/pareto.csv");
  csv << "point,limit_" << quantity << ",objective," << quantity << ",run_dir";
  const nlohmann::json& vars0 = prev.best["variables"];
  for (auto it = vars0.begin(); it != vars0.end(); ++it) csv << "," << it.key();
  csv << "\n" << std::setprecision(10);
  auto row = [&](const std::string& name, double limit, double obj, double q, const std::string& dir,
                 const nlohmann::json& v) {
    csv << name << "," << (std::isfinite(limit) ? std::to_string(limit) : "") << "," << obj << "," << q << ","
        << dir;
    for (auto it = v.begin(); it != v.end(); ++it) csv << "," << it.value().get<double>();
    csv << "\n";
    csv.flush();
  };
  row("anchor", NAN, SeaMean(prev.best["seas"], weights), qmin, "anchor", prev.best["variables"]);
  std::vector<double> fq, fo;
  for (int k = 1; k <= points; ++k) {
    const double eps = from + (to - from) * (k - 1) / (points - 1);
    YAML::Node c = YAML::Clone(raw);
    c["optimize"]["constraints"][key] = eps;
    for (auto it = prev.best["variables"].begin(); it != prev.best["variables"].end(); ++it)
      c["optimize"]["start"][it.key()] = it.value().get<double>();
    char name[32];
    std::snprintf(name, sizeof name, "point_%02d", k);
    const std::string dir = out_dir + "/" + name, cfg = out_dir + "/" + name + ".yaml";
    {
      std::ofstream f(cfg);
      f << "# hullopt optimize — Pareto point " << k << ": " << key << " = " << eps << " (generated from "
        << config_file << ")\n" << c << "\n";
    }
    std::filesystem::create_directories(dir);
    run_optimize(cfg, dir);
    const Best b = ReadBest(dir);
    const double q = b.best["constrained_quantities"][quantity].get<double>();
    row(name, eps, b.objective, q, name, b.best["variables"]);
    fq.push_back(q);
    fo.push_back(b.objective);
    prev = b;
  }
  io::PlotFigure fig;
  fig.title = "Pareto front (ε-constraint on " + quantity + ")";
  fig.footnote = "each point: minimise the campaign objective with " + key + " = ε; anchor: minimum " + quantity;
  io::PlotPanel& pn = fig.AddPanel("", quantity, measure == "rms_accel" ? "objective rms accel [g]" : "objective MSI [%]");
  pn.series.push_back(io::PlotSeries::LineMarkers("front", fq, fo));
  pn.series.push_back(io::PlotSeries::Markers("anchor (min " + quantity + ")", {qmin},
                                              {SeaMean(ReadBest(anchor_dir).best["seas"], weights)}));
  io::WriteSvg(fig, out_dir + "/pareto.svg");
  std::printf("pareto: %d points of %s %.6g..%.6g; wrote pareto.csv, pareto.svg and anchor/, point_NN/ in %s\n",
              points, quantity.c_str(), from, to, out_dir.c_str());
}

}  // namespace hullopt::app
