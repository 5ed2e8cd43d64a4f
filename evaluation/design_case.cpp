#include "evaluation/design_case.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "evaluation/input_error.h"
#include "optimizer/evaluation_cost.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/periodic_motion_solver.h"
#include "seakeeping/motions/rao_checks.h"
#include "seakeeping/motions/validity_range.h"

namespace hullopt::eval {
namespace {

sk::RaoSolverOptions SolverOptions(const DesignCase& d, double cs) { return RaoOptions(d.solver, d.name, cs); }

// The 2D+t method's validity range (conventional strip theory has its own, low-Fn one: not flagged here).
void AddValidityWarnings(const DesignCase& d, sk::RaoTable* t) {
  if (d.solver.rao.method != sk::RaoSolverOptions::Method::kTimeDomainStrip) return;
  for (auto& w : sk::ValidityWarnings(d.speed_m_s, d.hydrostatics.L_m, d.water.g_m_s2, t->omega_rad_s))
    t->warnings.push_back(std::move(w));
}

// The kernel builder, its time counted as the kernel build (--profile) rather than the solver's set-up.
sk::StripKernelBuilder TimedKernelBuilder(const DesignCase& d) {
  return [inner = sk::TransientGreenKernelBuilder(d.solver.sectional_force, d.solver.body_potential)](
             sk::StripKernel* k) {
    const opt::CostTimer timer(opt::CostStage::kKernelBuild);
    inner(k);
  };
}

template <class F>
auto Guard(const DesignCase& d, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::domain_error& e) {
    throw InputError("design '" + d.name + "': cannot compute RAOs: " + e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError("design '" + d.name + "': cannot compute RAOs: " + e.what());
  }
}

}  // namespace

sk::HullExtent DesignCase::Extent() const {
  const double x_aft = hydrostatics.x_ap_m;
  const double x_fwd = hydrostatics.x_ap_m + hydrostatics.L_m;
  return {mass.lcg_m_from_ap - x_aft, x_fwd - mass.lcg_m_from_ap};
}

std::map<std::string, double> DesignCase::Parameters() const {
  const auto& h = hydrostatics;
  std::map<std::string, double> p = {{"Fr", speed_m_s / std::sqrt(water.g_m_s2 * h.L_m)},
                                     {"Cvp", h.Cvp},
                                     {"B_over_T", h.B_m / h.T_m},
                                     {"L_over_B", h.L_m / h.B_m},
                                     {"L_m", h.L_m}};
  // The attitude the strips were solved at, where it is not the hull at rest.
  if (solver.steady_flow || !attitude.IsEvenKeel())
    p["running_sinkage_m"] = attitude.sinkage_m, p["running_trim_deg"] = attitude.trim_deg;
  return p;
}

sk::StripKernel BuildDesignKernel(const DesignCase& d) {
  if (d.solver.rao.method != sk::RaoSolverOptions::Method::kTimeDomainStrip)
    throw InputError("design '" + d.name + "': solver.method = " + MethodName(d.solver.rao.method) +
                         ": only the time-domain strip method has a frequency-independent strip kernel "
                         "(needed here); use method: time_domain_strip");
  return Guard(d, [&] {
    return sk::BuildHullStripKernel(d.running_hull, SolverOptions(d, d.solver.cs()), d.speed_m_s, d.water.rho_kg_m3,
                                    d.water.g_m_s2, sk::TransientGreenKernelBuilder(d.solver.sectional_force, d.solver.body_potential));
  });
}

sk::RaoTable DesignRaosFromKernel(const DesignCase& d, const sk::StripKernel& kernel,
                                  const std::vector<double>& omega_rad_s, double cs) {
  return Guard(d, [&] {
    const sk::HeadSeaShipModel model(kernel, d.mass, SolverOptions(d, cs).motion);
    sk::RaoTable t = sk::SolvePeriodicRaos(model, omega_rad_s);
    sk::RequireFiniteRaos(t);
    t.warnings = d.input_warnings;
    for (const auto& w : sk::StripKernelWarnings(kernel)) t.warnings.push_back(w);
    for (const auto& w : sk::RaoResonanceWarnings(t)) t.warnings.push_back(w);
    AddValidityWarnings(d, &t);
    // What the generator changed to build the hull goes with every result of it.
    t.warnings.insert(t.warnings.begin(), d.hull.adjustments.begin(), d.hull.adjustments.end());
    return t;
  });
}

sk::RaoTable ComputeDesignRaos(const DesignCase& d, const std::vector<double>& omega_rad_s,
                               double cs_override, const GridSeas* seas) {
  const double cs = cs_override >= 0.0 ? cs_override : d.solver.cs();
  return Guard(d, [&] {
    sk::RaoTable t;
    // sk::ComputeRaos's steps, each timed for --profile: the set-up (panelling, the kernel build timed inside
    // it), the solve.
    std::unique_ptr<sk::RaoSweeper> sweeper;
    {
      const opt::CostTimer timer(opt::CostStage::kPanelling);
      sweeper = std::make_unique<sk::RaoSweeper>(d.running_hull, d.mass, d.speed_m_s, d.water.rho_kg_m3,
                                                 d.water.g_m_s2, SolverOptions(d, cs), TimedKernelBuilder(d));
    }
    if (!d.solver.grid.enabled) {
      {
        const opt::CostTimer timer(opt::CostStage::kPeriodicSolve);
        t = sweeper->Solve(omega_rad_s);
      }
      t.warnings = sweeper->Warnings(t, sk::kGridAdvice);
    } else {
      t = SweepAdaptively(*sweeper, omega_rad_s, d.solver.grid, seas);
    }
    t.warnings.insert(t.warnings.begin(), d.input_warnings.begin(), d.input_warnings.end());
    AddValidityWarnings(d, &t);
    // What the generator changed to build the hull goes with every result of it.
    t.warnings.insert(t.warnings.begin(), d.hull.adjustments.begin(), d.hull.adjustments.end());
    return t;
  });
}

std::vector<double> SeaFrequencies(const DesignCase& d) {
  if (!d.has_frequencies) return EvaluationFrequencies();
  try {
    return sk::WaveFrequencies(d.solver.frequencies, d.speed_m_s, d.water.g_m_s2, d.hydrostatics.L_m);
  } catch (const std::invalid_argument& e) {
    throw InputError("design '" + d.name + "': solver.frequencies: " + e.what());
  }
}

std::string SeaFrequencyAdvice(const DesignCase& d, const std::string& config_file) {
  return d.has_frequencies ? "extend solver.frequencies in " + config_file
                           : "add solver.frequencies to " + config_file +
                                 " (without it the grid is omega 0.2..3 rad/s)";
}

sk::CoefficientTable ComputeDesignCoefficients(const DesignCase& d, const std::vector<double>& omega_rad_s) {
  try {
    return sk::ComputeCoefficients(d.running_hull, d.mass, d.speed_m_s, d.water.rho_kg_m3, d.water.g_m_s2, omega_rad_s,
                                   SolverOptions(d, d.solver.cs()), sk::TransientGreenKernelBuilder(d.solver.sectional_force, d.solver.body_potential));
  } catch (const std::domain_error& e) {
    throw InputError("design '" + d.name + "': cannot compute coefficients: " + e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError("design '" + d.name + "': cannot compute coefficients: " + e.what());
  }
}

std::vector<double> EvaluationFrequencies(int count) {
  std::vector<double> w(count);
  for (int i = 0; i < count; ++i) w[i] = 0.2 + (3.0 - 0.2) * i / (count - 1);
  return w;
}

}  // namespace hullopt::eval
