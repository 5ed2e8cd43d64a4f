#pragma once
// The ε-constraint Pareto sweep of `hullopt optimize` (optimize.pareto): the campaign objective (MSI, rms
// acceleration or operability) against a resistance quantity at the design speed.
//
//   optimize:
//     pareto: { quantity: P_E_kW, points: 8, to: 11200, starts: 4 }   # from: optional (default: the anchor's minimum)
//
// 1. Anchor: the same campaign minimising the quantity itself (objective measure = quantity) → DIR/anchor.
// 2. Points k = 1..points: minimise the campaign objective with <quantity>_max = ε_k, ε_k evenly spaced from
//    `from` (default: the anchor's minimum + 0.1 %) to `to`, each a multistart of `starts` runs: run 0 from the
//    previous point's best design (feasible for the next, looser limit, so a local algorithm always has a
//    feasible start and the front cannot rise), runs 1.. from seeded random points of the box (seed + k - 1),
//    which let a local algorithm leave the local minimum the continuation stops in → DIR/point_k.
// Every run is an ordinary optimize run (history.csv, best.yaml re-runnable, summary.json, resumable).
// DIR/pareto.csv and DIR/pareto.svg collect the front.
#include <functional>
#include <string>

namespace hullopt::campaign {

/// True if the config's optimize block has a `pareto` key.
bool HasParetoSweep(const std::string& config_file);

/// Runs the sweep; `run_optimize(config, out)` runs one ordinary campaign. Returns the sweep's result line
/// (points, range, files written; no newline). Throws io::InputError for a bad pareto block (fewer than 2
/// points, unknown quantity, to <= from, a quantity already constrained).
std::string RunParetoSweep(const std::string& config_file, const std::string& out_dir,
                    const std::function<void(const std::string&, const std::string&)>& run_optimize);

}  // namespace hullopt::campaign
