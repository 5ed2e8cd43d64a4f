// Convergence of the heave peak with sections × panels: 20 × 8 (panel counts are even, so
// not 20 × 7), 40 × 14 and 80 × 28, with the paper's transient Green-function kernel and the periodic path,
// strip steps at the cell faces (StationLayout::kCellFaces, strip_kernel.h; opt-in). The change from 40 × 14
// to 80 × 28 must be under 3% (the acceptance) for
//  - the NPL 5b-like catamaran (Table 1 hull 2, generator), Fr 0.8, both demihulls (also checked with the
//    default cell midpoints);
//  - the Delft 372 demihull at Fn 0.75, whose wetted section narrows sharply in the last 75 mm to a 3 mm deep
//    transom. With steps at the cell midpoints it misses (+4.9%, reported below): the hull force telescopes
//    to U·J(x_T), the momentum the strip carries away at the transom, and midpoint BDF2 takes J_T by linear
//    extrapolation from the last two stations, which the bend of J in the last half cell makes 8% too high at
//    40 sections. At the cell faces the strip holds the transom section itself and the sum is exactly U·J_T
//    (docs/ship-motions.md, "Convergence").
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "io/config/hull_config.h"
#include "io/config/water_config.h"
#include "io/config/yaml_map.h"
#include "parametric_hull/hydrostatics.h"
#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/rao_solver.h"
#include "support/delft372_hull.h"

namespace sk = hullopt::sk;
namespace hull = hullopt::hull;

namespace {

constexpr double kG = 9.81;
// Acceptance: the change at the heave peak from 40 × 14 to 80 × 28 under 3%.
constexpr double kConvergenceTol = 0.03;

struct Case {
  std::string name;
  hull::HullForm form;
  hull::MassProperties mass;
  double speed = 0, rho = 0, cs = 0, L = 0;
};

Case Npl5b() {
  auto root = hullopt::io::YamlMap::LoadFile(std::string(HULLOPT_SOURCE_DIR) +
                                             "/configs/davis-holloway-2003/hull02_NPL5b.yaml");
  const auto water = hullopt::io::ParseWater(root);
  const auto opts = hullopt::io::ParseHullConfig(root, water);
  Case c;
  c.name = "NPL 5b-like catamaran, Fr 0.8";
  c.form = hullopt::io::LoadHull(opts, "hull02_NPL5b.yaml");
  const auto hs = hull::ComputeHydrostatics(c.form, water.rho_kg_m3);
  c.mass = {hs.displacement_kg, hs.lcb_m_from_ap, 0.25 * hs.L_m, hs.T_m};
  c.L = hs.L_m;
  c.speed = 0.8 * std::sqrt(kG * hs.L_m);
  c.rho = water.rho_kg_m3;
  c.cs = 0.065;
  return c;
}

Case DelftDemihull() {
  Case c;
  c.name = "Delft 372 demihull";
  c.form = hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR);
  // One demihull alone on y = 0 (the hull's mirror pair would add the second demihull).
  c.form.type = "monohull";
  c.form.bodies[0].y_centre_m = 0.0;
  c.mass = hullopt::testing::Delft372Mass();
  c.mass.mass_kg *= 0.5;
  c.L = 3.0;
  c.speed = 0.75 * std::sqrt(kG * 3.0);
  c.rho = 1000.0;
  c.cs = 0.024;
  return c;
}

// Peak heave RAO over λ/L 1–4 (fine enough that the grid does not limit the comparison: 151 points).
double PeakHeave(const Case& c, int sections, int panels, sk::StationLayout layout) {
  sk::RaoSolverOptions o;
  o.sections = sections;
  o.panels = panels;
  o.layout = layout;
  o.motion.damping_cs = c.cs;
  o.motion.hull_name = c.name;
  const auto w = sk::WaveFrequencies(
      sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kLambdaOverL, 1.0, 4.0, 151), c.speed, kG, c.L);
  const auto rao = sk::ComputeRaos(c.form, c.mass, c.speed, c.rho, kG, w, o, sk::TransientGreenKernelBuilder());
  double peak = 0;
  for (const auto& h : rao.heave) peak = std::max(peak, std::abs(h));
  return peak;
}

double Change4014To8028(const Case& c, sk::StationLayout layout = sk::StationLayout::kCellFaces) {
  const double p20 = PeakHeave(c, 20, 8, layout), p40 = PeakHeave(c, 40, 14, layout),
               p80 = PeakHeave(c, 80, 28, layout);
  WARN(c.name << (layout == sk::StationLayout::kCellFaces ? " (cell faces)" : " (cell midpoints)")
              << ": heave peak " << p20 << " (20x8), " << p40 << " (40x14), " << p80 << " (80x28); change "
              << 100 * (p40 / p20 - 1) << "%, then " << 100 * (p80 / p40 - 1) << "%");
  return p80 / p40 - 1;
}

}  // namespace

TEST_CASE("heave peak converges with sections and panels: NPL 5b-like catamaran", "[motions][convergence]") {
  CHECK(std::fabs(Change4014To8028(Npl5b())) < kConvergenceTol);
  CHECK(std::fabs(Change4014To8028(Npl5b(), sk::StationLayout::kCellMidpoints)) < kConvergenceTol);
}

TEST_CASE("heave peak converges with sections and panels: Delft 372 demihull", "[motions][convergence]") {
  CHECK(std::fabs(Change4014To8028(DelftDemihull())) < kConvergenceTol);
  // Reported: the midpoint layout's known miss on this hull (transom momentum by extrapolation).
  Change4014To8028(DelftDemihull(), sk::StationLayout::kCellMidpoints);
}
