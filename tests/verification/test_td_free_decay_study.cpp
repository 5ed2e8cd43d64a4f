// Study behind the free-decay tests of test_td_strip_solver.cpp: why the second-cycle log
// decrement of the 14-panel time-domain release differs from the prediction from the time-domain
// coefficients, and how the frequency-domain (lid on / off) predictions converge with the panels. Hidden
// (minutes of CPU); output on stdout:
//   ./build/tests/verification_td_free_decay_study "[decay_study]"      (panels, dt, lid, Fourier grid)
//   ./build/tests/verification_td_free_decay_study "[decay_ringing]"    (irregular-frequency ringing, 14
//   panels)
//   ./build/tests/verification_td_free_decay_study "[decay_ringing_N]"  (ringing amplitude vs panels)
#include <catch2/catch.hpp>

#include "support/release_march.h"
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "support/free_decay.h"
#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/strip_marcher.h"
#include "seakeeping/strip/strip_operators.h"
#include "seakeeping/strip/td_heave_coefficients.h"

using namespace hullopt::sk;
namespace {
constexpr double kG = 9.81, kRho = 1025.0;
Eigen::VectorXd Nz(const std::vector<Panel>& p) { return hullopt::testing::PanelNz(p); }
struct M {
  double period, l1, l2, p1, p3;
};
M Measure(const std::vector<double>& h, double dt) {
  std::vector<double> zero, ext;
  const int N = h.size();
  for (int n = 1; n < N; ++n)
    if ((h[n - 1] > 0) != (h[n] > 0)) zero.push_back((n - 1 + h[n - 1] / (h[n - 1] - h[n])) * dt);
  for (int n = 1; n + 1 < N; ++n)
    if ((h[n] - h[n - 1]) * (h[n + 1] - h[n]) < 0) ext.push_back(h[n]);
  if (zero.size() < 5 || ext.size() < 4) return {0, 0, 0, 0, 0};
  return {zero[4] - zero[2], std::log(h[0] / ext[1]), std::log(ext[1] / ext[3]), ext[1], ext[3]};
}
using hullopt::testing::Times;
FreeDecayInput FdInput(const std::vector<Panel>& panels, double m, double C, int lid, double dw,
                       double wmax) {
  FrequencyDomainOptions fo;
  fo.rho_kg_m3 = kRho, fo.g_m_s2 = kG, fo.lid_panels = lid;
  FreeDecayInput in;
  for (double w = 0.1; w <= wmax + 1e-9; w += dw) in.omega_rad_s.push_back(w);
  const auto fd = SolveSectionFrequencyDomain({panels}, in.omega_rad_s, fo);
  for (const auto& h : fd) in.a33_kg_per_m.push_back(h.a33()), in.b33_kg_per_m_s.push_back(h.b33());
  in.a33_infinite_kg_per_m = SolveSectionFrequencyDomain({panels}, std::sqrt(200 * kG), fo).a33();
  in.mass_kg_per_m = m, in.restoring_n_per_m2 = C;
  return in;
}
FreeDecayInput TdInput(const StripOperators& ops, const std::vector<Panel>& panels, double m, double C,
                       double dw, double wmax, double band_lo = 0, double band_hi = 0) {
  FreeDecayInput in;
  for (double w = 0.1; w <= wmax + 1e-9; w += dw) {
    if (w > band_lo && w < band_hi) continue;
    const auto I = SteadyHeaveMomentum(ops, w, ops.Steps() - 1);
    in.omega_rad_s.push_back(w), in.a33_kg_per_m.push_back(-I.real()),
        in.b33_kg_per_m_s.push_back(w * I.imag());
  }
  in.a33_infinite_kg_per_m = -ops.MomentumCurrent(0).dot(ops.Solve(0, Nz(panels)).col(0));
  in.mass_kg_per_m = m, in.restoring_n_per_m2 = C;
  return in;
}
void Print(const char* name, const M& a) {
  std::printf("%-48s period %.4f  logdec1 %.4f  logdec2 %.4f  peak1 %.5f peak2 %.5f\n", name, a.period, a.l1,
              a.l2, a.p1, a.p3);
}
}  // namespace

