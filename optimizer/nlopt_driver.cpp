#include "optimizer/nlopt_driver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <nlopt.hpp>

#include "optimizer/nlopt_algorithms.h"
#include "optimizer/seeded_random.h"

namespace hullopt::opt {
namespace {

const char* ResultName(nlopt::result r) {
  switch (r) {
    case nlopt::SUCCESS:
      return "SUCCESS";
    case nlopt::STOPVAL_REACHED:
      return "STOPVAL_REACHED";
    case nlopt::FTOL_REACHED:
      return "FTOL_REACHED";
    case nlopt::XTOL_REACHED:
      return "XTOL_REACHED";
    case nlopt::MAXEVAL_REACHED:
      return "MAXEVAL_REACHED";
    case nlopt::MAXTIME_REACHED:
      return "MAXTIME_REACHED";
    default:
      return "FAILURE";
  }
}

bool SameBits(const std::vector<double>& a, const double* b, unsigned n) {
  return a.size() == n && (n == 0 || std::memcmp(a.data(), b, n * sizeof(double)) == 0);
}

// Seeds: one independent stream per (campaign seed, run); NLopt's own generator for stochastic algorithms.
std::uint64_t RunSeed(std::uint64_t seed, int run) {
  SeededRandom mix(seed ^ (0x6A09E667F3BCC909ULL * static_cast<std::uint64_t>(run + 1)));
  return mix.NextBits();
}

// State shared by the NLopt callbacks of one run.
struct RunState {
  NloptDriver* driver = nullptr;
  std::function<EvaluationRecord(int step, const std::vector<double>& x)> evaluate;
  const RecordSink* sink = nullptr;
  int steps = 0;
  int replayed = 0;
  EvaluationRecord last;  // the most recent evaluation: constraints are asked at the objective's point
  bool has_last = false;
  double worst_seen = 0.0;  // largest produced objective so far (base of the refusal penalty)
  bool has_worst = false;
  bool found_feasible = false;
  double best_objective = 0.0;
  std::vector<double> best_x;
  bool penalise = false;  // the current stage's algorithm sees the exact penalty (no native constraints)
  std::exception_ptr error;

