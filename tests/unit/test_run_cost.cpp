// The run-cost estimate (io/config/run_cost.h) against measured runs, its scaling against the kernel's
// operation counts, and the refusals beyond the documented thresholds (8 GiB, 1 h) naming the key that drives
// them.
#include <catch2/catch.hpp>

#include "io/config/run_cost.h"

using hullopt::io::EstimateRunCost;
using hullopt::io::RunCostRefusal;
using hullopt::io::StripWork;

namespace {

StripWork Catamaran(int sections, int panels) {
  StripWork w;
  w.sections = sections;
  w.panels = panels;
  w.bodies = 2;
  w.frequencies = 45;
  return w;
}

}  // namespace

TEST_CASE("run cost: within a factor 1.5 of measured runs", "[run_cost]") {
  // hullopt rao examples/rao_delft372.yaml (Delft 372 catamaran, 45 frequencies, adaptive_grid: off) with
  // sections and panels changed, OMP_NUM_THREADS=1, /usr/bin/time: user CPU seconds and peak resident set (MB)
  // on the 2-core build machine. The 20 x 8 run is mostly process start-up and is left out.
  struct Measured {
    int sections, panels;
    double cpu_s, rss_mb;
  };
  const Measured runs[] = {{40, 14, 0.08, 14.4},  {80, 14, 0.30, 20.6},  {40, 28, 0.28, 19.5},
                           {80, 28, 1.37, 39.6},  {160, 14, 1.37, 45.4}, {160, 28, 7.63, 117.4},
                           {40, 56, 1.88, 39.5},  {80, 56, 6.10, 109.5}};
  // A refusal is for runs far beyond the limits; a factor 1.5 keeps the printed figure honest ("about").
  constexpr double kTimeFactor = 1.5;
  // Memory is counted, not timed: the operators are the resident set.
  constexpr double kMemoryFactor = 1.3;
  for (const auto& r : runs) {
    INFO(r.sections << " x " << r.panels);
    const auto c = EstimateRunCost(Catamaran(r.sections, r.panels));
    CHECK(c.seconds < kTimeFactor * r.cpu_s);
    CHECK(c.seconds > r.cpu_s / kTimeFactor);
    const double mb = c.bytes / 1.0e6;
    CHECK(mb < kMemoryFactor * r.rss_mb);
    CHECK(mb > r.rss_mb / kMemoryFactor);
  }
  // Conventional strip theory: 3.00 s at 40 x 14 (frequency-domain half sections).
  StripWork stf = Catamaran(40, 14);
  stf.method = "strip_theory_stf";
  const double stf_s = EstimateRunCost(stf).seconds;
  CHECK(stf_s < kTimeFactor * 3.00);
  CHECK(stf_s > 3.00 / kTimeFactor);
  // Oblique seas, 5 headings (180, 165, 150, 135, 120 deg) at 40 x 14: 0.33 s by the time-domain strip method
  // (the kernel with its lateral rows), 35 s by the oblique-sea strip theory (full sections, each heading its
  // own encounter frequencies).
  StripWork td5 = Catamaran(40, 14);
  td5.headings = 5;
  stf.headings = 5;
  const double td5_s = EstimateRunCost(td5).seconds, stf5_s = EstimateRunCost(stf).seconds;
  INFO("estimates: 5 headings time-domain " << td5_s << " s, strip theory " << stf5_s << " s");
  CHECK(td5_s < kTimeFactor * 0.33);
  CHECK(td5_s > 0.33 / kTimeFactor);
  CHECK(stf5_s < kTimeFactor * 35.0);
  CHECK(stf5_s > 35.0 / kTimeFactor);
}

TEST_CASE("run cost: scaling follows the operation counts", "[run_cost]") {
  // Memory operators: (S^2/2) p^2 doubles. Doubling the panels quadruples them (force rows, S^2 P, add 6 %).
  const double m1 = EstimateRunCost(Catamaran(200, 50)).kernel_bytes;
  const double m2 = EstimateRunCost(Catamaran(200, 100)).kernel_bytes;
  CHECK(m2 / m1 == Approx(4.0).epsilon(0.05));
  // Time between the Green term (x4 for doubled sections) and the reduction term (x8).
  const double t1 = EstimateRunCost(Catamaran(100, 50)).kernel_seconds;
  const double t2 = EstimateRunCost(Catamaran(200, 50)).kernel_seconds;
  CHECK(t2 / t1 > 3.9);
  CHECK(t2 / t1 < 8.0);
  // Designs multiply the time, not the memory (one kernel at a time); parallel kernels the memory.
  StripWork many = Catamaran(40, 14);
  many.kernels = 1000;
  const auto one = EstimateRunCost(Catamaran(40, 14)), thousand = EstimateRunCost(many);
  CHECK(thousand.seconds == Approx(1000 * (one.seconds - 0.04) + 0.04).epsilon(1e-9));
  CHECK(thousand.bytes == one.bytes);
  many.parallel = 4;
  CHECK(EstimateRunCost(many).bytes == Approx(4 * one.bytes));
}

