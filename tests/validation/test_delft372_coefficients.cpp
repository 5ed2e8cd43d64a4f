// Delft 372: the links of the RAO chain against the measured ones (van 't Veer 1998, data/delft372): forced
// heave and pitch coefficients and restrained-model wave loads at Fn 0.30, 0.45, 0.60, 0.75 (zero trim and
// sinkage), for the time-domain strip method (default 40 × 14, cell faces, Cs 0.024, both demihulls) and for
// strip theory (`strip_theory_stf`). Prints per speed and coefficient the mean error, the error of B33 and |F3|
// at the heave resonance (at Fn 0.75 also at the running attitude, hull and measurement), and at Fn 0.75 the
// decomposition: each measured link substituted alone into the
// computed equations of motion and where it moves the heave peak. Writes the comparison plots to the build
// folder (docs/figures/coefficients_delft372_*.svg are copies). Tables and findings: docs/coefficients.md.
//
// Checks (each can fail against the measurement, none is tuned): the measured links at the running attitude,
// all substituted, reproduce the tank's heave peak through the equations of motion (so the signs and phase
// reference read into them are right); the decomposition's bookkeeping (nothing substituted = the RAO solve);
// every link has measured points at every speed. The comparison itself is reported, not bounded.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include "io/report/coefficients_plot.h"
#include "io/formats/measured_coefficients_csv.h"
#include "optimizer/rao_peak.h"
#include "parametric_hull/running_attitude.h"
#include "seakeeping/motions/encounter_frequency.h"
#include "seakeeping/motions/rao_solver.h"
#include "support/delft372_hull.h"

namespace sk = hullopt::sk;
namespace io = hullopt::io;
using cd = std::complex<double>;

namespace {
constexpr double kG = 9.81, kRho = 1000.0, kL = 3.0;
const double kNondim = std::sqrt(kL / kG);  // ω √(L/g) = ω · kNondim

// Piecewise-linear interpolation of measured points (sorted here); NaN outside their range.
struct Curve {
  std::vector<double> x, y;
  Curve(std::vector<double> xs, std::vector<double> ys) {
    std::vector<std::size_t> idx(xs.size());
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
    std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return xs[a] < xs[b]; });
    for (auto i : idx) {
      x.push_back(xs[i]);
      y.push_back(ys[i]);
    }
  }
  double At(double v) const {
    if (x.empty() || v < x.front() || v > x.back()) return NAN;
    for (std::size_t i = 1; i < x.size(); ++i)
      if (v <= x[i]) {
        const double t = x[i] == x[i - 1] ? 0.0 : (v - x[i - 1]) / (x[i] - x[i - 1]);
        return y[i - 1] + t * (y[i] - y[i - 1]);
      }
    return y.back();
  }
};

// Phase-aware interpolation of a complex measured load (amplitude and unwrapped phase).
struct ComplexCurve {
  Curve amp, phase;
  ComplexCurve(const std::vector<double>& x, const std::vector<double>& a, std::vector<double> p_deg)
      : amp(x, a), phase(x, Unwrap(x, p_deg)) {}
  static std::vector<double> Unwrap(const std::vector<double>& x, std::vector<double> p) {
    std::vector<std::size_t> idx(x.size());
    for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
    std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return x[a] < x[b]; });
    for (std::size_t k = 1; k < idx.size(); ++k) {
      while (p[idx[k]] - p[idx[k - 1]] > 180) p[idx[k]] -= 360;
      while (p[idx[k]] - p[idx[k - 1]] < -180) p[idx[k]] += 360;
    }
    return p;
  }
  cd At(double v) const { return std::polar(amp.At(v), phase.At(v) * M_PI / 180); }
};

double WaveFromEncounter(double we, double U) { return (-1 + std::sqrt(1 + 4 * U * we / kG)) * kG / (2 * U); }

