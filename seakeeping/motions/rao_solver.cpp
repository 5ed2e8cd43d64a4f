#include "seakeeping/motions/rao_solver.h"

#include "seakeeping/motions/rao_checks.h"

#include <stdexcept>

#include "seakeeping/motions/periodic_motion_solver.h"
#include "seakeeping/strip/strip_force_model.h"
#include "seakeeping/strip/strip_kernel_builder.h"
#include "seakeeping/motions/strip_theory_stf.h"

namespace hullopt::sk {

StripKernelBuilder TransientGreenKernelBuilder(SectionalForce force) {
  return [force](StripKernel* k) {
    StripOperatorOptions o;
    o.layout = k->layout;
    o.sectional_force = force;
    StripKernel built = BuildStripKernelMirrorReduced(k->panels, k->x_m, k->dt_s, k->rho_kg_m3, k->g_m_s2, o);
    k->force = std::move(built.force);
    k->system_condition = std::move(built.system_condition);
  };
}

bool RaoSolverOptions::IsValid(std::string* error) const {
  StripGeometryOptions g;
  g.sections = sections;
  g.panels = panels;
  g.layout = layout;
  if (!g.IsValid(error)) return false;
  if (!motion.IsValid(error)) return false;
  if (path == Path::kTimeMarching && !marching.IsValid(error)) return false;
  return true;
}

StripKernel BuildHullStripKernel(const hull::HullForm& hull, const RaoSolverOptions& options,
                                 double speed_m_s, double rho_kg_m3, double g_m_s2,
                                 const StripKernelBuilder& builder) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument(err);
  StripGeometryOptions g;
  g.sections = options.sections;
  g.panels = options.panels;
  g.layout = options.layout;
  if (options.interaction || (hull.bodies.size() == 1 && hull.bodies[0].y_centre_m == 0.0)) {
    StripKernel k = StripKernelGeometry(hull, g, speed_m_s, rho_kg_m3, g_m_s2);
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

RaoTable ComputeRaos(const hull::HullForm& hull, const hull::MassProperties& mass, double speed_m_s,
                     double rho_kg_m3, double g_m_s2, const std::vector<double>& omega_rad_s,
                     const RaoSolverOptions& options, const StripKernelBuilder& builder) {
  if (options.method == RaoSolverOptions::Method::kStripTheory) {
    std::string err;
    if (!options.IsValid(&err)) throw std::invalid_argument(err);
    StripGeometryOptions g;
    g.sections = options.sections;
    g.panels = options.panels;
    g.layout = options.layout;  // the same strip stations as the time-domain method
    const StripKernel geometry = StripKernelGeometry(hull, g, speed_m_s, rho_kg_m3, g_m_s2);
    const HeadSeaShipModel model(geometry, mass, options.motion);
    RaoTable t = SolveStripTheoryRaos(model, omega_rad_s,
                                      FrequencyDomainSectionRows(geometry, options.panels, options.interaction));
    RequireFiniteRaos(t);
    t.warnings = RaoResonanceWarnings(t);
    return t;
  }
  const StripKernel kernel = BuildHullStripKernel(hull, options, speed_m_s, rho_kg_m3, g_m_s2, builder);
  const HeadSeaShipModel model(kernel, mass, options.motion);
  RaoTable t;
  if (options.path == RaoSolverOptions::Path::kPeriodic) {
    t = SolvePeriodicRaos(model, omega_rad_s);
  } else {
    KernelStripForceModel forces(kernel);
    t = SolveMarchingRaos(model, forces, omega_rad_s, options.marching);
  }
  RequireFiniteRaos(t);
  t.warnings = StripKernelWarnings(kernel);
  for (const auto& w : RaoResonanceWarnings(t)) t.warnings.push_back(w);
  return t;
}

}  // namespace hullopt::sk
