// Seas + MSI part of the 14-hull study: 14 designs (synthetic RAO tables of 60 frequencies), 6 seas on the
// paper's sea-state line, 3 positions. The RAO computation itself is benchmarked with the ship solver.
#include <benchmark/benchmark.h>

#include <complex>
#include <vector>

#include "seas/design_evaluation.h"
#include "seakeeping/motions/encounter_frequency.h"
#include "seas/sea_state_line.h"

namespace sk = hullopt::sk;

namespace {
constexpr double kG = 9.81;
constexpr double kU = 40.0 * 1852.0 / 3600.0;

std::vector<sk::RaoTable> StudyTables() {
  std::vector<sk::RaoTable> tables;
  for (int d = 0; d < 14; ++d) {
    sk::RaoTable t;
    t.speed_m_s = kU;
    t.g_m_s2 = kG;
    const double wn = 1.2 + 0.05 * d;
    for (int i = 0; i < 60; ++i) {
      const double w = 0.2 + 2.8 * i / 59.0, we = sk::HeadSeaEncounterFrequency(w, kU, kG);
      const std::complex<double> den(1.0 - (we / wn) * (we / wn), 0.5 * we / wn);
      t.omega_rad_s.push_back(w);
      t.omega_e_rad_s.push_back(we);
      t.heave.push_back(1.0 / den);
      t.pitch.push_back(std::complex<double>(0.0, -1.0) / den);
    }
    tables.push_back(t);
  }
  return tables;
}

const std::vector<double> kHeights = {0.5, 1.0, 1.5, 2.0, 2.5, 3.0};

void BM_StudySeasAndMsi(benchmark::State& state) {  // spectra built inside, as `hullopt evaluate` does once
  const auto tables = StudyTables();
  const auto seas = sk::SeaStateLine(kHeights);
  for (auto _ : state) {
    const auto spectra = sk::BuildSpectra(seas);
    double sum = 0.0;
    for (const auto& t : tables)
      sum += sk::EvaluateDesign(t, {20.0, 25.0}, spectra, {}, {}).seas[5].mean.msi_pct;
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_StudySeasAndMsi)->Unit(benchmark::kMillisecond);

void BM_OneDesignPrebuiltSpectra(benchmark::State& state) {  // optimiser inner loop
  const auto tables = StudyTables();
  const auto spectra = sk::BuildSpectra(sk::SeaStateLine(kHeights));
  for (auto _ : state) {
    benchmark::DoNotOptimize(sk::EvaluateDesign(tables[0], {20.0, 25.0}, spectra, {}, {}));
  }
}
BENCHMARK(BM_OneDesignPrebuiltSpectra)->Unit(benchmark::kMicrosecond);

void BM_BuildSpectrum(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sk::WaveSpectrum(sk::SeaState::JonswapTz(3.0, 7.5)));
}
BENCHMARK(BM_BuildSpectrum)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
