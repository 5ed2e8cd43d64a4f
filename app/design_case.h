#pragma once
// One design as the commands that need RAOs see it (evaluate, optimize, calibrate): the hull, its
// hydrostatics and mass properties, the speed and the strip-solver settings read from a config, and the call
// that turns it into heave and pitch RAOs with the paper's time-domain strip method.
#include <map>
#include <string>
#include <vector>

#include "io/hull_config.h"
#include "io/motion_config.h"
#include "io/water_config.h"
#include "io/yaml_map.h"
#include "parametric_hull/hydrostatics.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/motions/rao_table.h"
#include "seas/passenger_positions.h"

namespace hullopt::app {

struct DesignCase {
  std::string name;
  hull::HullForm hull;          ///< at rest, even keel: coefficients, mass defaults, Fr, passenger positions
  hull::HullForm running_hull;  ///< at hull.attitude (= hull at even keel): strips and RAOs
  hull::Hydrostatics hydrostatics;  ///< of `hull` (at rest)
  hull::MassProperties mass;
  /// Plausibility warnings of the hull and mass (parametric_hull/plausibility.h), carried into every RAO
  /// table computed for this design and so into every output.
  std::vector<std::string> input_warnings;
  io::WaterOptions water;
  double speed_m_s = 0.0;      ///< [m/s]
  io::SolverConfig solver;     ///< Cs, sections, panels, path ...
  bool has_frequencies = false;  ///< the config gave solver.frequencies
  /// CG-to-transom and CG-to-bow distances for the passenger positions [m].
  sk::HullExtent Extent() const;
  /// Fr, Cvp, B_over_T, L_over_B, L_m of the main body: axes of the study plots.
  std::map<std::string, double> Parameters() const;
};

/// Reads water, hull, speed, solver (optional: defaults 40 sections × 14 panels, Cs 0, periodic path) and mass
/// from root and builds the hull. Consumes exactly these keys (the caller calls root.Finish()). With
/// read_speed false the speed is left to the caller (speed_m_s = 0). Errors are io::InputError naming the
/// file, key and rule.
DesignCase LoadDesignCase(io::YamlMap& root, const std::string& config_file, const std::string& name,
                          bool read_speed = true);

/// RAOs of the design at wave frequencies omega_rad_s (increasing, > 0) by the config's solver.method: the
/// time-domain strip method (transient Green-function kernel) or conventional strip theory. Cs overrides the
/// config's when >= 0. Throws io::InputError naming the design for a hull that
/// cannot be solved or non-finite results.
sk::RaoTable ComputeDesignRaos(const DesignCase& design, const std::vector<double>& omega_rad_s,
                               double cs_override = -1.0);

/// The heave–pitch coefficients of the design at wave frequencies omega_rad_s by the config's solver.method
/// (sk::ComputeCoefficients: the same strips as ComputeDesignRaos). Throws io::InputError naming the design
/// for path: time_marching, a frequency outside the kernel's range or a hull that cannot be solved.
sk::CoefficientTable ComputeDesignCoefficients(const DesignCase& design, const std::vector<double>& omega_rad_s);

/// The strip kernel of the design (frequency- and Cs-independent; compute once, reuse for many Cs). Time-domain
/// strip method only: io::InputError for solver.method strip_theory_stf.
sk::StripKernel BuildDesignKernel(const DesignCase& design);
/// RAOs from a prebuilt kernel (periodic path) for a given Cs.
sk::RaoTable DesignRaosFromKernel(const DesignCase& design, const sk::StripKernel& kernel,
                                  const std::vector<double>& omega_rad_s, double cs);

/// Wave frequencies for evaluating the design in seas: its config's solver.frequencies when given (λ/L, ω or
/// ω_e at the design's speed and length), else EvaluationFrequencies(). io::InputError if they cannot be
/// converted.
std::vector<double> SeaFrequencies(const DesignCase& design);
/// Advice for a warning that the range is too narrow, naming the key that sets it in config_file.
std::string SeaFrequencyAdvice(const DesignCase& design, const std::string& config_file);

/// Wave-frequency grid for sea-state evaluation: uniform in ω over [0.2, 3.0] rad/s (wavelengths 7 m to 1.5 km),
/// which holds all but a negligible part of the energy of JONSWAP seas with Tz 4–12 s.
std::vector<double> EvaluationFrequencies(int count = 60);

}  // namespace hullopt::app