TEST_CASE("free decay: panels, time step, lid and Fourier grid", "[.][decay_study]") {
  const double R = 1.0, m = kRho * M_PI * R * R / 2, C = 2 * kRho * kG * R;
  const double T = 8.0;
  for (int np : {14, 28, 56}) {
    const auto panels = PanelSymmetricSection(SemicircleContour(R), np);
    for (int lid : {-1, 0}) {
      const auto in = FdInput(panels, m, C, lid, 0.05, 12.05);
      char buf[100];
      std::snprintf(buf, sizeof buf, "FD %d panels lid %d", np, lid);
      Print(buf, Measure(FreeDecayFromCoefficients(in, Times(T / 0.01, 0.01)), 0.01));
      if (np == 14 && lid == -1) {
        auto in2 = FdInput(panels, m, C, lid, 0.025, 24.0);
        Print("FD 14 lid on, dw 0.025 to 24",
              Measure(FreeDecayFromCoefficients(in2, Times(T / 0.01, 0.01)), 0.01));
      }
    }
  }
  for (auto [np, dt] : std::vector<std::pair<int, double>>{
           {14, 0.02}, {14, 0.01}, {14, 0.04}, {28, 0.02}, {28, 0.01}, {56, 0.02}}) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto panels = PanelSymmetricSection(SemicircleContour(R), np);
    const int N = static_cast<int>(std::lround(T / dt));
    const auto ops = BuildFixedSectionOperators(panels, N, dt, kRho, kG);
    const auto x = hullopt::testing::ReleaseHistory(ops, panels, m, C, N);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    char buf[100];
    std::snprintf(buf, sizeof buf, "TD march %d panels dt %.3f (%.1f s)", np, dt, sec);
    Print(buf, Measure(x, dt));
    if (np == 14 && dt == 0.02) {
      const int Nl = 1500;
      const auto opsl = BuildFixedSectionOperators(panels, Nl, dt, kRho, kG, {}, true);
      Print("TD-coef 14 dt .02 dw .05 to 12.05",
            Measure(FreeDecayFromCoefficients(TdInput(opsl, panels, m, C, 0.05, 12.05), Times(N, dt)), dt));
      Print("TD-coef 14 dt .02 dw .0125 to 12.05",
            Measure(FreeDecayFromCoefficients(TdInput(opsl, panels, m, C, 0.0125, 12.05), Times(N, dt)), dt));
      Print("TD-coef 14 dt .02 dw .05 to 30",
            Measure(FreeDecayFromCoefficients(TdInput(opsl, panels, m, C, 0.05, 30), Times(N, dt)), dt));
      const double wi_lo = std::sqrt(1.5 * kG), wi_hi = std::sqrt(2.05 * kG);
      Print("TD-coef 14 dt .02 band 1.5-2.05 removed",
            Measure(FreeDecayFromCoefficients(TdInput(opsl, panels, m, C, 0.05, 12.05, wi_lo, wi_hi),
                                              Times(N, dt)),
                    dt));
      // residual spectrum vs FD lid-on 14 panels
      const auto fdp = FreeDecayFromCoefficients(FdInput(panels, m, C, -1, 0.05, 12.05), Times(N, dt));
      for (double w = 1.0; w <= 8.0; w += 0.25) {
        std::complex<double> s = 0;
        int cnt = 0;
        for (int n = N / 2; n < N; ++n, ++cnt)
          s += (x[n] - fdp[n]) * std::exp(std::complex<double>(0, -w * n * dt));
        std::printf("  residual (TD march - FD lid) over 4..8 s at w %.2f (w^2/g %.2f): amp %.5f\n", w,
                    w * w / kG, 2 * std::abs(s) / cnt);
      }
    }
  }
}

