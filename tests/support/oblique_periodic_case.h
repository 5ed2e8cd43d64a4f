#pragma once
// A hull's time-domain strip kernel with the lateral rows (sway force, roll moment) and its head-sea model,
// for the tests of the oblique periodic solver (seakeeping/motions/oblique_periodic_solver.h).
#include <memory>

#include "parametric_hull/hull_form.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/oblique_periodic_solver.h"
#include "seakeeping/motions/rao_solver.h"

namespace hullopt::test {

/// The kernel on full sections with lateral rows at speed U (stations at the cell faces, the default), and
/// the head-sea model on it with Cs. The kernel is held by pointer so that the model's reference stays valid.
struct ObliquePeriodicCase {
  std::unique_ptr<sk::StripKernel> kernel;
  std::unique_ptr<sk::HeadSeaShipModel> model;
};

inline ObliquePeriodicCase MakeObliquePeriodicCase(const hull::HullForm& hull,
                                                   const hull::MassProperties& mass, double speed_m_s,
                                                   int sections, int panels, double cs, double rho = 1000.0,
                                                   double g = 9.81) {
  sk::RaoSolverOptions o;
  o.sections = sections;
  o.panels = panels;
  ObliquePeriodicCase c;
  c.kernel = std::make_unique<sk::StripKernel>(
      sk::BuildHullStripKernel(hull, o, speed_m_s, rho, g, sk::TransientGreenLateralKernelBuilder()));
  sk::MotionOptions mo;
  mo.damping_cs = cs;
  c.model = std::make_unique<sk::HeadSeaShipModel>(*c.kernel, mass, mo);
  return c;
}

/// The kernel's stations as oblique-strip-theory stations (the same panels, x and weights).
inline std::vector<sk::ObliqueStripStation> KernelStations(const sk::StripKernel& k) {
  std::vector<sk::ObliqueStripStation> out(k.Steps());
  for (int n = 0; n < k.Steps(); ++n) out[n] = {k.x_m[n], k.Weight(n), k.panels[n]};
  return out;
}

}  // namespace hullopt::test
