#pragma once
// Delft 372 catamaran (data/delft372) as a HullForm for tests: the demihull offsets (x from AP, keel to
// deck), draught 0.15 m, demihulls at ±0.35 m, and the model's mass properties. A minimal reader for tests
// only; the product reads offsets through io/.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "parametric_hull/hull_form.h"
#include "seakeeping/motions/rao_solver.h"

namespace hullopt::testing {

inline hull::HullForm Delft372Hull(const std::string& source_dir) {
  std::ifstream in(source_dir + "/data/delft372/delft372_offsets.csv");
  if (!in) throw std::runtime_error("cannot open delft372_offsets.csv");
  hull::Demihull body;
  body.role = "demihull";
  body.y_centre_m = 0.35;
  std::string line;
  std::getline(in, line);  // header x_m,y_m,z_m
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream r(line);
    double x, y, z;
    char c;
    r >> x >> c >> y >> c >> z;
    if (body.stations.empty() || body.stations.back().x_m != x) body.stations.push_back({x, {}, {}});
    body.stations.back().y_m.push_back(y);
    body.stations.back().z_m.push_back(z);
  }
  hull::HullForm h;
  h.type = "catamaran";
  h.draught_m = 0.15;
  h.length_m = 3.0;
  h.bodies.push_back(body);
  return h;
}

/// Model particulars for the motion tests (delft372_particulars.csv): whole catamaran.
inline hull::MassProperties Delft372Mass() { return {87.07, 1.41, 0.782, 0.34}; }

/// The solver set-up the Delft 372 verification and validation tests share: the default 40 × 14 strips and
/// Cs 0.024 (the value the reference paper takes for this hull).
inline sk::RaoSolverOptions Delft372SolverOptions(sk::RaoSolverOptions::Method method) {
  sk::RaoSolverOptions o;
  o.method = method;
  o.sections = 40;
  o.panels = 14;
  o.motion.damping_cs = 0.024;
  o.motion.hull_name = "Delft 372";
  return o;
}

}  // namespace hullopt::testing