TEST_CASE("free decay: irregular-frequency ringing of the 14-panel release", "[.][decay_ringing]") {
  const double R = 1.0, m = kRho * M_PI * R * R / 2, C = 2 * kRho * kG * R, dt = 0.02;
  const auto panels = PanelSymmetricSection(SemicircleContour(R), 14);
  const int N = 1500;
  const auto ops = BuildFixedSectionOperators(panels, N, dt, kRho, kG);
  const auto x = hullopt::testing::ReleaseHistory(ops, panels, m, C, N);
  const auto pred = FreeDecayFromCoefficients(TdInput(ops, panels, m, C, 0.05, 12.05), Times(N, dt));
  for (double t0 : {4.0, 8.0, 16.0, 24.0}) {
    double mx = 0, mr = 0;
    for (int n = t0 / dt; n < (t0 + 6) / dt && n < N; ++n)
      mx = std::max(mx, std::fabs(x[n])), mr = std::max(mr, std::fabs(x[n] - pred[n]));
    std::printf("t in [%g, %g]: max|x_march| %.5f  max|x_march - x_TDcoef| %.5f\n", t0, t0 + 6, mx, mr);
  }
  std::printf("residual march - TDcoef spectrum over 2..8 s and 16..30 s:\n");
  for (double w = 1.0; w <= 8.0; w += 0.25) {
    std::complex<double> s = 0, s2 = 0;
    int c = 0, c2 = 0;
    for (int n = 2 / dt; n < 8 / dt; ++n, ++c)
      s += (x[n] - pred[n]) * std::exp(std::complex<double>(0, -w * n * dt));
    for (int n = 16 / dt; n < N; ++n, ++c2) s2 += x[n] * std::exp(std::complex<double>(0, -w * n * dt));
    std::printf("  w %.2f (w^2R/g %.2f): %.5f  late march %.5f\n", w, w * w / kG, 2 * std::abs(s) / c,
                2 * std::abs(s2) / c2);
  }
  std::printf("TD coefficients near the irregular frequency (14 panels):\n");
  for (double k = 1.5; k <= 2.1; k += 0.02) {
    const double w = std::sqrt(k * kG);
    const auto I = SteadyHeaveMomentum(ops, w, N - 1);
    std::printf("  %.2f a33/m0 %.4f b33/(m0 w) %.4f\n", k, -I.real() / m, w * I.imag() / (m * w));
  }
  FrequencyDomainOptions fo;
  fo.rho_kg_m3 = kRho, fo.g_m_s2 = kG;
  for (int lid : {0, 4, 7, 14, 28, 56}) {
    fo.lid_panels = lid;
    std::printf("FD 14 body panels, lid %d:", lid);
    for (double k : {0.25, 0.8, 1.5}) {
      const auto h = SolveSectionFrequencyDomain({panels}, std::sqrt(k * kG), fo);
      std::printf("  k %.2f a %.4f b %.4f", k, h.a33() / m, h.b33() / (m * std::sqrt(k * kG)));
    }
    std::printf("\n");
  }
}

TEST_CASE("free decay: ringing amplitude against the panel count", "[.][decay_ringing_N]") {
  const double R = 1.0, m = kRho * M_PI * R * R / 2, C = 2 * kRho * kG * R, dt = 0.02;
  for (int np : {14, 28, 56}) {
    const auto panels = PanelSymmetricSection(SemicircleContour(R), np);
    const int N = 1000;
    const auto ops = BuildFixedSectionOperators(panels, N, dt, kRho, kG);
    const auto x = hullopt::testing::ReleaseHistory(ops, panels, m, C, N);
    double mx = 0;
    for (int n = 14 / dt; n < N; ++n) mx = std::max(mx, std::fabs(x[n]));
    std::complex<double> s = 0;
    double best = 0, wb = 0;
    for (double w = 3.5; w < 5.0; w += 0.01) {
      s = 0;
      int c = 0;
      for (int n = 12 / dt; n < N; ++n, ++c) s += x[n] * std::exp(std::complex<double>(0, -w * n * dt));
      if (2 * std::abs(s) / c > best) best = 2 * std::abs(s) / c, wb = w;
    }
    std::printf("%d panels: max|x|/x0 over 14-20 s %.5f, ringing at w %.2f (w^2R/g %.3f) amplitude %.5f\n",
                np, mx, wb, wb * wb / kG, best);
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<double> w;
  for (double ww = 0.1; ww < 6.0; ww += 0.05) w.push_back(ww);
  for (double ww = 6.0; ww <= 12.01; ww += 0.25) w.push_back(ww);
  const auto panels = PanelSymmetricSection(SemicircleContour(R), 56);
  FrequencyDomainOptions fo;
  fo.rho_kg_m3 = kRho, fo.g_m_s2 = kG;
  const auto fd = SolveSectionFrequencyDomain({panels}, w, fo);
  std::printf("FD 56 panels at %zu frequencies: %.2f s\n", w.size(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}
