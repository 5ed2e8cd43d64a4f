#include "seakeeping/motions/rao_solver.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "seakeeping/motions/rao_checks.h"
#include "seakeeping/motions/encounter_frequency.h"
#include "seakeeping/motions/periodic_motion_solver.h"
#include "seakeeping/strip/strip_force_model.h"
#include "seakeeping/strip/strip_kernel_builder.h"
#include "seakeeping/motions/strip_theory_stf.h"

namespace hullopt::sk {

StripKernelBuilder TransientGreenKernelBuilder(SectionalForce force, BodyPotential potential) {
  return [force, potential](StripKernel* k) {
    StripOperatorOptions o;
    o.layout = k->layout;
    o.sectional_force = force;
    o.body_potential = potential;
    StripKernel built = BuildStripKernelMirrorReduced(k->panels, k->x_m, k->dt_s, k->rho_kg_m3, k->g_m_s2, o);
    k->force = std::move(built.force);
    k->system_condition = std::move(built.system_condition);
  };
}

StripKernelBuilder TransientGreenLateralKernelBuilder() {
  return [](StripKernel* k) {
    StripOperatorOptions o;
    o.layout = k->layout;
    o.lateral_rows = true;
    StripKernel built = BuildStripKernel(k->panels, k->x_m, k->dt_s, k->rho_kg_m3, k->g_m_s2, o);
    k->force = std::move(built.force);
    k->lateral_force = std::move(built.lateral_force);
    k->system_condition = std::move(built.system_condition);
  };
}

StripGeometryOptions RaoSolverOptions::Geometry() const {
  StripGeometryOptions g;
  g.sections = sections;
  g.panels = panels;
  g.layout = layout;
  g.spacing = spacing;
  return g;
}

bool RaoSolverOptions::IsValid(std::string* error) const {
  if (!Geometry().IsValid(error)) return false;
  if (!motion.IsValid(error)) return false;
  if (path == Path::kTimeMarching && !marching.IsValid(error)) return false;
  if (section_formulation == SectionFormulation::kDirect && method != Method::kStripTheory) {
    if (error)
      *error = "section_formulation: direct applies to method: strip_theory_stf only (the time-domain strip "
               "kernel has the source formulation)";
    return false;
  }
  return true;
}

StripKernel BuildHullStripKernel(const hull::HullForm& hull, const RaoSolverOptions& options,
                                 double speed_m_s, double rho_kg_m3, double g_m_s2,
                                 const StripKernelBuilder& builder, const StripKernel* geometry) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument(err);
  StripGeometryOptions g = options.Geometry();
  if (options.interaction || (hull.bodies.size() == 1 && hull.bodies[0].y_centre_m == 0.0)) {
    StripKernel k = geometry ? *geometry : StripKernelGeometry(hull, g, speed_m_s, rho_kg_m3, g_m_s2);
    builder(&k);
    return k;
  }
  // Body by body: each panelled alone (mirror pairs solved once and counted twice).
  std::vector<StripKernel> parts;
  for (std::size_t b = 0; b < hull.bodies.size(); ++b) {
    g.body = static_cast<int>(b);
    StripKernel k = StripKernelGeometry(hull, g, speed_m_s, rho_kg_m3, g_m_s2);
    builder(&k);
    parts.push_back(k);
    if (hull.bodies[b].y_centre_m > 0.0) parts.push_back(std::move(k));
  }
  return CombineIndependentKernels(parts);
}

struct RaoSweeper::State {
  RaoSolverOptions options;
  StripKernel kernel;  // strip theory: the geometry only
  std::unique_ptr<HeadSeaShipModel> model;
  SectionRowProvider rows;  // strip theory only
};

RaoSweeper::RaoSweeper(const hull::HullForm& hull, const hull::MassProperties& mass, double speed_m_s,
                       double rho_kg_m3, double g_m_s2, const RaoSolverOptions& options,
                       const StripKernelBuilder& builder, const StripKernel* geometry)
    : s_(std::make_unique<State>()) {
  s_->options = options;
  if (options.method == RaoSolverOptions::Method::kStripTheory) {
    std::string err;
    if (!options.IsValid(&err)) throw std::invalid_argument(err);
    StripGeometryOptions g = options.Geometry();  // the same strip stations as the time-domain method
    s_->kernel = geometry ? *geometry : StripKernelGeometry(hull, g, speed_m_s, rho_kg_m3, g_m_s2);
    s_->model = std::make_unique<HeadSeaShipModel>(s_->kernel, mass, options.motion);
    s_->rows = FrequencyDomainSectionRows(s_->kernel, options.panels, options.interaction,
                                          options.section_formulation);
    return;
  }
  s_->kernel = BuildHullStripKernel(hull, options, speed_m_s, rho_kg_m3, g_m_s2, builder, geometry);
  s_->model = std::make_unique<HeadSeaShipModel>(s_->kernel, mass, options.motion);
}

RaoSweeper::~RaoSweeper() = default;
RaoSweeper::RaoSweeper(RaoSweeper&&) noexcept = default;
RaoSweeper& RaoSweeper::operator=(RaoSweeper&&) noexcept = default;

