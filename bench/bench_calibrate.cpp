// Wall time of one Cs calibration (one hull, one speed: Delft 372 at Fn 0.75, 13 points, heave and pitch)
// with the synthetic oscillator model: the fit's own overhead (Ceres, numeric differentiation, covariance,
// peaks). With the strip solver, add model_evaluations × (cost of one RAO evaluation at the measured
// frequencies). Target: under 5 s wall for the whole calibration.
#include <benchmark/benchmark.h>

#include <chrono>
#include <thread>

#include "io/formats/tank_rao_reader.h"
#include "calibration/fit/cs_calibration.h"
#include "calibration/fit/synthetic_oscillator_rao.h"

using namespace hullopt;

namespace {
std::vector<opt::CalibrationCase> DelftCases() {
  const auto pts =
      io::ReadTankRaoCsv(std::string(HULLOPT_SOURCE_DIR) + "/data/delft372/delft372_tank_rao_fn075.csv");
  return io::GroupTankRaoBySpeed(pts, {0.75}, "", 0.0);
}

calib::SyntheticOscillatorOptions DelftLike() {
  calib::SyntheticOscillatorOptions o;
  o.heave_natural_rad_s = 8.1;
  o.pitch_natural_rad_s = 8.4;
  o.pitch_zeta0 = 0.2;
  o.pitch_zeta_per_Cs = 2.0;
  return o;
}

void BM_CalibrateOneHullOneSpeed(benchmark::State& state) {
  const auto cases = DelftCases();
  const auto model = calib::MakeSyntheticOscillatorModel(DelftLike(), cases);
  calib::CsCalibrationOptions o;
  o.Cs_initial = 0.024;
  int evaluations = 0;
  for (auto _ : state) {
    const auto r = calib::CalibrateCs(model, cases, o);
    evaluations = r.model_evaluations;
    benchmark::DoNotOptimize(r.parameters[0]);
  }
  state.counters["model_evaluations"] = evaluations;
}
BENCHMARK(BM_CalibrateOneHullOneSpeed)->Unit(benchmark::kMillisecond);

// The same fit with a model that costs 10 ms per call (a stand-in for the strip solver's 2×2 solves at the
// measured frequencies; the kernels are precomputed outside the fit): wall ≈ evaluations × 10 ms + overhead.
void BM_CalibrateWith10msModel(benchmark::State& state) {
  const auto cases = DelftCases();
  const auto fast = calib::MakeSyntheticOscillatorModel(DelftLike(), cases);
  const calib::CsRaoModel slow = [fast](double Cs, int c) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return fast(Cs, c);
  };
  calib::CsCalibrationOptions o;
  o.Cs_initial = 0.024;
  for (auto _ : state) benchmark::DoNotOptimize(calib::CalibrateCs(slow, cases, o).parameters[0]);
}
BENCHMARK(BM_CalibrateWith10msModel)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
}  // namespace

BENCHMARK_MAIN();
