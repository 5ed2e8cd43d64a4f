#pragma once
// One design as the evaluations that need RAOs see it (evaluate, optimize, calibrate): the hull, its
// hydrostatics and mass properties, the speed and the strip-solver settings, and the calls that turn it into
// heave and pitch RAOs with the paper's time-domain strip method. io/config/design_config.h fills one from a
// config.
#include <map>
#include <string>
#include <vector>

#include "evaluation/adaptive_frequency_grid.h"
#include "evaluation/solver_settings.h"
#include "evaluation/water.h"
#include "parametric_hull/hydrostatics.h"
#include "parametric_hull/running_attitude.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/motions/rao_table.h"
#include "seas/passenger_positions.h"

namespace hullopt::eval {

struct DesignCase {
  std::string name;
  hull::HullForm hull;          ///< at rest, even keel: coefficients, mass defaults, Fr, passenger positions
  hull::HullForm running_hull;  ///< at `attitude` (= hull at even keel): strips and RAOs
  hull::RunningAttitude attitude;  ///< hull.attitude, or solved in calm water with solver.steady_flow: on
  hull::Hydrostatics hydrostatics;  ///< of `hull` (at rest)
  hull::MassProperties mass;
  /// Plausibility warnings of the hull and mass (parametric_hull/plausibility.h), carried into every RAO
  /// table computed for this design and so into every output.
  std::vector<std::string> input_warnings;
  WaterOptions water;
  double speed_m_s = 0.0;        ///< [m/s]
  SolverSettings solver;         ///< Cs, sections, panels, path ...
  bool has_frequencies = false;  ///< solver.frequencies were given
  /// CG-to-transom and CG-to-bow distances for the passenger positions [m].
  sk::HullExtent Extent() const;
  /// Fr, Cvp, B_over_T, L_over_B, L_m of the main body: axes of the study plots; with a running attitude also
  /// running_sinkage_m (+ down) and running_trim_deg (+ bow up).
  std::map<std::string, double> Parameters() const;
};

/// RAOs of the design at wave frequencies omega_rad_s (increasing, > 0) by its solver method: the
/// time-domain strip method (transient Green-function kernel) or conventional strip theory. Cs overrides the
/// design's when >= 0. With design.solver.grid.enabled (solver.adaptive_grid, on by default) omega_rad_s is
/// the starting grid, refined until the RAO peaks and the MSI and accelerations of `seas` (if given) converge
/// (evaluation/adaptive_frequency_grid.h; the strip kernel is built once); off: exactly omega_rad_s. Throws
/// InputError naming the design for a hull that cannot be solved or non-finite results.
sk::RaoTable ComputeDesignRaos(const DesignCase& design, const std::vector<double>& omega_rad_s,
                               double cs_override = -1.0, const GridSeas* seas = nullptr);

/// The heave–pitch coefficients of the design at wave frequencies omega_rad_s by its solver method
/// (sk::ComputeCoefficients: the same strips as ComputeDesignRaos). Throws InputError naming the design
/// for path: time_marching, a frequency outside the kernel's range or a hull that cannot be solved.
sk::CoefficientTable ComputeDesignCoefficients(const DesignCase& design, const std::vector<double>& omega_rad_s);

/// The strip kernel of the design (frequency- and Cs-independent; compute once, reuse for many Cs). Time-domain
/// strip method only: InputError for strip_theory_stf.
sk::StripKernel BuildDesignKernel(const DesignCase& design);
/// RAOs from a prebuilt kernel (periodic path) for a given Cs.
sk::RaoTable DesignRaosFromKernel(const DesignCase& design, const sk::StripKernel& kernel,
                                  const std::vector<double>& omega_rad_s, double cs);

/// Wave frequencies for evaluating the design in seas: its solver.frequencies when given (λ/L, ω or ω_e at
/// the design's speed and length), else EvaluationFrequencies(). InputError if they cannot be converted.
std::vector<double> SeaFrequencies(const DesignCase& design);
/// Advice for a warning that the range is too narrow, naming the key that sets it in config_file.
std::string SeaFrequencyAdvice(const DesignCase& design, const std::string& config_file);

/// Wave-frequency grid for sea-state evaluation: uniform in ω over [0.2, 3.0] rad/s (wavelengths 7 m to 1.5 km),
/// which holds all but a negligible part of the energy of JONSWAP seas with Tz 4–12 s.
std::vector<double> EvaluationFrequencies(int count = 60);

}  // namespace hullopt::eval