TEST_CASE("run cost: refusals name the limit and the key", "[run_cost]") {
  // The paper's 40 x 14 and the default campaign (300 evaluations) pass.
  CHECK(RunCostRefusal(Catamaran(40, 14), EstimateRunCost(Catamaran(40, 14))).empty());
  StripWork campaign = Catamaran(40, 14);
  campaign.kernels = 301;
  campaign.frequencies = 60;
  CHECK(RunCostRefusal(campaign, EstimateRunCost(campaign)).empty());

  // A trihull at the documented maxima: (401^2/2) x 150^2 doubles = 14.5 GB of memory operators.
  StripWork tri = Catamaran(400, 100);
  tri.bodies = 3;
  const std::string memory = RunCostRefusal(tri, EstimateRunCost(tri));
  CHECK_THAT(memory, Catch::Contains("estimated memory"));
  CHECK_THAT(memory, Catch::Contains("exceeds the limit of 8 GiB"));
  CHECK_THAT(memory, Catch::Contains("solver.sections = 400 and solver.panels = 100"));
  CHECK_THAT(memory, Catch::Contains("--force"));

  // A catamaran at the maxima (the largest strip the documented limits allow for two bodies) passes: 6 GiB and
  // about 55 min of one core (the reduction, S^3 p^3 / 6 multiply-adds, dominates there).
  const StripWork cat = Catamaran(400, 100);
  CHECK(EstimateRunCost(cat).bytes < hullopt::io::kCostLimitBytes);
  CHECK(EstimateRunCost(cat).seconds < hullopt::io::kCostLimitSeconds);
  CHECK(RunCostRefusal(cat, EstimateRunCost(cat)).empty());

  // An explore of 200 designs over five headings at 40 x 14: by the time-domain method within the limits, by the
  // oblique-sea strip theory (about 40 s a design) refused, the samples driving it.
  StripWork headings = Catamaran(40, 14);
  headings.kernels = 200;
  headings.frequencies = 60;
  headings.headings = 5;
  headings.count_key = "explore.samples";
  CHECK(RunCostRefusal(headings, EstimateRunCost(headings)).empty());
  headings.method = "strip_theory_stf";
  CHECK_THAT(RunCostRefusal(headings, EstimateRunCost(headings)), Catch::Contains("explore.samples drives it"));

  // A million designs of a cheap kernel: the design count drives it.
  StripWork sweep = Catamaran(20, 8);
  sweep.kernels = 1000000;
  sweep.count_key = "explore.samples";
  CHECK_THAT(RunCostRefusal(sweep, EstimateRunCost(sweep)), Catch::Contains("explore.samples drives it"));

  // Kernels held at once: 100 threads of a 0.1 GiB kernel.
  StripWork threads = Catamaran(160, 28);
  threads.kernels = 100;
  threads.parallel = 100;
  threads.parallel_key = "--threads";
  CHECK_THAT(RunCostRefusal(threads, EstimateRunCost(threads)), Catch::Contains("100 kernels held at once (--threads)"));

  // Time marching over many frequencies: the frequencies drive it.
  StripWork marching = Catamaran(200, 50);
  marching.path = "time_marching";
  marching.frequencies = 1000;
  CHECK_THAT(RunCostRefusal(marching, EstimateRunCost(marching)), Catch::Contains("solver.frequencies (1000)"));
}

TEST_CASE("run cost: strip settings from a resolved config", "[run_cost]") {
  const YAML::Node r = YAML::Load(
      "hull: { parametric: { type: trihull } }\n"
      "solver: { sections: 30, panels: 10, stations: cell_midpoints, path: time_marching,\n"
      "          frequencies: { range: { quantity: omega_rad_s, from: 1, to: 2, count: 17 } } }\n");
  const StripWork w = hullopt::io::StripWorkFromResolved(r, 60);
  CHECK(w.sections == 30);
  CHECK(w.panels == 10);
  CHECK(w.bodies == 3);
  CHECK_FALSE(w.cell_faces);
  CHECK(w.path == "time_marching");
  CHECK(w.frequencies == 17);
  const StripWork offsets = hullopt::io::StripWorkFromResolved(
      YAML::Load("hull: { offsets_csv: a.csv, hulls: 2 }\nsolver: { interaction: false }\n"), 60);
  CHECK(offsets.bodies == 1);  // each body alone
  CHECK(offsets.frequencies == 60);
}
