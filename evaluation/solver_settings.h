#pragma once
// The strip-solver settings of a design, held in the solver's own types: the RAO solver's options (Cs in
// rao.motion.damping_cs, the time-marching scheme and fraction in rao.marching), the form of the sectional force that
// picks the kernel builder, and the wave frequencies a config may give.
#include <string>

#include "evaluation/adaptive_frequency_grid.h"
#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/strip/strip_operators.h"

namespace hullopt::eval {

struct SolverSettings {
  sk::RaoSolverOptions rao;  ///< defaults: the paper's 40 sections x 14 panels, Cs 0, periodic path
  /// The strip momentum's rate of change (default) or the paper's fixed-point pressure integral.
  sk::SectionalForce sectional_force = sk::SectionalForce::kMomentum;
  /// How the strip momentum takes the current sources' potential (time-domain strips, momentum form).
  sk::BodyPotential body_potential = sk::BodyPotential::kSourceSum;
  sk::FrequencySpec frequencies;
  /// solver.steady_flow: on solves the running sinkage and trim in calm water on the strips
  /// (seakeeping/motions/calm_water.h) and solves the RAOs on the hull at that attitude; off (default): the
  /// hull at hull.attitude, even keel unless given.
  bool steady_flow = false;
  /// How the frequencies (given or default) are refined (solver.adaptive_grid and its caps); on by default.
  AdaptiveGridOptions grid;
  double cs() const { return rao.motion.damping_cs; }
};

/// The settings' solver options for the hull named hull_name (messages) with damping coefficient cs (the
/// settings' own, or a trial value of a calibration).
sk::RaoSolverOptions RaoOptions(const SolverSettings& settings, const std::string& hull_name, double cs);

/// The config names of the methods: "time_domain_strip", "strip_theory_stf".
std::string MethodName(sk::RaoSolverOptions::Method method);
/// The config names of the paths: "periodic", "time_marching".
std::string PathName(sk::RaoSolverOptions::Path path);
/// The config names of the time-marching schemes (rao.marching.scheme): "weighted_average_trapezoid",
/// "paper_single_pass" (the registry's, seakeeping/motions/time_scheme_registry.h).
std::string TimeSchemeName(sk::TimeSchemeKind scheme);

}  // namespace hullopt::eval