RaoTable RaoSweeper::Solve(const std::vector<double>& omega_rad_s) const {
  RaoTable t;
  if (s_->options.method == RaoSolverOptions::Method::kStripTheory) {
    t = SolveStripTheoryRaos(*s_->model, omega_rad_s, s_->rows);
  } else if (s_->options.path == RaoSolverOptions::Path::kPeriodic) {
    t = SolvePeriodicRaos(*s_->model, omega_rad_s);
  } else {
    KernelStripForceModel forces(s_->kernel);
    t = SolveMarchingRaos(*s_->model, forces, omega_rad_s, s_->options.marching);
  }
  RequireFiniteRaos(t);
  return t;
}

std::vector<std::string> RaoSweeper::Warnings(const RaoTable& t, const std::string& advice) const {
  std::vector<std::string> w;
  if (s_->options.method != RaoSolverOptions::Method::kStripTheory) w = StripKernelWarnings(s_->kernel);
  for (auto& r : RaoResonanceWarnings(t, advice)) w.push_back(std::move(r));
  return w;
}

RaoTable ComputeRaos(const hull::HullForm& hull, const hull::MassProperties& mass, double speed_m_s,
                     double rho_kg_m3, double g_m_s2, const std::vector<double>& omega_rad_s,
                     const RaoSolverOptions& options, const StripKernelBuilder& builder,
                     const StripKernel* geometry) {
  const RaoSweeper sweeper(hull, mass, speed_m_s, rho_kg_m3, g_m_s2, options, builder, geometry);
  RaoTable t = sweeper.Solve(omega_rad_s);
  t.warnings = sweeper.Warnings(t, kGridAdvice);
  return t;
}

CoefficientTable ComputeCoefficients(const hull::HullForm& hull, const hull::MassProperties& mass,
                                     double speed_m_s, double rho_kg_m3, double g_m_s2,
                                     const std::vector<double>& omega_rad_s, const RaoSolverOptions& options,
                                     const StripKernelBuilder& builder) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument(err);
  if (options.path == RaoSolverOptions::Path::kTimeMarching)
    throw std::invalid_argument(
        "coefficients come from the periodic steady state of the strip equations; path: time_marching "
        "marches one history and has none (use path: periodic, the same kernel)");
  if (omega_rad_s.empty()) throw std::invalid_argument("coefficients: the frequency list is empty");
  StripGeometryOptions g = options.Geometry();
  // Geometry first (cheap): the frequency check needs only Δt.
  StripKernel kernel = StripKernelGeometry(hull, g, speed_m_s, rho_kg_m3, g_m_s2);
  for (double w : omega_rad_s) {
    if (!(w > 0.0) || !std::isfinite(w))
      throw std::invalid_argument("coefficients: wave frequency " + std::to_string(w) + " rad/s must be > 0");
    const double we = HeadSeaEncounterFrequency(w, speed_m_s, g_m_s2);
    if (we * kernel.dt_s > kMaxEncounterStepPhase) {
      std::ostringstream os;
      os << "encounter frequency omega_e = " << we << " rad/s (omega = " << w << " rad/s) is outside the strip "
         << "kernel's range: omega_e*dt = " << we * kernel.dt_s << " > pi/4 (fewer than 8 strip steps of dt = "
         << kernel.dt_s << " s per encounter period); the highest valid omega_e is "
         << kMaxEncounterStepPhase / kernel.dt_s << " rad/s, or use at least "
         << static_cast<int>(std::ceil(options.sections * we * kernel.dt_s / kMaxEncounterStepPhase))
         << " sections";
      throw std::invalid_argument(os.str());
    }
  }
  CoefficientTable t;
  t.speed_m_s = speed_m_s;
  t.g_m_s2 = g_m_s2;
  t.dt_s = kernel.dt_s;
  if (options.method == RaoSolverOptions::Method::kStripTheory) {
    const HeadSeaShipModel model(kernel, mass, options.motion);
    t.rows = StripTheoryCoefficients(model, omega_rad_s,
                                     FrequencyDomainSectionRows(kernel, options.panels, options.interaction,
                                                                options.section_formulation));
  } else {
    kernel = BuildHullStripKernel(hull, options, speed_m_s, rho_kg_m3, g_m_s2, builder);
    const HeadSeaShipModel model(kernel, mass, options.motion);
    t.rows = PeriodicCoefficientSweep(model, omega_rad_s, KernelStripForce(kernel));
    t.warnings = StripKernelWarnings(kernel);
  }
  for (const auto& c : t.rows) {
    bool ok = true;
    for (int i = 0; i < 2; ++i) {
      ok = ok && std::isfinite(std::abs(c.Exciting(i)));
      for (int j = 0; j < 2; ++j) ok = ok && std::isfinite(std::abs(c.moving[i][j]));
    }
    if (!ok) {
      std::ostringstream os;
      os << "hull '" << options.motion.hull_name << "': non-finite coefficients at omega = " << c.omega_rad_s
         << " rad/s (omega_e = " << c.omega_e_rad_s << " rad/s)";
      throw std::domain_error(os.str());
    }
  }
  return t;
}

}  // namespace hullopt::sk
