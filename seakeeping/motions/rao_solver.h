#pragma once
// One call from a hull, its mass properties and a speed to heave and pitch RAOs by the high-Froude-number
// time-domain strip method (the paper's method): strip geometry → strip kernel (any builder: the transient
// Green-function kernel, or the impulsive stand-in) → periodic steady state (2b) or time marching (2a).
// Multihull bodies either share the strips (interaction) or are solved one body at a time and added.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "seakeeping/motions/head_sea_coefficients.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/rao_table.h"
#include "seakeeping/strip/strip_geometry.h"
#include "seakeeping/strip/strip_operators.h"
#include "seakeeping/motions/time_marching_motion.h"
#include "seakeeping/sections/frequency_domain_section.h"

namespace hullopt::sk {

/// Fills the force rows of a kernel whose geometry is set (StripKernelGeometry).
using StripKernelBuilder = std::function<void(StripKernel*)>;

/// The paper's kernel: transient free-surface Green function strip operators reduced to force rows
/// (BuildStripKernel of strip_kernel_builder.h) on the kernel's panels, dt, ρ and g, with the sectional force
/// in the given form (strip_operators.h).
StripKernelBuilder TransientGreenKernelBuilder(SectionalForce force = SectionalForce::kMomentum,
                                               BodyPotential potential = BodyPotential::kSourceSum);

/// The same kernel on full sections (no mirror halving) with the lateral rows (sway force, roll moment;
/// StripOperatorOptions::lateral_rows) for the oblique periodic solver (oblique_periodic_solver.h): the
/// momentum form and the source-sum body potential only. Its vertical rows are those of the full solve, equal
/// to the mirror-reduced kernel's to round-off.
StripKernelBuilder TransientGreenLateralKernelBuilder();

struct RaoSolverOptions {
  enum class Path { kPeriodic, kTimeMarching };
  enum class Method { kTimeDomainStrip, kStripTheory };
  Method method = Method::kTimeDomainStrip;  ///< strip theory: frequency-domain sections (builder unused)
  int sections = 40;                         ///< strip steps along the hull (paper 40)
  int panels = 14;                           ///< panels per wetted section of one body (paper 14)
  StationLayout layout = kDefaultStationLayout;  ///< where the strip steps sit (strip_kernel.h)
  PanelSpacing spacing;  ///< how each section's panels are spread over its girth (panel.h)
  bool interaction = true;  ///< multihull bodies share the strips; false: each body alone, forces added
  /// How strip theory's 2D sections are solved (frequency_domain_section.h). The time-domain strip kernel has
  /// the source formulation only, so kDirect is valid with Method::kStripTheory alone.
  SectionFormulation section_formulation = SectionFormulation::kSource;
  Path path = Path::kPeriodic;
  MotionOptions motion;      ///< Cs, hull name
  MarchingOptions marching;  ///< time marching only
  /// The strip geometry these options ask for (all bodies).
  StripGeometryOptions Geometry() const;
  bool IsValid(std::string* error) const;
};

/// The strip kernel of the hull at speed U (all bodies together, or body by body without interaction and
/// combined). Throws as StripKernelGeometry and the builder do. `geometry`, when given, is
/// StripKernelGeometry(hull, options.Geometry(), speed, ρ, g) already made (a caller that checked the
/// sections first): it is used instead of panelling the sections again where all bodies share the strips.
StripKernel BuildHullStripKernel(const hull::HullForm& hull, const RaoSolverOptions& options,
                                 double speed_m_s, double rho_kg_m3, double g_m_s2,
                                 const StripKernelBuilder& builder, const StripKernel* geometry = nullptr);

/// The RAO solver with its frequency-independent set-up done once (the strip kernel of the time-domain strip
/// method, or strip theory's strip geometry and 2D section set-up), so that an adaptive frequency grid solves
/// the frequencies it inserts without rebuilding it. Solve(ω) gives what ComputeRaos gives for the same ω,
/// bitwise, without the warnings (Warnings() adds them for a table).
class RaoSweeper {
 public:
  /// Throws as ComputeRaos does for bad options or a hull that cannot be solved. `geometry`: as for
  /// BuildHullStripKernel.
  RaoSweeper(const hull::HullForm& hull, const hull::MassProperties& mass, double speed_m_s, double rho_kg_m3,
             double g_m_s2, const RaoSolverOptions& options, const StripKernelBuilder& builder,
             const StripKernel* geometry = nullptr);
  ~RaoSweeper();
  RaoSweeper(RaoSweeper&&) noexcept;
  RaoSweeper& operator=(RaoSweeper&&) noexcept;
  /// RAOs at omega_rad_s (increasing, > 0), checked finite (std::domain_error naming the frequency); no warnings.
  RaoTable Solve(const std::vector<double>& omega_rad_s) const;
  /// The warnings ComputeRaos attaches to `table`: the kernel's (time-domain strip method) and the resonance
  /// warnings of the table (rao_checks.h) with the given advice.
  std::vector<std::string> Warnings(const RaoTable& table, const std::string& advice) const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

/// RAOs at the wave frequencies omega_rad_s (increasing, > 0), with StripKernelWarnings in `warnings`. Throws
/// std::invalid_argument for bad options, speed or frequencies, std::domain_error for a hull that cannot be
/// solved or non-finite results (naming the hull and frequency). `geometry`: as for BuildHullStripKernel.
RaoTable ComputeRaos(const hull::HullForm& hull, const hull::MassProperties& mass, double speed_m_s,
                     double rho_kg_m3, double g_m_s2, const std::vector<double>& omega_rad_s,
                     const RaoSolverOptions& options, const StripKernelBuilder& builder,
                     const StripKernel* geometry = nullptr);

/// Largest ω_e Δt (Δt = Δx/U, the strip step) at which coefficients are given: π/4, 8 strip steps per
/// encounter period. The strip force is periodic in ω_e with period 2π/Δt (aliased beyond ω_e Δt = π), and the
/// BDF2 momentum difference errs by (ω_e Δt)²/3, 21% at π/4; beyond it the kernel does not resolve the motion.
constexpr double kMaxEncounterStepPhase = 0.7853981633974483;

struct CoefficientTable {
  double speed_m_s = 0.0;  ///< [m/s]
  double g_m_s2 = 9.81;
  double dt_s = 0.0;  ///< [s] strip step Δx/U
  std::vector<HeadSeaCoefficients> rows;  ///< one per wave frequency, increasing
  std::vector<std::string> warnings;      ///< as RaoTable::warnings
};

/// The coefficients of the heave–pitch equations (head_sea_coefficients.h) at the wave frequencies, from the
/// same strip kernel (time-domain method) or 2D sections (strip theory) as ComputeRaos: solving them gives
/// ComputeRaos' periodic-path RAOs. Throws std::invalid_argument for bad options or frequencies, for
/// Path::kTimeMarching (a marched history has no per-frequency coefficients) and for an encounter frequency
/// with ω_e Δt > kMaxEncounterStepPhase (naming it and the sections that would resolve it).
CoefficientTable ComputeCoefficients(const hull::HullForm& hull, const hull::MassProperties& mass,
                                     double speed_m_s, double rho_kg_m3, double g_m_s2,
                                     const std::vector<double>& omega_rad_s, const RaoSolverOptions& options,
                                     const StripKernelBuilder& builder);

}  // namespace hullopt::sk