// Linear interpolation of a computed coefficient at ω_e √(L/g) = v.
template <class F>
double ComputedAt(const sk::CoefficientTable& t, double v, F get) {
  for (std::size_t i = 1; i < t.rows.size(); ++i) {
    const double x0 = t.rows[i - 1].omega_e_rad_s * kNondim, x1 = t.rows[i].omega_e_rad_s * kNondim;
    if (v >= x0 && v <= x1) return get(t.rows[i - 1]) + (v - x0) / (x1 - x0) * (get(t.rows[i]) - get(t.rows[i - 1]));
  }
  return NAN;
}

struct Measured {
  std::vector<io::MeasuredCoefficientRow> heave, pitch;
  std::vector<io::MeasuredWaveLoadRow> loads;
};
Measured ReadMeasured() {
  const std::string d = std::string(HULLOPT_SOURCE_DIR) + "/data/delft372/";
  return {io::ReadForcedOscillationCsv(d + "delft372_forced_heave_coefficients.csv", 3),
          io::ReadForcedOscillationCsv(d + "delft372_forced_pitch_coefficients.csv", 5),
          io::ReadRestrainedWaveLoadCsv(d + "delft372_restrained_wave_loads.csv")};
}

// The model's calm-water running attitude at Fn 0.748 (data/delft372/delft372_running_attitude.csv: sinkage
// 2.57 mm up at the CG, trim 1.35 deg bow up), the condition of the forced tests labelled Fn0.75_trim_sinkage.
hullopt::hull::RunningAttitude Fn075Attitude() {
  hullopt::hull::RunningAttitude a;
  a.sinkage_m = -0.00257;
  a.trim_deg = 1.35;
  a.pivot_x_m = hullopt::testing::Delft372Mass().lcg_m_from_ap;
  return a;
}

sk::CoefficientTable Compute(sk::RaoSolverOptions::Method m, double U, const std::vector<double>& omega,
                             bool running_attitude = false) {
  auto hull = hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR);
  if (running_attitude) hull = hullopt::hull::ApplyRunningAttitude(hull, Fn075Attitude());
  return sk::ComputeCoefficients(hull, hullopt::testing::Delft372Mass(), U, kRho, kG, omega,
                                 hullopt::testing::Delft372SolverOptions(m), sk::TransientGreenKernelBuilder());
}

// Encounter frequencies ω_e √(L/g) = 2.5 … 9.2 (the measured range), count points (strip theory solves every
// section at every frequency, so it gets fewer).
std::vector<double> SweepOmega(double U, int count) {
  std::vector<double> w;
  for (int i = 0; i < count; ++i) w.push_back(WaveFromEncounter((2.5 + 6.7 * i / (count - 1)) / kNondim, U));
  return w;
}
}  // namespace

namespace {
// The measured heave resonance: ω with C33 = ω² (M + A33(ω)), A33 measured (interpolated), C33 and M of the
// report (10782 N/m, 87.07 kg in the motion tests). Fixed point from the middle of the measured range.
double MeasuredHeaveResonance(const io::MeasuredCoefficientPoints& m) {
  const Curve a33(m.heave_x, m.A33);
  double v = 0.5 * (a33.x.front() + a33.x.back());
  for (int it = 0; it < 50; ++it) {
    const double a = a33.At(std::clamp(v, a33.x.front(), a33.x.back()));
    v = std::sqrt(10782.0 / (87.07 + a)) * kNondim;
  }
  return v;
}

struct Stat {
  double bias_pct = 0, rms_pct = 0;
  int n = 0;
};
// bias: mean of (computed − measured) over the points, rms: root mean square of the same; both in % of the
// rms of the measured values (a scale that does not blow up where a coupling crosses zero).
Stat Compare(const std::vector<double>& x, const std::vector<double>& meas, const std::function<double(double)>& comp) {
  Stat s;
  double scale = 0, bias = 0, rms = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double c = comp(x[i]);
    if (!std::isfinite(c)) continue;
    scale += meas[i] * meas[i];
    bias += c - meas[i];
    rms += (c - meas[i]) * (c - meas[i]);
    ++s.n;
  }
  if (s.n == 0) return s;
  scale = std::sqrt(scale / s.n);
  s.bias_pct = 100 * bias / s.n / scale;
  s.rms_pct = 100 * std::sqrt(rms / s.n) / scale;
  return s;
}
}  // namespace

