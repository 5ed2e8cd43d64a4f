// hullopt hull CONFIG --out DIR: generate or read a hull, write its hydrostatics, offsets and body plan.
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "app/commands.h"
#include "app/output_options.h"
#include "app/output_dir.h"
#include "evaluation/hull_plausibility.h"
#include "io/report/bodyplan_svg.h"
#include "io/report/html_report.h"
#include "io/config/hull_config.h"
#include "io/formats/hydrostatics_json.h"
#include "io/formats/input_error.h"
#include "io/config/motion_config.h"
#include "io/formats/offsets_csv.h"
#include "io/config/speed_config.h"
#include "io/config/water_config.h"
#include "parametric_hull/hydrostatics.h"

namespace hullopt::app {
namespace {

// Top-level keys other commands own; a shared campaign config may carry them.
const char* const kOtherCommandsKeys[] = {"solver",    "seas",     "section", "optimize",
                                          "calibrate", "evaluate", "explore", "resistance"};

void RunHull(const std::string& config, const std::string& out_dir) {
  io::YamlMap root = io::YamlMap::LoadFile(config);
  const io::WaterOptions water = io::ParseWater(root);
  const io::HullOptions hull_opts = io::ParseHullConfig(root, water);
  bool has_speed = false;
  const io::SpeedOptions speed = io::ParseSpeed(root, false, &has_speed);
  for (const char* k : kOtherCommandsKeys) root.Skip(k);

  const hull::HullForm hull = io::LoadHull(hull_opts, config);
  hull::Hydrostatics hs;
  try {
    hs = hull::ComputeHydrostatics(hull, water.rho_kg_m3, hull.draught_m);
  } catch (const std::logic_error& e) {
    throw io::InputError(config + ": key 'hull': " + e.what());
  }
  // The mass block as the motion commands read it (KG defaults to the draught, LCG to the LCB), with the same
  // checks; its LCG is the running attitude's pivot.
  std::vector<std::string> warnings;
  hull::MassProperties m;
  {
    io::YamlMap mass = root.MapOrEmpty("mass");
    m = io::ParseMassConfig(mass, hs, &warnings);
    hs = hull::ComputeHydrostatics(hull, water.rho_kg_m3, m.kg_m);
  }
  for (auto& w : eval::ApplyDesignEnvelope(
           water, has_speed ? speed.MetresPerSecond(hs.L_m, water.g_m_s2) : NAN, NAN, hull, hs, &m, config))
    warnings.push_back(std::move(w));
  root.Finish();
  io::HydrostaticsReport rep;
  rep.warnings = warnings;
  rep.hs = hs;
  rep.adjustments = hull.adjustments;
  if (!hull_opts.attitude.IsEvenKeel()) {
    rep.attitude = hull_opts.attitude;
    rep.attitude.pivot_x_m = m.lcg_m_from_ap;
    const hull::HullForm running = io::ApplyHullAttitude(hull_opts, hull, rep.attitude.pivot_x_m, config);
    try {
      rep.running = hull::ComputeHydrostatics(running, water.rho_kg_m3, m.kg_m);
    } catch (const std::logic_error& e) {
      throw io::InputError(config + ": key 'hull.attitude': " + e.what());
    }
  }
  PrepareOutputDir(out_dir, "hull", config, root.resolved());
  for (const auto& w : warnings) std::cerr << "hullopt: warning: " << w << "\n";
  rep.rho_kg_m3 = water.rho_kg_m3;
  rep.g_m_s2 = water.g_m_s2;
  if (has_speed) rep.speed_m_s = speed.MetresPerSecond(hs.L_m, water.g_m_s2);
  io::WriteHydrostaticsJson(OutPath(out_dir, "hydrostatics.json"), hull, rep);
  io::WriteOffsetsCsv(OutPath(out_dir, "offsets.csv"), hull);
  std::ostringstream title;
  title << hull.type << " — L " << io::FormatNumber(hs.L_m) << " m, B " << io::FormatNumber(hs.B_m) << " m, T "
        << io::FormatNumber(hs.T_m) << " m, " << io::FormatNumber(hs.displacement_t) << " t";
  io::WriteBodyPlanSvg(OutPath(out_dir, "bodyplan.svg"), hull, title.str());

  Out() << "hull " << hull.type << ": L = " << hs.L_m << " m, B = " << hs.B_m << " m, T = " << hs.T_m
            << " m, displacement = " << hs.displacement_t << " t (rho " << water.rho_kg_m3 << " kg/m^3)\n"
            << "  Cb " << hs.Cb << "  Cp " << hs.Cp << "  Cm " << hs.Cm << "  Cwp " << hs.Cwp << "  Cvp "
            << hs.Cvp << "  LCB " << hs.LCB_pct_L << " %L  LCF " << hs.LCF_pct_L << " %L";
  if (rep.speed_m_s) Out() << "  Fr " << *rep.speed_m_s / std::sqrt(water.g_m_s2 * hs.L_m);
  if (rep.running)
    Out() << "\n  running attitude (sinkage " << rep.attitude.sinkage_m << " m + down, trim "
              << rep.attitude.trim_deg << " deg + bow up, at x = " << rep.attitude.pivot_x_m
              << " m): displacement " << rep.running->displacement_t << " t, LCB " << rep.running->lcb_m_from_ap
              << " m from AP, waterplane " << rep.running->awp_m2 << " m^2";
  for (const auto& a : hull.adjustments) Out() << "\n  adjusted: " << a;
  Out() << "\n  wrote " << out_dir
            << "/{hydrostatics.json, offsets.csv, bodyplan.svg, config.resolved.yaml}\n";
}

}  // namespace

void AddHullCommand(CLI::App& app) {
  AddConfigCommand(app,
                   {"hull",
                    "Generate (parametric) or read (offsets CSV / STL) a hull and write hydrostatics.json, "
                    "offsets.csv and bodyplan.svg",
                    "YAML config with a hull: map (and optional water:, speed:, mass:)"},
                   RunHull);
}

}  // namespace hullopt::app
