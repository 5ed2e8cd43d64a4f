#include "io/config/run_cost.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {

// The model follows the kernel's loops (seakeeping/strip/strip_operators.cpp, strip_kernel_builder.cpp), with
// S strip steps, P = panels x bodies panels per step and p = P/2 in the mirror-reduced system:
//  - Green-function evaluations: one per panel pair of every step pair (n, k < n): S^2/2 x P x p;
//  - the reduction: a p x p by p x p product for every (m <= k < n): S^3/6 x p^3 multiply-adds;
//  - memory: the memory operators, S^2/2 matrices p x p (doubles), dominate; responses and force rows add
//    S p^2 and S^2 P.
// Constants: CPU seconds of one core, measured with hullopt rao (OMP_NUM_THREADS=1, Release, gcc 12, the 2-core
// build machine, quiet, adaptive_grid off) on the Delft 372 catamaran (examples/rao_delft372.yaml, 45
// frequencies) at 40 x 14, 80 x 14, 40 x 28, 80 x 28, 160 x 14, 160 x 28, 40 x 56 and 80 x 56 sections x panels:
// 0.08, 0.30, 0.28, 1.37, 1.37, 7.63, 1.88 and 6.10 s, peak resident memory 14, 21, 20, 40, 45, 117, 39 and
// 110 MB (tests/unit/test_run_cost.cpp checks the model against these). The two constants are their
// least-squares fit in relative error (every run within 30 % but 40 x 56, 1.4 times the estimate): the Green
// term dominates small strips, the reduction (the p x p block products of the memory sums) the large ones.
constexpr double kSecondsPerGreenEvaluation = 1.3e-7;
constexpr double kSecondsPerReductionMultiplyAdd = 2.9e-10;
// One periodic-path frequency: the kernel's force rows against the motion's normal velocities, S^2/2 x P
// multiply-adds, plus a 2 x 2 solve (a small part of the runs above).
constexpr double kSecondsPerSweepMultiplyAdd = 2.0e-9;
// Time marching: every frequency marched to a steady state (up to MarchingOptions::max_periods); measured at
// 20 x 8, 5 frequencies (0.09 s against 0.06 s periodic with 45) as about 700 periodic sweeps per frequency.
constexpr double kTimeMarchingFactor = 1000.0;
// Strip theory (frequency-domain sections): P^2 frequency-domain Green evaluations per section and frequency;
// measured 3.00 s at 40 x 14, 45 frequencies on the catamaran (28 panels per section; the half-section heave
// solver).
constexpr double kSecondsPerFrequencyDomainEvaluation = 2.1e-6;
// Oblique seas (docs/performance.md, "Oblique seas: cost per heading", "The time-domain strip method over
// headings"): the time-domain kernel with its lateral rows is the kernel above on full sections (p = P: twice
// the Green evaluations, eight times the reduction; 139 ms against 61 ms for the mirror-reduced head-sea
// kernel of the Delft 372 demihull 40 x 14), and each heading's periodic sweep of three rows costs 22 ms against
// 6.6 ms for the head-sea sweep; the oblique strip theory's full sections cost 1.94 s per heading at speed
// against 0.78 s for the head-sea half sections (the catamaran 40 x 14, 20 frequencies; `rao` of the
// catamaran at 40 x 14, 45 frequencies: 3.0 s head seas, 35 s at five headings).
constexpr double kObliqueSweepFactorPerHeading = 3.3;
constexpr double kObliqueStripTheoryFactorPerHeading = 2.5;
// Libraries, hull and tables: the 20 x 8 run's 0.06 s and 11 MB.
constexpr double kBaseSeconds = 0.04;
constexpr double kBaseBytes = 11.0 * 1024 * 1024;

int Steps(const StripWork& w) { return w.cell_faces ? w.sections + 1 : w.sections; }

