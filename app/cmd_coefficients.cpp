// hullopt coefficients CONFIG --out DIR: the heave–pitch added mass, damping, restoring and exciting loads of
// one hull at one speed in head seas, from the same strips as `hullopt rao` → coefficients.csv,
// coefficients.svg (with measured forced-oscillation and restrained-model points from `compare:`).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/commands.h"
#include "app/output_options.h"
#include "io/config/design_config.h"
#include "app/output_dir.h"
#include "app/run_checks.h"
#include "io/formats/coefficients_csv_writer.h"
#include "io/report/coefficients_plot.h"
#include "io/config/config_path.h"
#include "io/formats/input_error.h"
#include "io/formats/measured_coefficients_csv.h"
#include "io/config/yaml_map.h"

namespace hullopt::app {
namespace {

void RunCoefficients(const std::string& config_file, const std::string& out_dir) {
  auto root = io::YamlMap::LoadFile(config_file);
  const std::string name = io::ParseDesignName(root, std::filesystem::path(config_file).stem().string());
  io::ParsedDesign parsed = io::ParseDesign(root, config_file, name);
  if (!parsed.spec.has_frequencies)
    root.Map("solver").Fail("frequencies", "required: the frequencies of the coefficients");
  // compare: measured points to draw over the computed curves (io/formats/measured_coefficients_csv.h).
  std::vector<io::MeasuredCoefficientRow> heave, pitch;
  std::vector<io::MeasuredWaveLoadRow> loads;
  std::string trim = "zero";
  int skipped = 0;
  if (root.Has("compare")) {
    auto c = root.Map("compare");
    if (c.Has("forced_heave_csv"))
      heave = io::ReadForcedOscillationCsv(io::ConfigFilePath(c, "forced_heave_csv"), 3);
    if (c.Has("forced_pitch_csv"))
      pitch = io::ReadForcedOscillationCsv(io::ConfigFilePath(c, "forced_pitch_csv"), 5);
    if (c.Has("wave_loads_csv"))
      loads = io::ReadRestrainedWaveLoadCsv(io::ConfigFilePath(c, "wave_loads_csv"),
                                            &skipped);
    trim = c.String("trim_sinkage", trim);
    c.Finish();
  }
  root.Finish();  // the whole config read and checked before the design is built
  const eval::DesignCase d = io::BuildParsedDesign(parsed);
  const double L = d.hydrostatics.L_m, g = d.water.g_m_s2;
  const auto omega = sk::WaveFrequencies(d.solver.frequencies, d.speed_m_s, g, L);
  CheckOutputDirConfig(out_dir, "coefficients", root.resolved());
  CheckRunCost("coefficients", io::StripWorkFromResolved(root.resolved(), static_cast<long>(omega.size())));
  const sk::CoefficientTable t = eval::ComputeDesignCoefficients(d, omega);
  for (const auto& w : t.warnings) std::fprintf(stderr, "hullopt: warning: hull '%s': %s\n", name.c_str(), w.c_str());
  PrepareOutputDir(out_dir, "coefficients", config_file, root.resolved());
  const double Fn = d.speed_m_s / std::sqrt(g * L);
  std::ostringstream fn;
  fn << "speed U = " << d.speed_m_s << " m/s (Fn " << Fn << "), method " << eval::MethodName(d.solver.rao.method) << ", "
     << d.solver.rao.sections << " sections x " << d.solver.rao.panels << " panels, Cs = " << d.solver.cs()
     << (d.solver.rao.interaction ? "" : ", bodies without interaction")
     << (d.solver.sectional_force == sk::SectionalForce::kPressure ? ", sectional force: pressure form" : "")
     << (d.solver.body_potential == sk::BodyPotential::kGreenIdentity ? ", body potential: Green's identity" : "")
     << (d.solver.rao.section_formulation == sk::SectionFormulation::kDirect ? ", sections: direct formulation" : "");
  std::vector<std::string> notes = {"hull: " + name, fn.str()};
  for (const auto& w : t.warnings) notes.push_back("warning: " + w);
  try {
    io::WriteCoefficientsCsv(OutPath(out_dir, "coefficients.csv"), t, L, notes);
  } catch (const std::domain_error& e) {
    throw io::InputError("hull '" + name + "': " + e.what());
  }
  const std::string curve =
      d.solver.rao.method == sk::RaoSolverOptions::Method::kStripTheory ? "strip theory (STF type)" : "time-domain strip";
  io::MeasuredCoefficientPoints m =
      io::MeasuredPointsForSpeed(heave, pitch, loads, Fn, trim, d.speed_m_s, g, L);
  const bool any = !m.heave_x.empty() || !m.pitch_x.empty() || !m.load_x.empty();
  if (any && skipped > 0) m.label += " (" + std::to_string(skipped) + " doubtful row(s) left out)";
  io::WriteSvg(io::CoefficientsFigure({t}, {curve}, L, "Coefficients: " + fn.str(), any ? &m : nullptr),
               OutPath(out_dir, "coefficients.svg"));
  Say("hull '%s': %zu frequencies, omega_e sqrt(L/g) %.3g to %.3g; measured points drawn: %zu heave, "
      "%zu pitch, %zu wave loads; wrote coefficients.csv, coefficients.svg in %s\n",
      name.c_str(), t.rows.size(), t.rows.front().omega_e_rad_s * std::sqrt(L / g),
      t.rows.back().omega_e_rad_s * std::sqrt(L / g), m.heave_x.size(), m.pitch_x.size(),
      m.load_x.size(), out_dir.c_str());
}

}  // namespace

void AddCoefficientsCommand(CLI::App& app) {
  AddConfigCommand(app,
                   {"coefficients",
                    "heave-pitch added mass, damping and wave loads in head seas (coefficients.csv, .svg)",
                    "YAML config (hull, mass, speed, water, solver, optional compare)"},
                   RunCoefficients);
}

}  // namespace hullopt::app
