#include "evaluation/strip_attitude.h"

#include <atomic>
#include <sstream>

#include "evaluation/input_error.h"
#include "seakeeping/motions/calm_water.h"

namespace hullopt::eval {
namespace {
std::atomic<long> g_calm_water_solves{0};
}  // namespace

long CalmWaterSolves() { return g_calm_water_solves.load(); }

hull::RunningAttitude StripAttitude(const hull::HullForm& at_rest, const hull::MassProperties& mass,
                                    double speed_m_s, const WaterOptions& water, const SolverSettings& settings,
                                    hull::RunningAttitude given, const std::string& where) {
  given.pivot_x_m = mass.lcg_m_from_ap;
  if (!settings.steady_flow) return given;
  if (!given.IsEvenKeel())
    throw InputError(where + ": key 'solver.steady_flow': 'on' computes the running attitude, and hull.attitude "
                             "gives one: remove hull.attitude or set steady_flow: off");
  sk::CalmWaterOptions o;
  o.geometry = settings.rao.Geometry();
  o.geometry.layout = sk::StationLayout::kCellFaces;
  o.sectional_force = settings.sectional_force;
  sk::CalmWaterResult r;
  ++g_calm_water_solves;
  try {
    r = sk::SolveRunningAttitude(at_rest, mass, speed_m_s, water.rho_kg_m3, water.g_m_s2, o);
  } catch (const std::logic_error& e) {
    throw InputError(where + ": key 'solver.steady_flow': " + e.what());
  }
  if (!r.converged) throw InputError(where + ": key 'solver.steady_flow': no running attitude: " + r.note);
  return r.attitude;
}

std::string AttitudeNote(const hull::RunningAttitude& a, const SolverSettings& settings) {
  if (a.IsEvenKeel() && !settings.steady_flow) return {};
  std::ostringstream os;
  os << "running attitude: sinkage " << a.sinkage_m << " m (+ down), trim " << a.trim_deg
     << " deg (+ bow up) at x = " << a.pivot_x_m << " m"
     << (settings.steady_flow ? " (from calm water on the strips, solver.steady_flow: on)" : " (hull.attitude)");
  return os.str();
}

}  // namespace hullopt::eval
