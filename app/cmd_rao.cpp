// hullopt rao CONFIG --out DIR: heave and pitch RAOs of one hull at one speed in head seas → rao.csv,
// rao.svg.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/commands.h"
#include "app/output_options.h"
#include "app/output_dir.h"
#include "app/run_checks.h"
#include "evaluation/adaptive_frequency_grid.h"
#include "evaluation/hull_plausibility.h"
#include "evaluation/strip_attitude.h"
#include "io/config/design_config.h"
#include "io/config/hull_config.h"
#include "io/formats/input_error.h"
#include "io/config/motion_config.h"
#include "io/report/rao_comparison.h"
#include "io/formats/rao_csv_writer.h"
#include "io/report/rao_plot.h"
#include "io/config/speed_config.h"
#include "io/config/water_config.h"
#include "io/config/yaml_map.h"
#include "optimizer/rao_peak.h"
#include "parametric_hull/hydrostatics.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/motions/validity_range.h"
#include "seakeeping/strip/impulsive_strip_kernel.h"

namespace hullopt::app {
namespace {

void RunRao(const std::string& config_file, const std::string& out_dir) {
  auto root = io::YamlMap::LoadFile(config_file);
  const io::WaterOptions water = io::ParseWater(root);
  const io::HullOptions hull_opts = io::ParseHullConfig(root, water);
  const io::SpeedOptions speed = io::ParseSpeed(root, true);
  std::vector<std::string> input_warnings;
  const hull::HullForm hull = io::LoadHull(hull_opts, config_file, &input_warnings);
  const std::string hull_name = io::ParseDesignName(root, hull_opts.file.empty()
                                                              ? std::filesystem::path(config_file).stem().string()
                                                              : std::filesystem::path(hull_opts.file).stem().string());
  auto solver_map = root.Map("solver");
  const std::string kernel_kind =
      solver_map.Choice("kernel", {"transient_green", "impulsive"}, "transient_green");
  const io::SolverConfig sc = io::ParseSolverConfig(solver_map);
  if (kernel_kind == "impulsive" && sc.body_potential != sk::BodyPotential::kSourceSum)
    solver_map.Fail("body_potential", "the impulsive stand-in kernel has the source sum only (use kernel: "
                                      "transient_green)");
  if (kernel_kind == "impulsive" && sc.sectional_force == sk::SectionalForce::kPressure)
    solver_map.Fail("sectional_force", "the impulsive stand-in kernel has the momentum form only (use kernel: "
                                       "transient_green)");
  hull::Hydrostatics hs;  // at rest: L for Fn and the wavelengths, mass defaults
  try {
    hs = hull::ComputeHydrostatics(hull, water.rho_kg_m3);
  } catch (const std::exception& e) {
    throw io::InputError("hull '" + hull_name + "': " + e.what());
  }
  auto mass_map = root.MapOrEmpty("mass");
  const hull::MassProperties mass = io::ParseMassConfig(mass_map, hs, &input_warnings);
  const double U = speed.MetresPerSecond(hs.L_m, water.g_m_s2);
  {
    eval::EnvelopeInput env;
    env.rho_kg_m3 = water.rho_kg_m3;
    env.g_m_s2 = water.g_m_s2;
    env.speed_m_s = U;
    env.cs = sc.cs();
    env.hull = &hull;
    env.hs = &hs;
    env.mass = &mass;
    for (auto& w : eval::ApplyEnvelope(eval::CheckEnvelope(env), config_file)) input_warnings.push_back(std::move(w));
  }
  const std::optional<io::MeasuredRao> measured =
      io::ReadRaoComparison(root, U / std::sqrt(water.g_m_s2 * hs.L_m), hs.L_m, water.g_m_s2);
  root.Finish();
  // The strips see the hull at its running attitude (the hull itself at even keel): given, or solved in calm
  // water (solver.steady_flow: on).
  const hull::RunningAttitude attitude =
      eval::StripAttitude(hull, mass, U, water, sc, hull_opts.attitude, config_file + ": hull '" + hull_name + "'");
  const hull::HullForm running = sc.steady_flow ? hull::ApplyRunningAttitude(hull, attitude)
                                                : io::ApplyHullAttitude(hull_opts, hull, mass.lcg_m_from_ap, config_file);
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
  CheckRunCost("rao", io::StripWorkFromResolved(root.resolved(), static_cast<long>(omega.size())));
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
  AddConfigCommand(app,
                   {"rao", "heave and pitch RAOs in head seas (rao.csv, rao.svg)",
                    "YAML config (hull, mass, speed, water, solver, compare)"},
                   RunRao);
}

}  // namespace hullopt::app
