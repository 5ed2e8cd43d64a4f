// hullopt rao CONFIG --out DIR: heave and pitch RAOs of one hull at one speed in head seas → rao.csv,
// rao.svg; with solver.headings_deg sway, heave, roll, pitch and yaw at each heading → rao.csv with a heading
// column, from the time-domain strip method's periodic steady state (the default method) or the oblique-sea
// strip theory (method strip_theory_stf).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/commands.h"
#include "app/output_dir.h"
#include "app/output_options.h"
#include "app/run_checks.h"
#include "evaluation/adaptive_frequency_grid.h"
#include "evaluation/hull_plausibility.h"
#include "evaluation/oblique_design.h"
#include "evaluation/strip_attitude.h"
#include "io/config/design_config.h"
#include "io/config/hull_config.h"
#include "io/config/motion_config.h"
#include "io/config/speed_config.h"
#include "io/config/water_config.h"
#include "io/config/yaml_map.h"
#include "io/formats/input_error.h"
#include "io/formats/rao_csv_writer.h"
#include "io/report/rao_comparison.h"
#include "io/report/rao_plot.h"
#include "optimizer/rao_peak.h"
#include "parametric_hull/hydrostatics.h"
#include "seakeeping/motions/oblique_strip_theory.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/motions/validity_range.h"
#include "seakeeping/strip/impulsive_strip_kernel.h"

