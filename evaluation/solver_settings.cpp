#include "evaluation/solver_settings.h"

namespace hullopt::eval {

sk::RaoSolverOptions RaoOptions(const SolverSettings& settings, const std::string& hull_name, double cs) {
  sk::RaoSolverOptions o = settings.rao;
  o.motion.damping_cs = cs;
  o.motion.hull_name = hull_name;
  return o;
}

std::string MethodName(sk::RaoSolverOptions::Method method) {
  return method == sk::RaoSolverOptions::Method::kStripTheory ? "strip_theory_stf" : "time_domain_strip";
}

std::string PathName(sk::RaoSolverOptions::Path path) {
  return path == sk::RaoSolverOptions::Path::kTimeMarching ? "time_marching" : "periodic";
}

std::string TimeSchemeName(sk::TimeSchemeKind scheme) { return sk::TimeSchemeName(scheme); }

}  // namespace hullopt::eval