std::string Seconds(double s) {
  char buf[64];
  if (s < 120) std::snprintf(buf, sizeof buf, "%.2g s", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.3g min", s / 60);
  else if (s < 4 * 86400) std::snprintf(buf, sizeof buf, "%.3g h", s / 3600);
  else std::snprintf(buf, sizeof buf, "%.3g days", s / 86400);
  return buf;
}

std::string Bytes(double b) {
  char buf[64];
  if (b < 1024.0 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%.3g MiB", b / (1024.0 * 1024));
  else std::snprintf(buf, sizeof buf, "%.3g GiB", b / (1024.0 * 1024 * 1024));
  return buf;
}

long CountFrequencies(const YAML::Node& f, long fallback) {
  if (!f || !f.IsMap()) return fallback;
  for (const char* key : {"lambda_over_L", "omega_rad_s", "omega_e_rad_s"})
    if (f[key] && f[key].IsSequence()) return static_cast<long>(f[key].size());
  if (f["range"] && f["range"].IsMap() && f["range"]["count"]) return f["range"]["count"].as<long>(fallback);
  return fallback;
}

}  // namespace

RunCost EstimateRunCost(const StripWork& w) {
  // The time-domain kernel with lateral rows (oblique seas) is built on full sections: no mirror reduction.
  const bool lateral = w.headings > 0 && w.method == "time_domain_strip";
  const double S = Steps(w), P = static_cast<double>(w.panels) * w.bodies, p = lateral ? P : 0.5 * P;
  const double F = static_cast<double>(w.frequencies);
  RunCost c;
  if (w.method == "section_time_domain") {
    // Lag operators LagMemory(l), l < lags: P x p Green evaluations each, held as p x p; every frequency sums
    // them (complex) and solves a p x p system. `lags` is the solver's cap, so this is an upper bound
    // (examples/section_semicircle.yaml: estimated 2.5 s, measured 0.9 s).
    const double L = w.lags;
    c.kernel_seconds = kSecondsPerGreenEvaluation * L * P * p;
    c.sweep_seconds = kSecondsPerSweepMultiplyAdd * (4.0 * L * p * p + p * p * p) * F;
    c.kernel_bytes = kBaseBytes + 8.0 * L * (p * p + P);
  } else if (w.method == "strip_theory_stf") {
    c.kernel_seconds = 0.0;
    c.sweep_seconds = kSecondsPerFrequencyDomainEvaluation * S * F * P * P;
    c.kernel_bytes = kBaseBytes + 8.0 * (3.0 * P * P + S * F * 8.0);
  } else {
    c.kernel_seconds = kSecondsPerGreenEvaluation * 0.5 * S * S * P * p +
                       kSecondsPerReductionMultiplyAdd * S * S * S * p * p * p / 6.0;
    const double sweep = kSecondsPerSweepMultiplyAdd * 0.5 * S * S * P * F;
    c.sweep_seconds = w.path == "time_marching" ? kTimeMarchingFactor * sweep : sweep;
    c.kernel_bytes = kBaseBytes + 8.0 * (0.5 * S * S * p * p + 0.5 * S * S * (P + p) + 3.0 * S * p * p);
  }
  if (w.headings > 0 && w.method == "strip_theory_stf") {
    c.sweep_seconds *= kObliqueStripTheoryFactorPerHeading * w.headings;
  } else if (lateral) {
    c.sweep_seconds *= kObliqueSweepFactorPerHeading * w.headings;
  }
  const double kernels = static_cast<double>(std::max(1L, w.kernels));
  c.seconds = kBaseSeconds + kernels * (c.kernel_seconds + static_cast<double>(std::max(1L, w.sweeps_per_kernel)) * c.sweep_seconds);
  c.bytes = std::max(1, w.parallel) * c.kernel_bytes;
  return c;
}

StripWork StripWorkFromResolved(const YAML::Node& resolved, long default_frequencies) {
  StripWork w;
  w.frequencies = default_frequencies;
  const YAML::Node solver = resolved["solver"];
  if (solver && solver.IsMap()) {
    if (solver["method"]) w.method = solver["method"].as<std::string>(w.method);
    if (solver["path"]) w.path = solver["path"].as<std::string>(w.path);
    if (solver["sections"]) w.sections = solver["sections"].as<int>(w.sections);
    if (solver["panels"]) w.panels = solver["panels"].as<int>(w.panels);
    if (solver["stations"]) w.cell_faces = solver["stations"].as<std::string>("cell_faces") != "cell_midpoints";
    w.frequencies = CountFrequencies(solver["frequencies"], default_frequencies);
  }
  const YAML::Node hull = resolved["hull"];
  w.bodies = 1;
  if (hull && hull.IsMap()) {
    if (hull["parametric"] && hull["parametric"]["type"]) {
      const std::string type = hull["parametric"]["type"].as<std::string>("monohull");
      w.bodies = type == "trihull" ? 3 : (type == "monohull" ? 1 : 2);
    } else if (hull["hulls"]) {
      w.bodies = hull["hulls"].as<int>(1);
    }
  }
  // Without interaction each body is solved alone (mirror pairs once): the strip holds one body.
  if (solver && solver.IsMap() && solver["interaction"] && !solver["interaction"].as<bool>(true)) w.bodies = 1;
  return w;
}

std::string DescribeRunCost(const StripWork& w, const RunCost& c) {
  char what[256];
  const long kernels = std::max(1L, w.kernels);
  if (w.method == "section_time_domain") {
    std::snprintf(what, sizeof what, "a section strip of %d panels, up to %d time lags", w.panels * w.bodies,
                  w.lags);
  } else {
    std::snprintf(what, sizeof what, "%ld kernel%s of %d steps x %d panels (%s%s)", kernels,
                  kernels == 1 ? "" : "s", Steps(w), w.panels * w.bodies, w.method.c_str(),
                  w.method == "strip_theory_stf" ? "" : (", " + w.path).c_str());
  }
  char buf[512];
  std::snprintf(buf, sizeof buf, "cost estimate: %s, %ld frequencies%s%s: about %s on one core, %s of memory", what,
                w.frequencies, w.headings > 0 ? (" x " + std::to_string(w.headings) + " headings").c_str() : "",
                w.sweeps_per_kernel > 1 ? (" x " + std::to_string(w.sweeps_per_kernel) + " sweeps").c_str() : "",
                Seconds(c.seconds).c_str(), Bytes(c.bytes).c_str());
  return buf;
}

std::string RunCostRefusal(const StripWork& w, const RunCost& c) {
  const bool memory = c.bytes > kCostLimitBytes, time = c.seconds > kCostLimitSeconds;
  if (!memory && !time) return "";
  std::string driver;
  const std::string resolution =
      w.method == "section_time_domain"
          ? "section.panels = " + std::to_string(w.panels) + " and section.count = " + std::to_string(w.bodies)
          : "solver.sections = " + std::to_string(w.sections) + " and solver.panels = " + std::to_string(w.panels);
  if (memory) {
    driver = w.parallel > 1 && c.kernel_bytes <= kCostLimitBytes
                 ? std::to_string(w.parallel) + " kernels held at once (" + w.parallel_key + ") drive it"
                 : resolution + " drive it (memory grows as sections^2 x panels^2)";
  } else {
    const double one = c.kernel_seconds + std::max(1L, w.sweeps_per_kernel) * c.sweep_seconds;
    if (w.kernels > 1 && one <= kCostLimitSeconds && !w.count_key.empty())
      driver = w.count_key + " drives it (" + std::to_string(w.kernels) + " kernels of about " + Seconds(one) +
               " each)";
    else if (c.sweep_seconds > c.kernel_seconds)
      driver = "solver.frequencies (" + std::to_string(w.frequencies) + ")" +
               (w.headings > 0 ? " at " + std::to_string(w.headings) + " headings" : std::string()) +
               (w.path == "time_marching" ? " on solver.path: time_marching" : std::string()) + " drives it";
    else
      driver = resolution + " drive it (time grows as sections^2 x panels^2 to sections^3 x panels^3)";
  }
  char limit[160];
  std::snprintf(limit, sizeof limit, "estimated %s %s exceeds the limit of %s", memory ? "memory" : "time",
                memory ? Bytes(c.bytes).c_str() : Seconds(c.seconds).c_str(),
                memory ? Bytes(kCostLimitBytes).c_str() : Seconds(kCostLimitSeconds).c_str());
  return DescribeRunCost(w, c) + "; " + limit + ": " + driver + "; reduce it, or give --force to run it anyway";
}

std::string CheckRunCostLine(const std::string& command, const StripWork& work, bool force) {
  const RunCost cost = EstimateRunCost(work);
  const std::string refusal = RunCostRefusal(work, cost);
  if (!refusal.empty() && !force) throw InputError(command + ": " + refusal);
  // Runs that finish within a minute and fit in 1 GiB are not worth a line: stderr then holds only warnings.
  constexpr double kQuietSeconds = 60.0, kQuietBytes = 1024.0 * 1024.0 * 1024.0;
  if (refusal.empty() && cost.seconds < kQuietSeconds && cost.bytes < kQuietBytes) return "";
  return "hullopt: " + command + ": " + DescribeRunCost(work, cost) +
         (refusal.empty() ? "" : " (beyond the limits; running because of --force)");
}

}  // namespace hullopt::io
