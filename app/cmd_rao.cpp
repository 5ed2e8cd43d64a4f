// hullopt rao CONFIG --out DIR: heave and pitch RAOs of one hull at one speed in head seas → rao.csv,
// rao.svg.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "app/commands.h"
#include "app/output_dir.h"
#include "io/input_error.h"
#include "io/motion_config.h"
#include "io/rao_csv_writer.h"
#include "io/rao_plot.h"
#include "io/yaml_map.h"
#include "parametric_hull/hydrostatics.h"
#include "seakeeping/impulsive_strip_kernel.h"
#include "seakeeping/rao_solver.h"

namespace hullopt::app {
namespace {

// Offsets CSV (ARCHITECTURE §4: x_m,y_m,z_m, stations consecutive keel → deck edge). Minimal reader used by
// `rao` until io/ has the shared hull reader; errors name file and line.
hull::Demihull ReadOffsetsBody(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw io::InputError(file + ": cannot open offsets file");
  std::string line;
  int line_no = 1;
  if (!std::getline(in, line) || line.rfind("x_m,y_m,z_m", 0) != 0)
    throw io::InputError(file + ":1: header must start with x_m,y_m,z_m");
  hull::Demihull body;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream r(line);
    double v[3];
    for (double& x : v) {
      std::string cell;
      std::getline(r, cell, ',');
      try {
        std::size_t used = 0;
        x = std::stod(cell, &used);
      } catch (const std::exception&) {
        throw io::InputError(file + ":" + std::to_string(line_no) + ": '" + cell + "' is not a number");
      }
      if (!std::isfinite(x))
        throw io::InputError(file + ":" + std::to_string(line_no) + ": non-finite value");
    }
    if (v[1] < 0) throw io::InputError(file + ":" + std::to_string(line_no) + ": y_m must be >= 0");
    if (body.stations.empty() || body.stations.back().x_m != v[0]) {
      if (!body.stations.empty() && v[0] < body.stations.back().x_m)
        throw io::InputError(file + ":" + std::to_string(line_no) +
                             ": stations must be ordered aft to forward");
      body.stations.push_back({v[0], {}, {}});
    }
    body.stations.back().y_m.push_back(v[1]);
    body.stations.back().z_m.push_back(v[2]);
  }
  if (body.stations.size() < 2) throw io::InputError(file + ": needs at least 2 stations");
  return body;
}

std::string ResolvePath(const std::string& p, const std::string& config_file) {
  if (std::filesystem::exists(p)) return p;
  const auto alt = std::filesystem::path(config_file).parent_path() / p;
  return std::filesystem::exists(alt) ? alt.string() : p;
}

hull::HullForm ParseHull(io::YamlMap& h, const std::string& config_file, std::string* name) {
  if (h.Has("parametric"))
    h.Fail("parametric", "parametric hulls are not yet available to 'rao' in this build");
  hull::HullForm hf;
  const std::string file = ResolvePath(h.String("offsets_csv"), config_file);
  hull::Demihull body = ReadOffsetsBody(file);
  *name = std::filesystem::path(file).stem().string();
  hf.draught_m = h.Number("draught_m");
  // Waterline length L (for Fn, λ/L and coefficients) when the offsets stop short of the stem.
  if (h.Has("length_m")) {
    hf.length_m = h.Number("length_m");
    if (!(hf.length_m > 0)) h.Fail("length_m", "must be > 0");
  }
  if (!(hf.draught_m > 0)) h.Fail("draught_m", "must be > 0");
  const int hulls = h.Integer("hulls", 1);
  if (hulls != 1 && hulls != 2) h.Fail("hulls", "must be 1 (monohull) or 2 (catamaran/SWATH demihulls)");
  if (hulls == 2) {
    const double spacing = h.Number("spacing_m");
    double max_y = 0;
    for (const auto& s : body.stations)
      for (double y : s.y_m) max_y = std::max(max_y, y);
    if (!(spacing > 2 * max_y)) h.Fail("spacing_m", "must exceed the demihull's maximum breadth");
    body.y_centre_m = 0.5 * spacing;
    body.role = "demihull";
    hf.type = "catamaran";
  } else {
    body.role = "main";
    hf.type = "offsets";
  }
  hf.bodies.push_back(body);
  h.Finish();
  return hf;
}

// speed: { Fn: .. } | { kn: .. } | { m_s: .. }
double ParseSpeed(io::YamlMap& s, double length_m, double g) {
  const int given = (s.Has("Fn") ? 1 : 0) + (s.Has("kn") ? 1 : 0) + (s.Has("m_s") ? 1 : 0);
  if (given != 1) s.Fail("Fn", "give exactly one of Fn, kn or m_s");
  double u = 0;
  std::string key;
  if (s.Has("Fn")) key = "Fn", u = s.Number("Fn") * std::sqrt(g * length_m);
  if (s.Has("kn")) key = "kn", u = s.Number("kn") * 1852.0 / 3600.0;
  if (s.Has("m_s")) key = "m_s", u = s.Number("m_s");
  if (!(u > 0)) s.Fail(key, "ship speed must be > 0 (the strip method needs forward speed)");
  s.Finish();
  return u;
}

void RunRao(const std::string& config_file, const std::string& out_dir) {
  auto root = io::YamlMap::LoadFile(config_file);
  auto water = root.MapOrEmpty("water");
  const double rho = water.Number("rho_kg_m3", 1025.0), g = water.Number("g_m_s2", 9.81);
  if (!(rho > 0)) water.Fail("rho_kg_m3", "must be > 0");
  if (!(g > 0)) water.Fail("g_m_s2", "must be > 0");
  water.Finish();
  auto hull_map = root.Map("hull");
  std::string hull_name;
  const hull::HullForm hull = ParseHull(hull_map, config_file, &hull_name);
  auto solver_peek = root.Map("solver");
  hull::Hydrostatics hs;
  try {
    // Sections first: a section that does not reach the waterline is named with its body and station.
    sk::StripGeometryOptions geo;
    geo.sections = solver_peek.Has("sections") ? solver_peek.Integer("sections") : 40;
    geo.panels = solver_peek.Has("panels") ? solver_peek.Integer("panels") : 14;
    if (geo.IsValid(nullptr)) sk::StripKernelGeometry(hull, geo, 1.0, rho, g);
    hs = hull::ComputeHydrostatics(hull, rho);
  } catch (const std::exception& e) {
    throw io::InputError("hull '" + hull_name + "': " + e.what());
  }
  auto mass_map = root.MapOrEmpty("mass");
  const hull::MassProperties mass = io::ParseMassConfig(mass_map, hs);
  auto speed_map = root.Map("speed");
  const double U = ParseSpeed(speed_map, hs.L_m, g);
  auto& solver_map = solver_peek;
  const std::string kernel_kind =
      solver_map.Choice("kernel", {"transient_green", "impulsive"}, "transient_green");
  const io::SolverConfig sc = io::ParseSolverConfig(solver_map);
  root.Finish();
  if (sc.method == "strip_theory_stf")
    throw io::InputError(config_file +
                         ": key 'solver.method' = strip_theory_stf: not yet available in this build");
  sk::StripKernelBuilder builder;
  if (kernel_kind == "impulsive") {
    builder = sk::FillImpulsiveStripKernel;
  } else {
    throw io::InputError(
        config_file +
        ": key 'solver.kernel' = transient_green: the transient Green-function strip kernel is not "
        "yet in this build; 'kernel: impulsive' gives the infinite-frequency stand-in");
  }
  sk::RaoSolverOptions o;
  o.sections = sc.sections;
  o.panels = sc.panels;
  o.interaction = sc.interaction;
  o.path = sc.path == "periodic" ? sk::RaoSolverOptions::Path::kPeriodic
                                 : sk::RaoSolverOptions::Path::kTimeMarching;
  o.motion.damping_cs = sc.cs;
  o.motion.hull_name = hull_name;
  o.marching.hydrodynamic_fraction = sc.hydrodynamic_fraction;
  const auto omega = sk::WaveFrequencies(sc.frequencies, U, g, hs.L_m);
  sk::RaoTable t;
  try {
    t = sk::ComputeRaos(hull, mass, U, rho, g, omega, o, builder);
  } catch (const std::domain_error& e) {
    throw io::InputError(std::string("cannot compute RAOs: ") + e.what());
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string("cannot compute RAOs: ") + e.what());
  }
  PrepareOutputDir(out_dir, "rao", config_file, root.resolved());
  std::ostringstream fn;
  fn << "speed U = " << U << " m/s (Fn " << U / std::sqrt(g * hs.L_m) << "), method " << sc.method
     << ", kernel " << kernel_kind << ", path " << sc.path << ", " << sc.sections << " sections x "
     << sc.panels << " panels, Cs = " << sc.cs;
  try {
    io::WriteRaoCsv(OutPath(out_dir, "rao.csv"), t, hs.L_m, {"hull: " + o.motion.hull_name, fn.str()});
  } catch (const std::domain_error& e) {
    throw io::InputError(std::string("hull '") + o.motion.hull_name + "': " + e.what());
  }
  io::WriteSvg(io::RaoFigure({t}, {"time-domain strip (" + kernel_kind + ")"}, hs.L_m, "RAOs: " + fn.str()),
               OutPath(out_dir, "rao.svg"));
}

}  // namespace

void AddRaoCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("rao", "heave and pitch RAOs in head seas (rao.csv, rao.svg)");
  auto config = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  cmd->add_option("config", *config, "YAML config (hull, mass, speed, water, solver)")->required();
  cmd->add_option("--out", *out, "output folder")->required();
  cmd->callback([config, out] { RunRao(*config, *out); });
}

}  // namespace hullopt::app
