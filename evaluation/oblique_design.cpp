#include "evaluation/oblique_design.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "parametric_hull/hydrostatics.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/oblique_periodic_solver.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/motions/validity_range.h"

namespace hullopt::eval {

std::string CheckHeadingList(const std::vector<double>& headings_deg, const std::string& key) {
  auto entry = [&](std::size_t i) {
    std::ostringstream os;
    os << key << "[" << i << "] = " << headings_deg[i];
    return os.str();
  };
  for (std::size_t i = 0; i < headings_deg.size(); ++i) {
    if (!(headings_deg[i] >= 0.0 && headings_deg[i] < 360.0)) return entry(i) + ": must be within [0, 360)";
    for (std::size_t j = 0; j < i; ++j)
      if (headings_deg[j] == headings_deg[i]) return entry(i) + ": given twice";
  }
  return "";
}

double DefaultRollRadiusOfGyration(const hull::HullForm& hull) {
  double half_beam = 0.0;
  for (const auto& body : hull.bodies)
    for (const auto& st : body.stations)
      for (double y : st.y_m) half_beam = std::max(half_beam, std::fabs(body.y_centre_m) + y);
  return 0.35 * 2.0 * half_beam;
}

sk::ObliqueMassProperties ObliqueMassOf(const DesignCase& design, double kxx_m) {
  if (!(kxx_m > 0.0) || !std::isfinite(kxx_m))
    throw std::invalid_argument("roll radius of gyration kxx = " + std::to_string(kxx_m) + " m must be > 0");
  const hull::MassProperties& mass = design.mass;
  sk::ObliqueMassProperties m;
  m.mass_kg = mass.mass_kg;
  m.x_g_m = mass.lcg_m_from_ap;
  m.z_g_m = mass.kg_m - design.running_hull.draught_m;
  m.inertia_kg_m2.diagonal() << mass.mass_kg * kxx_m * kxx_m, mass.mass_kg * mass.kyy_m * mass.kyy_m,
      mass.mass_kg * mass.kyy_m * mass.kyy_m;
  return m;
}

std::string ObliqueTimeDomainFault(const SolverSettings& solver) {
  if (solver.sectional_force != sk::SectionalForce::kMomentum) return "the sectional force must be the momentum form";
  if (solver.body_potential != sk::BodyPotential::kSourceSum) return "the body potential must be the source sum";
  if (!solver.rao.interaction) return "all bodies must share the strips (interaction on)";
  return "";
}

namespace {
bool SolvedByTimeDomain(const DesignCase& design) {
  return design.solver.rao.method == sk::RaoSolverOptions::Method::kTimeDomainStrip;
}
}  // namespace

std::string ObliqueSpeedFault(const DesignCase& design, double speed_m_s) {
  if (SolvedByTimeDomain(design) && !(speed_m_s > 0.0))
    return "the time-domain strip method needs a forward speed > 0 (the hull passing through the strips; "
           "solver.method: strip_theory_stf solves zero speed)";
  return "";
}

std::string ObliqueMethodNote(const DesignCase& design) {
  std::ostringstream os;
  os << (SolvedByTimeDomain(design) ? "the time-domain strip method (periodic steady state" : "the oblique-sea strip theory (STF")
     << ", Cs = " << design.solver.cs() << " in heave and pitch)";
  return os.str();
}

sk::ObliqueStripResult SolveObliqueDesign(const DesignCase& design, double speed_m_s,
                                          const std::vector<double>& omega_rad_s,
                                          const std::vector<double>& headings_deg, double kxx_m,
                                          sk::ObliqueStripOptions options, std::vector<std::string>* warnings) {
  const sk::ObliqueMassProperties mass = ObliqueMassOf(design, kxx_m);
  const double rho = design.water.rho_kg_m3, g = design.water.g_m_s2;
  options.rho_kg_m3 = rho;
  options.g_m_s2 = g;
  options.speed_m_s = speed_m_s;
  options.damping_cs = design.solver.cs();
  if (!SolvedByTimeDomain(design)) {
    const std::vector<sk::ObliqueStripStation> stations =
        sk::ObliqueStripStations(design.running_hull, design.solver.rao.Geometry());
    return sk::SolveObliqueStripTheory(stations, mass, omega_rad_s, headings_deg, options);
  }
  if (const std::string fault = ObliqueTimeDomainFault(design.solver); !fault.empty())
    throw std::invalid_argument("the time-domain strip method in oblique seas: " + fault +
                                " (or solver.method: strip_theory_stf)");
  if (const std::string fault = ObliqueSpeedFault(design, speed_m_s); !fault.empty())
    throw std::invalid_argument(fault);
  const sk::RaoSolverOptions rao = RaoOptions(design.solver, design.name, design.solver.cs());
  const sk::StripKernel kernel = sk::BuildHullStripKernel(design.running_hull, rao, speed_m_s, rho, g,
                                                          sk::TransientGreenLateralKernelBuilder());
  if (warnings) {
    for (auto& w : sk::StripKernelWarnings(kernel)) warnings->push_back(std::move(w));
    for (auto& w : sk::ValidityWarnings(speed_m_s, design.hydrostatics.L_m, g, omega_rad_s))
      warnings->push_back(std::move(w));
  }
  const sk::HeadSeaShipModel model(kernel, design.mass, rao.motion);
  sk::ObliquePeriodicOptions po;
  po.mass = mass;
  po.roll = options;
  return sk::SolveObliquePeriodic(model, omega_rad_s, headings_deg, po);
}

sk::RollDampingHull RollDampingHullOf(const hull::HullForm& hull, const hull::Hydrostatics& hs, double og_m,
                                      double rho_kg_m3) {
  sk::RollDampingHull h;
  h.length_m = hs.L_m;
  h.breadth_m = hs.B_m;
  h.draught_m = hs.T_m;
  h.block_coefficient = hs.Cb;
  h.midship_coefficient = hs.Cm;
  h.og_m = og_m;
  if (hull.BodyCount() > 1)
    for (const auto& body : hull.bodies) {
      hull::HullForm one = hull;
      one.type = "monohull";
      one.bodies = {body};
      one.bodies[0].y_centre_m = 0.0;
      const double awp = hull::ComputeHydrostatics(one, rho_kg_m3).awp_m2;
      for (int side = 0; side < (body.y_centre_m > 0.0 ? 2 : 1); ++side) {
        h.body_offset_m.push_back(body.y_centre_m);
        h.body_waterplane_m2.push_back(awp);
      }
    }
  return h;
}

void SetDesignRollDamping(const DesignCase& design, const sk::RollDampingOptions& roll,
                          sk::ObliqueStripOptions* options) {
  if (roll.model == sk::RollDampingModel::kNone) return;
  options->roll_damping = roll;
  options->roll_damping.damping_cs = design.solver.cs();
  const double z_g_m = design.mass.kg_m - design.running_hull.draught_m;  // as ObliqueMassOf
  options->roll_damping_hull = RollDampingHullOf(design.hull, design.hydrostatics, -z_g_m, design.water.rho_kg_m3);
}

std::string RollDampingNote(const sk::ObliqueStripOptions& o) {
  if (o.roll_damping.model == sk::RollDampingModel::kNone) return "potential only";
  std::ostringstream os;
  if (o.roll_damping_hull.Multihull())
    os << "the demihulls' Cs heave damping at their offsets (B44 += sum y_i^2 0.5 Cs rho U A_wp,i, Cs = "
       << o.roll_damping.damping_cs << ")";
  else
    os << "Ikeda's components (Kawahara, Maekawa & Ikeda 2009: skin friction, eddy making, hull lift; no bilge "
          "keels)";
  os << " added to the potential B44, linearised at a roll amplitude of "
     << o.roll_damping.roll_amplitude_rad * 180.0 / 3.14159265358979323846 << " deg";
  return os.str();
}

double RollNaturalFrequency(const sk::ObliqueStripResult& r) {
  const double c44 = r.restoring(3, 3);
  double best = 0.0, miss = 0.0;
  if (!(c44 > 0.0)) return 0.0;
  for (const auto& f : r.frequencies) {
    const double m = std::fabs(f.omega_rad_s * f.omega_rad_s * (r.mass(3, 3) + f.added_mass(3, 3)) - c44);
    if (best == 0.0 || m < miss) {
      best = f.omega_rad_s;
      miss = m;
    }
  }
  return best;
}

}  // namespace hullopt::eval