namespace hullopt::app {
namespace {

// What solver.headings_deg and its mass keys give: the headings, the roll radius of gyration and the viscous
// roll damping (solver.roll_damping, solver.roll_amplitude_deg).
struct HeadingRequest {
  std::vector<double> headings_deg;
  double kxx_m = 0.0;
  bool roll_damping = false;
  double roll_amplitude_deg = 5.0;
};

// The RAOs of every heading, written as rao.csv with a heading column, by the design's method
// (eval::SolveObliqueDesign: the time-domain strip method's periodic steady state on the kernel with its
// lateral rows, or the oblique-sea strip theory, each with the design's Cs in heave and pitch). Yaw's radius
// of gyration is taken as pitch's.
void WriteObliqueRaos(const HeadingRequest& req, const eval::DesignCase& design, double U,
                      const io::WaterOptions& water, const std::vector<double>& omega,
                      const std::string& hull_name, std::vector<std::string> notes,
                      const std::string& out_dir) {
  const hull::Hydrostatics& hs = design.hydrostatics;
  sk::ObliqueStripOptions o;
  if (req.roll_damping) {
    sk::RollDampingOptions roll;
    roll.model = sk::RollDampingModel::kIkeda;
    roll.roll_amplitude_rad = req.roll_amplitude_deg * M_PI / 180.0;
    eval::SetDesignRollDamping(design, roll, &o);
  }
  sk::ObliqueStripResult r;
  int roll_flags = 0;
  std::vector<std::string> warnings;
  try {
    r = eval::SolveObliqueDesign(design, U, omega, req.headings_deg, req.kxx_m, o, &warnings);
  } catch (const std::domain_error& e) {
    throw io::InputError(std::string("cannot compute RAOs: ") + e.what());
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string("cannot compute RAOs: ") + e.what());
  }
  for (const auto& w : warnings) {
    std::fprintf(stderr, "hullopt: warning: hull '%s': %s\n", hull_name.c_str(), w.c_str());
    notes.push_back("warning: " + w);
  }
  // The viscous roll damping: what was used, its size at the roll resonance, and where the hull lies outside
  // the method's range (a warning in every output).
  std::ostringstream rd;
  const double wn = eval::RollNaturalFrequency(r);
  if (!req.roll_damping) {
    rd << "roll damping: potential only (solver.roll_damping: none): roll near its resonance is too large";
  } else {
    rd << "roll damping: " << eval::RollDampingNote(o);
    if (wn > 0.0) {
      for (const auto& w : r.waves)
        if (w.omega_e_rad_s == wn) {
          rd << "; at the roll natural frequency " << wn << " rad/s viscous B44 " << w.viscous_roll_damping
             << " N m s, potential " << w.damping(3, 3) << " N m s";
          break;
        }
    }
    for (const auto& f : sk::RollDampingRangeFlags(o.roll_damping_hull, wn, U, o.roll_damping)) {
      std::fprintf(stderr, "hullopt: warning: hull '%s': %s\n", hull_name.c_str(), f.c_str());
      notes.push_back("warning: " + f);
      ++roll_flags;
    }
  }
  std::ostringstream os;
  os << eval::ObliqueMethodNote(design) << " at " << req.headings_deg.size() << " headings, kxx = " << req.kxx_m;
  os << " m, kzz = kyy, the given frequencies (no adaptive refinement)";
  notes.push_back(os.str());
  notes.push_back(rd.str());
  try {
    io::WriteObliqueRaoCsv(OutPath(out_dir, "rao.csv"), r, U, water.g_m_s2, hs.L_m, notes);
  } catch (const std::domain_error& e) {
    throw io::InputError(std::string("hull '") + hull_name + "': " + e.what());
  }
  Say("hull '%s': RAOs of sway, heave, roll, pitch and yaw at %zu headings x %zu frequencies; roll damping %s%s; "
      "wrote rao.csv in %s\n",
      hull_name.c_str(), req.headings_deg.size(), omega.size(),
      !req.roll_damping ? "potential only" : o.roll_damping_hull.Multihull() ? "demihull Cs" : "Ikeda",
      roll_flags ? (" (" + std::to_string(roll_flags) + " warning(s): outside its range)").c_str() : "",
      out_dir.c_str());
}

void RunRao(const std::string& config_file, const std::string& out_dir) {
  auto root = io::YamlMap::LoadFile(config_file);
  io::DesignReadOptions read;
  read.frequencies_required = true;
  read.impulsive_kernel = true;
  read.headings = true;
  read.name_after_hull = [&](const io::HullOptions& h) {
    return io::ParseDesignName(root, h.file.empty() ? std::filesystem::path(config_file).stem().string()
                                                    : std::filesystem::path(h.file).stem().string());
  };
  io::ParsedDesign parsed = io::ParseDesign(root, config_file, "design", read);
  const std::optional<io::RaoComparisonSource> compare = io::ParseRaoComparison(root);
  root.Finish();  // the whole config read and checked before the hull is built
  const std::string& hull_name = parsed.spec.name;
  const std::string& kernel_kind = parsed.kernel;
  // The hull at rest (L for Fn and the wavelengths, mass defaults) and at its running attitude: given, or
  // solved in calm water (solver.steady_flow: on); the strips see the running one.
  const eval::DesignCase design = io::BuildParsedDesign(parsed);
  const io::WaterOptions& water = design.water;
  const hull::HullForm& hull = design.hull;
  const hull::Hydrostatics& hs = design.hydrostatics;
  const hull::MassProperties& mass = design.mass;
  const eval::SolverSettings& sc = design.solver;
  const hull::RunningAttitude& attitude = design.attitude;
  const hull::HullForm& running = design.running_hull;
  const double U = design.speed_m_s;
  std::vector<std::string> input_warnings = design.input_warnings;
  // solver.headings_deg: the oblique-sea strip theory at every heading, roll with kxx (default from the beam).
  HeadingRequest headings;
  headings.headings_deg = parsed.headings_deg;
  const bool oblique = !headings.headings_deg.empty();
  if (oblique) headings.kxx_m = parsed.kxx_m ? *parsed.kxx_m : eval::DefaultRollRadiusOfGyration(hull);
  headings.roll_damping = parsed.roll_damping == "ikeda";
  headings.roll_amplitude_deg = parsed.roll_amplitude_deg;
  std::optional<io::MeasuredRao> measured;
  if (compare)
    measured = io::ReadRaoComparison(*compare, U / std::sqrt(water.g_m_s2 * hs.L_m), hs.L_m, water.g_m_s2);
  sk::StripKernel geometry;  // panelled once: the check here, then the solver
  try {
    // Sections first: a section that does not reach the waterline is named with its body and station.
    geometry = sk::StripKernelGeometry(running, sc.rao.Geometry(), U, water.rho_kg_m3, water.g_m_s2);
    hull::ComputeHydrostatics(running, water.rho_kg_m3);
  } catch (const std::exception& e) {
    throw io::InputError("hull '" + hull_name + "': " + e.what());
  }
  const sk::StripKernelBuilder builder = kernel_kind == "impulsive"
                                             ? sk::StripKernelBuilder(sk::FillImpulsiveStripKernel)
                                             : sk::TransientGreenKernelBuilder(sc.sectional_force, sc.body_potential);
  const sk::RaoSolverOptions o = eval::RaoOptions(sc, hull_name, sc.cs());
  const auto omega = sk::WaveFrequencies(sc.frequencies, U, water.g_m_s2, hs.L_m);
  CheckOutputDirConfig(out_dir, "rao", root.resolved());
  io::StripWork work = io::StripWorkFromResolved(root.resolved(), static_cast<long>(omega.size()));
  work.headings = static_cast<int>(headings.headings_deg.size());
  CheckRunCost("rao", work);
  if (oblique) {
    for (const auto& w : input_warnings)
      std::fprintf(stderr, "hullopt: warning: hull '%s': %s\n", hull_name.c_str(), w.c_str());
    PrepareOutputDir(out_dir, "rao", config_file, root.resolved());
    std::vector<std::string> notes = {"hull: " + hull_name};
    std::ostringstream fn;
    fn << "speed U = " << U << " m/s (Fn " << U / std::sqrt(water.g_m_s2 * hs.L_m) << "), method "
       << eval::MethodName(sc.rao.method) << ", " << sc.rao.sections << " sections x " << sc.rao.panels
       << " panels";
    notes.push_back(fn.str());
    for (const auto& a : hull.adjustments) notes.push_back("adjusted: " + a);
    for (const auto& w : input_warnings) notes.push_back("warning: " + w);
    WriteObliqueRaos(headings, design, U, water, omega, hull_name, notes, out_dir);
    return;
  }
  sk::RaoTable t;
  try {
    // solver.adaptive_grid (on by default): the peaks refined from the given grid, the kernel built once.
    const sk::RaoSweeper sweeper(running, mass, U, water.rho_kg_m3, water.g_m_s2, o, builder, &geometry);
    t = eval::SweepAdaptively(sweeper, omega, sc.grid);
  } catch (const std::domain_error& e) {
    throw io::InputError(std::string("cannot compute RAOs: ") + e.what());
  } catch (const std::invalid_argument& e) {
    throw io::InputError(std::string("cannot compute RAOs: ") + e.what());
  }
  t.warnings.insert(t.warnings.begin(), input_warnings.begin(), input_warnings.end());
  if (sc.rao.method == sk::RaoSolverOptions::Method::kTimeDomainStrip)
    for (auto& w : sk::ValidityWarnings(U, hs.L_m, water.g_m_s2, t.omega_rad_s)) t.warnings.push_back(std::move(w));
  for (const auto& w : t.warnings) std::fprintf(stderr, "hullopt: warning: hull '%s': %s\n", hull_name.c_str(), w.c_str());
  for (const auto& a : hull.adjustments) std::fprintf(stderr, "hullopt: note: hull '%s': %s\n", hull_name.c_str(), a.c_str());
  PrepareOutputDir(out_dir, "rao", config_file, root.resolved());
  std::ostringstream fn;
  fn << "speed U = " << U << " m/s (Fn " << U / std::sqrt(water.g_m_s2 * hs.L_m) << "), method " << eval::MethodName(sc.rao.method)
     << ", kernel " << kernel_kind << ", path " << eval::PathName(sc.rao.path)
     << (sc.rao.path == sk::RaoSolverOptions::Path::kTimeMarching
             ? " (time scheme " + eval::TimeSchemeName(sc.rao.marching.scheme) + ")"
             : std::string())
     << ", " << sc.rao.sections << " sections x "
     << sc.rao.panels << " panels, Cs = " << sc.cs() << (sc.rao.interaction ? "" : ", bodies without interaction")
     << (sc.sectional_force == sk::SectionalForce::kPressure ? ", sectional force: pressure form" : "")
     << (sc.body_potential == sk::BodyPotential::kGreenIdentity ? ", body potential: Green's identity" : "")
     << (sc.rao.section_formulation == sk::SectionFormulation::kDirect ? ", sections: direct formulation" : "");
  if (const std::string note = eval::AttitudeNote(attitude, sc); !note.empty()) fn << ", " << note;
  try {
    std::vector<std::string> header = {"hull: " + hull_name, fn.str()};
    for (const auto& a : hull.adjustments) header.push_back("adjusted: " + a);
    for (const auto& w : t.warnings) header.push_back("warning: " + w);
    io::WriteRaoCsv(OutPath(out_dir, "rao.csv"), t, hs.L_m, header);
  } catch (const std::domain_error& e) {
    throw io::InputError(std::string("hull '") + hull_name + "': " + e.what());
  }
  const std::string curve =
      sc.rao.method == sk::RaoSolverOptions::Method::kStripTheory ? "strip theory (STF type)" : "time-domain strip (" + kernel_kind + ")";
  if (!NoPlotsGiven())  // the figure after the numbers
    io::WriteSvg(io::RaoFigure({t}, {curve}, hs.L_m, "RAOs: " + fn.str(), measured ? &*measured : nullptr),
                 OutPath(out_dir, "rao.svg"));
  // One line for the console: where the heave and pitch peaks are (parabola through the largest sample).
  std::vector<double> lam, heave, pitch;
  for (std::size_t i = 0; i < t.omega_rad_s.size(); ++i) {
    lam.push_back(2 * M_PI * water.g_m_s2 / (t.omega_rad_s[i] * t.omega_rad_s[i]) / hs.L_m);
    heave.push_back(std::abs(t.heave[i]));
    pitch.push_back(std::abs(t.pitch[i]));
  }
  const auto h = opt::InterpolatedPeak(lam, heave), p = opt::InterpolatedPeak(lam, pitch);
  auto edge = [](const opt::RaoPeak& r) { return r.at_edge ? " (at the end of the range)" : ""; };
  Say("hull '%s': heave peak %.4g m/m at lambda/L %.3g%s, pitch peak %.4g rad/rad at lambda/L %.3g%s; "
      "%swrote rao.csv%s in %s\n",
      hull_name.c_str(), h.value, h.x, edge(h), p.value, p.x, edge(p),
      measured ? ("measured points drawn: " + std::to_string(measured->heave_amp.size()) + "; ").c_str() : "",
      NoPlotsGiven() ? "" : ", rao.svg", out_dir.c_str());
}

}  // namespace

void AddRaoCommand(CLI::App& app) {
  AddConfigCommand(
      app,
      {"rao", "heave and pitch RAOs in head seas, or all modes at solver.headings_deg (rao.csv, rao.svg)",
       "YAML config (hull, mass, speed, water, solver, compare)"},
      RunRao);
}

}  // namespace hullopt::app
