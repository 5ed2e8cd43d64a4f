// Cost per heading of the oblique-sea strip theory (sk::SolveObliqueStripTheory): Delft 372 catamaran (both
// demihulls in each 2D section), 40 sections x 14 panels on the cell faces, 20 wave frequencies (λ/L 0.8–3),
// 1, 2, 4 and 8 headings spread over 180° to 90° (and 8 over 180° to 97.5°), at Fn 0 and Fn 0.75. At zero
// speed every heading shares the sections (one 2D solve per frequency and station); at speed each heading has
// its own encounter frequencies (beam seas share the wave frequencies), so the section solves grow with the
// number of headings. The head-sea STF method (sk::SolveStripTheoryRaos, heave and pitch only) on the same
// stations at Fn 0.75 for reference. Quote medians with the core count (docs/developer-guide.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seakeeping/motions/oblique_strip_theory.h"
#include "seakeeping/motions/strip_theory_stf.h"
#include "seakeeping/strip/strip_geometry.h"
#include "tests/support/delft372_hull.h"

namespace sk = hullopt::sk;

namespace {

constexpr double kRho = 1000.0, kG = 9.81, kL = 3.0;

struct Catamaran {
  hullopt::hull::HullForm hull = hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR);
  hullopt::hull::MassProperties mass = hullopt::testing::Delft372Mass();
  sk::StripGeometryOptions geo;
  sk::StripKernel geometry;
  std::vector<sk::ObliqueStripStation> stations;
  sk::ObliqueMassProperties oblique_mass;
  std::vector<double> omega;
  Catamaran() {
    geo.layout = sk::StationLayout::kCellFaces;
    geometry = sk::StripKernelGeometry(hull, geo, Speed(0.75), kRho, kG);
    for (int n = 0; n < geometry.Steps(); ++n)
      stations.push_back({geometry.x_m[n], geometry.Weight(n), geometry.panels[n]});
    oblique_mass.mass_kg = mass.mass_kg;
    oblique_mass.x_g_m = mass.lcg_m_from_ap;
    oblique_mass.z_g_m = mass.kg_m - hull.draught_m;
    oblique_mass.inertia_kg_m2.diagonal() << mass.mass_kg * 0.3 * 0.3, mass.mass_kg * mass.kyy_m * mass.kyy_m,
        mass.mass_kg * mass.kyy_m * mass.kyy_m;
    omega =
        sk::WaveFrequencies(sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kLambdaOverL, 0.8, 3.0, 20),
                            Speed(0.75), kG, kL);
  }
  static double Speed(double fn) { return fn * std::sqrt(kG * kL); }
};

const Catamaran& TheCatamaran() {
  static const Catamaran c;
  return c;
}

// state.range(0): number of headings; state.range(1): Fn x 100.
void BM_ObliqueStripHeadings(benchmark::State& state) {
  const Catamaran& c = TheCatamaran();
  const int nh = static_cast<int>(state.range(0));
  std::vector<double> headings;
  for (int h = 0; h < nh; ++h) headings.push_back(nh == 1 ? 180.0 : 180.0 - 90.0 * h / (nh - 1));
  sk::ObliqueStripOptions o;
  o.rho_kg_m3 = kRho;
  o.g_m_s2 = kG;
  o.speed_m_s = Catamaran::Speed(state.range(1) / 100.0);
  for (auto _ : state) {
    const auto r = sk::SolveObliqueStripTheory(c.stations, c.oblique_mass, c.omega, headings, o);
    benchmark::DoNotOptimize(r.waves.data());
  }
  state.counters["headings"] = nh;
  state.counters["per_heading_s"] =
      benchmark::Counter(nh, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ObliqueStripHeadings)
    ->ArgsProduct({{1, 2, 4, 8}, {0, 75}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

void BM_HeadSeaStf(benchmark::State& state) {
  const Catamaran& c = TheCatamaran();
  sk::MotionOptions mo;
  const sk::HeadSeaShipModel model(c.geometry, c.mass, mo);
  for (auto _ : state) {
    // New rows each time: the provider caches its sections.
    const auto r =
        sk::SolveStripTheoryRaos(model, c.omega, sk::FrequencyDomainSectionRows(c.geometry, c.geo.panels));
    benchmark::DoNotOptimize(r.heave.data());
  }
}
BENCHMARK(BM_HeadSeaStf)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