TEST_CASE("Delft 372 coefficients and wave loads against the forced and restrained tests",
          "[validation][delft372][coefficients]") {
  const Measured meas = ReadMeasured();
  for (auto method : {sk::RaoSolverOptions::Method::kTimeDomainStrip, sk::RaoSolverOptions::Method::kStripTheory}) {
    const bool stf = method == sk::RaoSolverOptions::Method::kStripTheory;
    std::printf("\n%s: bias / rms of computed - measured in %% of the rms measured value (n points)\n",
                stf ? "strip theory (STF)" : "time-domain strip, 40 x 14, Cs 0.024");
    std::printf("| Fn | A33 | B33 | A55 | B55 | A35 | A53 | B35 | B53 | abs F3 | abs F5 | w_n sqrt(L/g) | B33 at w_n | abs F3 at w_n |\n");
    for (double Fn : {0.30, 0.45, 0.60, 0.75}) {
      const double U = Fn * std::sqrt(kG * kL);
      const auto t0 = Compute(method, U, SweepOmega(U, stf ? 24 : 61));
      const auto m_zero = io::MeasuredPointsForSpeed(meas.heave, meas.pitch, meas.loads, Fn, "zero", U, kG, kL);
      for (const std::string trim : {"zero", "Fn0.75_trim_sinkage"}) {
        if (trim != "zero" && Fn != 0.75) continue;
        const auto m = io::MeasuredPointsForSpeed(meas.heave, meas.pitch, meas.loads, Fn, trim, U, kG, kL);
        // The running-attitude rows against the hull computed at that attitude.
        const sk::CoefficientTable t = trim == "zero" ? t0 : Compute(method, U, SweepOmega(U, stf ? 24 : 61), true);
        auto A = [&](int i, int j) { return [&, i, j](double v) { return ComputedAt(t, v, [=](const sk::HeadSeaCoefficients& c) { return c.A(i, j); }); }; };
        auto B = [&](int i, int j) { return [&, i, j](double v) { return ComputedAt(t, v, [=](const sk::HeadSeaCoefficients& c) { return c.B(i, j); }); }; };
        auto F = [&](int i) { return [&, i](double v) { return ComputedAt(t, v, [=](const sk::HeadSeaCoefficients& c) { return std::abs(c.Exciting(i)); }); }; };
        const Stat s[10] = {Compare(m.heave_x, m.A33, A(0, 0)), Compare(m.heave_x, m.B33, B(0, 0)),
                            Compare(m.pitch_x, m.A55, A(1, 1)), Compare(m.pitch_x, m.B55, B(1, 1)),
                            Compare(m.pitch_x, m.A35, A(0, 1)), Compare(m.heave_x, m.A53, A(1, 0)),
                            Compare(m.pitch_x, m.B35, B(0, 1)), Compare(m.heave_x, m.B53, B(1, 0)),
                            Compare(m.load_x, m.F3_amp, F(0)),  Compare(m.load_x, m.F5_amp, F(1))};
        const double wn = MeasuredHeaveResonance(m);
        const double b33m = Curve(m.heave_x, m.B33).At(wn), f3m = m.load_x.empty() ? NAN : Curve(m.load_x, m.F3_amp).At(wn);
        const double b33c = B(0, 0)(wn), f3c = F(0)(wn);
        // The A55 gap as an in-phase stiffness: (A55 measured − computed) ω_e² [N m/rad] at each pitch point.
        // Roughly constant over frequency where a frequency-independent moment is missing from one side.
        std::vector<double> stiff;
        for (std::size_t k = 0; k < m.pitch_x.size(); ++k) {
          const double c = A(1, 1)(m.pitch_x[k]), w = m.pitch_x[k] / kNondim;
          if (std::isfinite(c)) stiff.push_back((m.A55[k] - c) * w * w);
        }
        std::sort(stiff.begin(), stiff.end());
        if (!stiff.empty())
          std::printf("A55 gap x omega_e^2, Fn %.2f %s: %.0f to %.0f N m/rad (median %.0f, %zu points; C55 %.0f)\n", Fn,
                      trim.c_str(), stiff.front(), stiff.back(), stiff[stiff.size() / 2], stiff.size(),
                      t.rows[0].restoring[1][1]);
        std::printf("| %.2f%s |", Fn, trim == "zero" ? "" : " (running attitude, computed at it)");
        for (const auto& x : s) std::printf(" %+.0f / %.0f (%d) |", x.bias_pct, x.rms_pct, x.n);
        std::printf(" %.2f | %.0f vs %.0f (%+.1f%%) | %.0f vs %.0f (%+.1f%%) |\n", wn, b33c, b33m,
                    100 * (b33c / b33m - 1), f3c, f3m, 100 * (f3c / f3m - 1));
        for (int i = 0; i < (trim == "zero" ? 10 : 8); ++i) CHECK(s[i].n > 0);  // measured points for every link
        if (trim != "zero") {
          char name[128];
          std::snprintf(name, sizeof name, "%s/coefficients_delft372_fn075_attitude_%s.svg", HULLOPT_BINARY_DIR,
                        stf ? "stf" : "td");
          auto ma = m;
          io::WriteSvg(io::CoefficientsFigure({t}, {stf ? "strip theory (STF)" : "time-domain strip 40 x 14"}, kL,
                                              "Delft 372, Fn 0.75, running trim and sinkage, Cs 0.024", &ma),
                       name);
        }
      }
      char name[128];
      std::snprintf(name, sizeof name, "%s/coefficients_delft372_fn%03d_%s.svg", HULLOPT_BINARY_DIR,
                    static_cast<int>(std::lround(Fn * 100)), stf ? "stf" : "td");
      auto mm = m_zero;
      io::WriteSvg(io::CoefficientsFigure({t0}, {stf ? "strip theory (STF)" : "time-domain strip 40 x 14"}, kL,
                                          "Delft 372, Fn " + std::to_string(Fn).substr(0, 4) +
                                              ", zero trim and sinkage, Cs 0.024",
                                          &mm),
                   name);
    }
  }
}

