// hullopt resistance CONFIG --out DIR: calm-water resistance and effective power of one hull against speed
// → resistance.csv, resistance.svg.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "app/commands.h"
#include "app/output_options.h"
#include "app/output_dir.h"
#include "evaluation/hull_plausibility.h"
#include "io/config/design_config.h"
#include "io/config/hull_config.h"
#include "io/formats/input_error.h"
#include "io/config/resistance_config.h"
#include "io/report/resistance_output.h"
#include "io/config/speed_config.h"
#include "io/config/water_config.h"
#include "parametric_hull/hydrostatics.h"
#include "resistance/water_viscosity.h"

namespace hullopt::app {
namespace {

// Top-level keys other commands own; a shared campaign config may carry them.
const char* const kOtherCommandsKeys[] = {"solver",  "seas",     "section", "optimize", "calibrate",
                                          "evaluate", "explore", "mass",    "msi",      "positions",
                                          "report",   "operability"};

void RunResistance(const std::string& config, const std::string& out_dir) {
  io::YamlMap root = io::YamlMap::LoadFile(config);
  const io::WaterOptions water = io::ParseWater(root);
  const io::HullOptions hull_opts = io::ParseHullConfig(root, water);
  bool has_speed = false;
  const io::SpeedOptions speed = io::ParseSpeed(root, false, &has_speed);
  const io::ResistanceConfig rc = io::ParseResistanceConfig(root, true);
  const std::string hull_name = io::ParseDesignName(root, hull_opts.file.empty()
                                                              ? std::filesystem::path(config).stem().string()
                                                              : std::filesystem::path(hull_opts.file).stem().string());
  for (const char* k : kOtherCommandsKeys) root.Skip(k);
  root.Finish();
  const hull::HullForm hull = io::LoadHull(hull_opts, config);
  hull::Hydrostatics hs;
  std::unique_ptr<res::CalmWaterResistance> model;
  try {
    hs = hull::ComputeHydrostatics(hull, water.rho_kg_m3);
    model = std::make_unique<res::CalmWaterResistance>(hull, rc.options);
  } catch (const std::logic_error& e) {
    throw io::InputError(config + ": key 'hull': " + e.what());
  }
  std::vector<double> speeds = rc.MetresPerSecond(model->MainLength_m(), water.g_m_s2);
  if (speeds.empty()) {
    if (!has_speed)
      throw io::InputError(config + ": key 'resistance': give resistance.speeds_kn, speeds_Fn or speed_range_kn (or a "
                                    "design speed `speed:`)");
    speeds.push_back(speed.MetresPerSecond(model->MainLength_m(), water.g_m_s2));
  }
  // The validity envelope: the water and the hull once, each speed in its row (Michell's thin-ship theory, like
  // the strips, assumes a hull floating on its at-rest waterline: planing speeds are flagged or refused).
  eval::EnvelopeInput env;
  env.rho_kg_m3 = water.rho_kg_m3;
  env.g_m_s2 = water.g_m_s2;
  env.hull = &hull;
  env.hs = &hs;
  const std::vector<std::string> envelope_warnings = eval::ApplyEnvelope(eval::CheckEnvelope(env), config);
  std::vector<res::ResistanceAtSpeed> rows;
  for (double U : speeds) {
    try {
      rows.push_back(model->At(U, water.rho_kg_m3, water.g_m_s2));
    } catch (const std::invalid_argument& e) {
      throw io::InputError(config + ": key 'resistance': " + e.what());
    }
    eval::EnvelopeInput at_speed;
    at_speed.g_m_s2 = water.g_m_s2;
    at_speed.speed_m_s = U;
    at_speed.hs = &hs;
    for (const auto& f : eval::CheckEnvelope(at_speed)) {
      if (f.refuse) throw io::InputError(config + ": key 'resistance': " + f.message);
      rows.back().warning += (rows.back().warning.empty() ? "" : "; ") + f.message;
    }
  }
  PrepareOutputDir(out_dir, "resistance", config, root.resolved());
  const double nu = rc.options.kinematic_viscosity_m2_s > 0.0 ? rc.options.kinematic_viscosity_m2_s
                                                              : res::ViscosityForDensity(water.rho_kg_m3);
  std::ostringstream cond;
  cond << "L " << model->MainLength_m() << " m, S " << model->WettedSurface_m2() << " m^2, "
       << hs.displacement_t << " t; rho " << water.rho_kg_m3 << " kg/m^3, nu " << nu << " m^2/s"
       << (rc.options.kinematic_viscosity_m2_s > 0.0 ? " (given)" : " (15 C, by density)") << ", 1+k "
       << rc.options.form_factor << ", transom area " << model->Transom().area_m2 << " m^2";
  std::vector<std::string> header = {"hull: " + hull_name + " (" + hull.type + ")", cond.str(),
                                     "ITTC-1957 friction, Michell thin-ship wave resistance with multihull "
                                     "interference, dry-transom hydrostatic deficit (docs/resistance.md)"};
  for (const auto& w : envelope_warnings) {
    std::fprintf(stderr, "hullopt: warning: hull '%s': %s\n", hull_name.c_str(), w.c_str());
    header.push_back("warning: " + w);
  }
  int warned = 0;
  for (const auto& r : rows)
    if (!r.warning.empty()) {
      if (warned++ == 0)
        std::fprintf(stderr, "hullopt: warning: hull '%s' at %.4g kn: %s\n", hull_name.c_str(),
                     r.U_m_s / io::kMetresPerSecondPerKnot, r.warning.c_str());
    }
  if (warned > 1) std::fprintf(stderr, "hullopt: warning: %d speeds carry a warning (column 'warning')\n", warned);
  io::WriteResistanceCsv(OutPath(out_dir, "resistance.csv"), rows, header);
  io::WriteSvg(io::ResistanceFigure(rows, "Calm-water resistance: " + hull_name + " (" + hull.type + ")", cond.str()),
               OutPath(out_dir, "resistance.svg"));
  const auto& last = rows.back();
  Say("hull '%s': %zu speeds; at %.4g kn (Fn %.3g): R_T %.4g kN (R_W %.3g, (1+k)R_F %.3g, R_h %.3g), "
      "C_T %.4g, P_E %.4g kW; wrote resistance.csv, resistance.svg in %s\n",
      hull_name.c_str(), rows.size(), last.U_m_s / io::kMetresPerSecondPerKnot, last.Fn, last.R_T_N / 1e3,
      last.R_W_N / 1e3, last.R_V_N / 1e3, last.R_H_N / 1e3, last.C_T, last.P_E_W / 1e3, out_dir.c_str());
}

}  // namespace

void AddResistanceCommand(CLI::App& app) {
  AddConfigCommand(app,
                   {"resistance",
                    "calm-water resistance and effective power against speed (resistance.csv, resistance.svg)",
                    "YAML config (hull, water, resistance, speed)"},
                   RunResistance);
}

}  // namespace hullopt::app
