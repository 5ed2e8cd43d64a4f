#include "optimizer/parallel_evaluation.h"

#include <chrono>
#include <exception>
#include <mutex>

namespace hullopt::opt {

void EvaluateInOrder(
    Evaluator& evaluator, const std::vector<std::vector<double>>& xs, int first, int last, int threads,
    const std::function<EvaluationRecord(int index, const std::vector<double>& x, const EvalResult& r,
                                         double wall_time_s)>& make_record,
    const RecordSink& sink) {
  const int count = last - first;
  if (count <= 0) return;
  std::vector<EvaluationRecord> done(count);
  std::vector<char> ready(count, 0);
  int next = 0;  // first index (relative) not yet handed to the sink
  std::mutex mutex;
  std::exception_ptr error;
  const int nthreads = evaluator.IsThreadSafe() ? std::max(1, threads) : 1;
  (void)nthreads;  // read only by the OpenMP pragma; a build without OpenMP runs in order
#pragma omp parallel for schedule(dynamic, 1) num_threads(nthreads)
  for (int k = 0; k < count; ++k) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (error) continue;
    }
    try {
      const int i = first + k;
      const auto t0 = std::chrono::steady_clock::now();
      const EvalResult r = EvaluateSafely(evaluator, xs[i]);
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      EvaluationRecord rec = make_record(i, xs[i], r, wall);
      std::lock_guard<std::mutex> lock(mutex);
      done[k] = std::move(rec);
      ready[k] = 1;
      while (next < count && ready[next]) {
        if (sink) sink(done[next]);
        done[next] = EvaluationRecord{};  // free memory of handed-over records
        ++next;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace hullopt::opt