  const EvaluationRecord& At(unsigned n, const double* x) {
    if (has_last && SameBits(last.x, x, n)) return last;
    last = evaluate(steps, std::vector<double>(x, x + n));
    has_last = true;
    ++steps;
    if (last.replayed) ++replayed;
    if (last.result.produced && (!has_worst || last.result.objective > worst_seen)) {
      worst_seen = last.result.objective;
      has_worst = true;
    }
    if (last.feasible && (!found_feasible || last.result.objective < best_objective)) {
      found_feasible = true;
      best_objective = last.result.objective;
      best_x = last.x;
    }
    if (*sink) (*sink)(last);
    return last;
  }
};

double Objective(unsigned n, const double* x, double* grad, void* data) {
  auto* s = static_cast<RunState*>(data);
  (void)grad;  // derivative-free algorithms only (CampaignDefinition::IsValid)
  try {
    const EvaluationRecord& rec = s->At(n, x);
    return s->driver->PenalisedObjective(rec, s->has_worst ? s->worst_seen : 0.0, s->penalise);
  } catch (...) {
    s->error = std::current_exception();
    throw nlopt::forced_stop();
  }
}

void Constraints(unsigned m, double* result, unsigned n, const double* x, double* grad, void* data) {
  auto* s = static_cast<RunState*>(data);
  (void)grad;
  try {
    const EvaluationRecord& rec = s->At(n, x);
    const auto g = s->driver->constraints().Values(rec.x, rec.result);
    for (unsigned j = 0; j < m; ++j) result[j] = g[j];
  } catch (...) {
    s->error = std::current_exception();
    throw nlopt::forced_stop();
  }
}

}  // namespace

NloptDriver::NloptDriver(const CampaignDefinition& campaign, Evaluator& evaluator)
    : campaign_(campaign), evaluator_(evaluator), constraints_(campaign, evaluator.QuantityNames()) {}

std::vector<double> NloptDriver::StartPoint(int run) const {
  if (run == 0) return campaign_.StartPoint();
  SeededRandom rng(RunSeed(campaign_.seed, run));
  std::vector<double> x;
  for (const auto& v : campaign_.variables) x.push_back(v.lower + (v.upper - v.lower) * rng.Uniform());
  return x;
}

double NloptDriver::PenalisedObjective(const EvaluationRecord& rec, double worst_seen, bool penalise) const {
  if (!rec.result.produced) return worst_seen + campaign_.penalty_weight;
  if (!penalise || constraints_.size() == 0) return rec.result.objective;
  return rec.result.objective + campaign_.penalty_weight * constraints_.Violation(rec.x, rec.result);
}

EvaluationRecord NloptDriver::Evaluate(int run, int step, const std::vector<double>& x,
                                       const ReplayLookup& replay) {
  if (const EvaluationRecord* logged = LookupReplay(replay, run, step, x)) {
    EvaluationRecord rec = *logged;
    rec.run = run;
    rec.step = step;
    rec.replayed = true;
    rec.feasible = constraints_.Feasible(rec.x, rec.result, campaign_.feasibility_tol);
    return rec;
  }
  EvaluationRecord rec;
  rec.run = run;
  rec.step = step;
  rec.x = x;
  if (has_baseline_ && SameBits(baseline_.x, x.data(), static_cast<unsigned>(x.size()))) {
    rec.result = baseline_.result;  // the base design, already evaluated as the baseline
    rec.result.cost = EvalCost{};   // not computed again (--profile counts it once)
    rec.feasible = baseline_.feasible;
    return rec;
  }
  const auto t0 = std::chrono::steady_clock::now();
  rec.result = EvaluateSafely(evaluator_, x);
  rec.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rec.feasible = constraints_.Feasible(rec.x, rec.result, campaign_.feasibility_tol);
  return rec;
}

EvaluationRecord NloptDriver::EvaluateBaseline(const ReplayLookup& replay, const RecordSink& sink) {
  EvaluationRecord rec = Evaluate(-1, 0, campaign_.StartPoint(), replay);
  baseline_ = rec;
  has_baseline_ = true;
  if (sink) sink(rec);
  return rec;
}

RunResult NloptDriver::Run(int run, const ReplayLookup& replay, const RecordSink& sink) {
  const unsigned n = static_cast<unsigned>(campaign_.variables.size());
  RunResult out;
  out.run = run;
  out.start = StartPoint(run);

  RunState state;
  state.driver = this;
  state.sink = &sink;
  state.evaluate = [&](int step, const std::vector<double>& x) { return Evaluate(run, step, x, replay); };

  // One NLopt optimisation of `algorithm` from x0 with at most max_eval evaluations; returns its status.
  // Local algorithms without native constraints run inside NLopt's augmented Lagrangian (AUGLAG), which adds
  // a smooth, adaptively weighted penalty and converges onto the constraint boundary; global ones without
  // native constraints see an exact (L1) penalty in the objective (PenalisedObjective).
  auto optimize = [&](const std::string& algorithm, int max_eval, std::vector<double> x) -> std::string {
    const bool native = SupportsInequalityConstraints(algorithm);
    const bool use_auglag = !native && !IsGlobal(algorithm) && constraints_.size() > 0;
    state.penalise = !native && !use_auglag;
    nlopt::opt opt(use_auglag ? "AUGLAG" : algorithm.c_str(), n);
    auto set_common = [&](nlopt::opt& o) {
      o.set_lower_bounds(campaign_.LowerBounds());
      o.set_upper_bounds(campaign_.UpperBounds());
      o.set_maxeval(max_eval);
      if (campaign_.stopping.xtol_rel > 0) o.set_xtol_rel(campaign_.stopping.xtol_rel);
      if (campaign_.stopping.ftol_rel > 0) o.set_ftol_rel(campaign_.stopping.ftol_rel);
    };
    set_common(opt);
    if (use_auglag) {
      nlopt::opt local(algorithm.c_str(), n);
      set_common(local);
      opt.set_local_optimizer(local);
    }
    opt.set_min_objective(Objective, &state);
    if ((native || use_auglag) && constraints_.size() > 0) {
      opt.add_inequality_mconstraint(Constraints, &state, std::vector<double>(constraints_.size(), 0.0));
    }
    double f = 0.0;
    std::string status;
    try {
      status = ResultName(opt.optimize(x, f));
    } catch (const nlopt::forced_stop&) {
      if (state.error) std::rethrow_exception(state.error);
      status = "FORCED_STOP";
    } catch (const nlopt::roundoff_limited&) {
      status = "ROUNDOFF_LIMITED";  // result still usable: the best point found so far is kept below
    } catch (const std::runtime_error& e) {
      if (state.error) std::rethrow_exception(state.error);
      status = std::string("FAILURE: ") + e.what();
    }
    if (state.error) std::rethrow_exception(state.error);
    return status;
  };

  // Stochastic algorithms draw from NLopt's global generator: seed it per run so runs are reproducible
  // regardless of which process (MPI rank) executes them.
  nlopt::srand(static_cast<unsigned long>(RunSeed(campaign_.seed, run) >> 1));
  out.status = optimize(campaign_.algorithm, campaign_.stopping.max_evaluations, out.start);
  if (!campaign_.polish_algorithm.empty() && state.found_feasible) {
    const int before = state.steps;
    out.polish_status =
        optimize(campaign_.polish_algorithm, campaign_.polish_max_evaluations, state.best_x);
    out.polish_evaluations = state.steps - before;
  }
  out.evaluations = state.steps;
  out.replayed = state.replayed;
  out.found_feasible = state.found_feasible;
  out.best_objective = state.best_objective;
  out.best_x = state.found_feasible ? state.best_x : out.start;
  return out;
}

}  // namespace hullopt::opt
