#pragma once
// Evaluating a list of designs in parallel (OpenMP) while handing the results over strictly in list order, so
// that whatever the thread count the output (samples.csv) is identical and a prefix of it is always complete.
#include <functional>
#include <vector>

#include "optimizer/evaluation_record.h"
#include "optimizer/evaluator.h"

namespace hullopt::opt {

/// Evaluates xs[first..last) with `threads` OpenMP threads (1 = serial; ignored if the evaluator is not
/// thread-safe). `make_record` turns (index, x, result, wall time) into the record (feasibility, run/step);
/// `sink` receives the records in index order, one at a time (serialised), as soon as all earlier ones are
/// done. Exceptions other than generator refusals are rethrown after the loop.
void EvaluateInOrder(
    Evaluator& evaluator, const std::vector<std::vector<double>>& xs, int first, int last, int threads,
    const std::function<EvaluationRecord(int index, const std::vector<double>& x, const EvalResult& r,
                                         double wall_time_s)>& make_record,
    const RecordSink& sink);

}  // namespace hullopt::opt