TEST_CASE("Delft 372 Fn 0.75: which measured link moves the heave peak", "[validation][delft372][coefficients]") {
  const Measured meas = ReadMeasured();
  const double Fn = 0.75, U = Fn * std::sqrt(kG * kL);
  const auto m = io::MeasuredPointsForSpeed(meas.heave, meas.pitch, meas.loads, Fn, "zero", U, kG, kL);
  // λ/L 1.00–1.98 (inside every measured range: forced tests to λ/L 2.02, wave loads to 1.986).
  std::vector<double> omega, lam;
  for (int i = 0; i <= 49; ++i) {
    lam.push_back(1.98 - 0.02 * i);
    omega.push_back(std::sqrt(kG * 2 * M_PI / (lam.back() * kL)));
  }
  std::reverse(omega.begin(), omega.end());
  std::reverse(lam.begin(), lam.end());
  // The running attitude's forced-oscillation points (the free-running RAO tests ran at it); wave loads were
  // measured at zero attitude only.
  const auto ma = io::MeasuredPointsForSpeed(meas.heave, meas.pitch, {}, Fn, "Fn0.75_trim_sinkage", U, kG, kL);
  struct Links {
    Curve A33, B33, A53, B53, A55, B55, A35, B35;
    explicit Links(const io::MeasuredCoefficientPoints& p)
        : A33(p.heave_x, p.A33), B33(p.heave_x, p.B33), A53(p.heave_x, p.A53), B53(p.heave_x, p.B53),
          A55(p.pitch_x, p.A55), B55(p.pitch_x, p.B55), A35(p.pitch_x, p.A35), B35(p.pitch_x, p.B35) {}
  };
  const Links zero(m), attitude(ma);
  const ComplexCurve F3(m.load_x, m.F3_amp, m.F3_phase_deg), F5(m.load_x, m.F5_amp, m.F5_phase_deg);
  enum Link { kA33 = 1, kB33 = 2, kA55 = 4, kB55 = 8, kCouple = 16, kF3 = 32, kF5 = 64, kF3amp = 128, kF5amp = 256 };
  auto Substitute = [&](sk::HeadSeaCoefficients c, int links, const Links& q) {
    const double v = c.omega_e_rad_s * kNondim, w = c.motion_omega_rad_s;
    auto set = [&](int i, int j, double a, double b) { c.moving[i][j] = cd(w * w * a, -w * b); };
    if (links & kA33) set(0, 0, q.A33.At(v), c.B(0, 0));
    if (links & kB33) set(0, 0, c.A(0, 0), q.B33.At(v));
    if (links & kA55) set(1, 1, q.A55.At(v), c.B(1, 1));
    if (links & kB55) set(1, 1, c.A(1, 1), q.B55.At(v));
    if (links & kCouple) {
      set(0, 1, q.A35.At(v), q.B35.At(v));
      set(1, 0, q.A53.At(v), q.B53.At(v));
    }
    for (int i = 0; i < 2; ++i) {
      const int full = i == 0 ? kF3 : kF5, amp = i == 0 ? kF3amp : kF5amp;
      cd f = c.Exciting(i);
      if (links & full) f = (i == 0 ? F3 : F5).At(v);
      if (links & amp) f *= (i == 0 ? F3 : F5).amp.At(v) / std::abs(f);
      c.froude_krylov[i] = f;
      c.diffraction[i] = c.damping_wave[i] = 0.0;
    }
    return c;
  };
  const int kAll = kA33 | kB33 | kA55 | kB55 | kCouple | kF3 | kF5;
  // One table row per case: the heave and pitch peaks over λ/L >= lam_min with the case's links substituted
  // from q. With raos, the unsubstituted system is checked against the RAO solve (bookkeeping).
  auto PrintPeaks = [&](const sk::CoefficientTable& t, const std::vector<std::pair<std::string, int>>& cases,
                        const Links& q, double lam_min, const sk::RaoTable* raos) {
    double base = 0;
    for (const auto& [label, links] : cases) {
      std::vector<double> h, p, l;
      for (std::size_t f = 0; f < omega.size(); ++f) {
        if (lam[f] < lam_min) continue;
        const auto x = Substitute(t.rows[f], links, q).Solve();
        if (links == 0 && raos) CHECK(std::abs(x[0] - raos->heave[f]) <= 1e-9 * std::abs(raos->heave[f]));
        h.push_back(std::abs(x[0]));
        p.push_back(std::abs(x[1]));
        l.push_back(lam[f]);
      }
      const auto hp = hullopt::opt::InterpolatedPeak(l, h), pp = hullopt::opt::InterpolatedPeak(l, p);
      if (links == 0) base = hp.value;
      std::printf("| %s | %.3f | %.2f%s | %+.3f | %.3f | %.2f%s |\n", label.c_str(), hp.value, hp.x,
                  hp.at_edge ? " (edge)" : "", hp.value - base, pp.value, pp.x, pp.at_edge ? " (edge)" : "");
    }
  };
  {
    // Consistency of the measured links with the measured RAO, and so of the conventions read into them
    // (coupling signs, phase reference): all measured links at the running attitude with the motion tests'
    // mass (87.07 kg, k_yy 0.782 m) and the strip restoring give the tank's heave peak. λ/L 1.30–1.98: the
    // attitude's pitch tests reach ω_e √(L/g) 6.14 only.
    constexpr double kPeakTol = 0.10, kLambdaTol = 0.05;  // interpolation between 5–7 measured points
    const auto t = Compute(sk::RaoSolverOptions::Method::kTimeDomainStrip, U, omega);
    std::vector<double> h, l;
    for (std::size_t f = 0; f < omega.size(); ++f)
      if (lam[f] >= 1.3) {
        h.push_back(std::abs(Substitute(t.rows[f], kAll, attitude).Solve()[0]));
        l.push_back(lam[f]);
      }
    const auto hp = hullopt::opt::InterpolatedPeak(l, h);
    std::printf("\nall measured links (running attitude coefficients, zero-attitude loads): heave peak %.3f at "
                "lambda/L %.2f (tank 2.53 at 1.80)\n", hp.value, hp.x);
    CHECK(std::abs(hp.value / 2.53 - 1) <= kPeakTol);
    CHECK(std::abs(hp.x / 1.80 - 1) <= kLambdaTol);
  }
  for (auto method : {sk::RaoSolverOptions::Method::kTimeDomainStrip, sk::RaoSolverOptions::Method::kStripTheory}) {
    const bool stf = method == sk::RaoSolverOptions::Method::kStripTheory;
    const auto t = Compute(method, U, omega);
    // Bookkeeping against the RAO solve for the time-domain method (strip theory's is the verification test's).
    const auto raos = stf ? sk::RaoTable{}
                          : sk::ComputeRaos(hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR),
                                            hullopt::testing::Delft372Mass(), U, kRho, kG, omega, hullopt::testing::Delft372SolverOptions(method),
                                            sk::TransientGreenKernelBuilder());
    std::printf("\n%s, Fn 0.75: heave peak with one measured link substituted (tank 2.53 at lambda/L 1.80)\n",
                stf ? "strip theory (STF)" : "time-domain strip, 40 x 14, Cs 0.024");
    std::printf("| substituted | heave peak | at lambda/L | change | pitch peak | at lambda/L |\n");
    const std::vector<std::pair<std::string, int>> cases = {
        {"none (computed)", 0}, {"A33", kA33}, {"B33", kB33}, {"A55", kA55}, {"B55", kB55},
        {"A35, A53, B35, B53", kCouple}, {"F3 (amplitude and phase)", kF3}, {"F5 (amplitude and phase)", kF5},
        {"|F3| only", kF3amp}, {"|F5| only", kF5amp}, {"A33 + B33", kA33 | kB33},
        {"all coefficients", kA33 | kB33 | kA55 | kB55 | kCouple},
        {"all coefficients and loads", kAll}};
    PrintPeaks(t, cases, zero, 0.0, stf ? nullptr : &raos);
  }
  {
    // The condition of the RAO tests: the hull computed at the running attitude, the running-attitude forced
    // points substituted (λ/L 1.30–1.98, where the attitude's pitch tests reach), the loads computed.
    const auto t = Compute(sk::RaoSolverOptions::Method::kTimeDomainStrip, U, omega, true);
    std::printf("\ntime-domain strip at the running attitude, Fn 0.75: running-attitude links substituted (lambda/L "
                ">= 1.3)\n| substituted | heave peak | at lambda/L | change | pitch peak | at lambda/L |\n");
    const std::vector<std::pair<std::string, int>> cases = {
        {"none (computed at the attitude)", 0}, {"A33", kA33}, {"B33", kB33}, {"A55", kA55}, {"B55", kB55},
        {"A35, A53, B35, B53", kCouple}, {"B33 + couplings", kB33 | kCouple},
        {"B33 + B55 + couplings", kB33 | kB55 | kCouple}, {"all coefficients", kA33 | kB33 | kA55 | kB55 | kCouple},
        {"all coefficients and the (zero-attitude) loads", kAll}};
    PrintPeaks(t, cases, attitude, 1.3, nullptr);
  }
}
