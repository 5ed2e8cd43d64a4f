// Delft 372 catamaran at Fn 0.75: computed heave and pitch RAOs (both demihulls in the
// strips, transient Green-function kernel, Cs = 0.024 as in the paper) against the tank data of van 't Veer
// (1998). Acceptance: the peak heave RAO within 15% of the measured peak, at a λ/L within 10% of the measured
// one. Computed with the default strip layout (steps at the cell faces, exact transom momentum). Writes the
// comparison plot to the build folder (docs/delft372_rao_fn075.svg is a copy).
//
// The prediction sits near the edge of the 15%, so the check is made where the discretisation no longer moves
// it by more than the margin. Since the panels carry the curvature term of their self influence (second-order
// panel convergence, docs/sections.md) the peak hardly depends on the resolution: 2.160 (40 × 14), 2.162
// (80 × 28), 2.167 (80 × 56), i.e. −14.7%, −14.6%, −14.4%. (With first-order panels it converged from
// below: 40 sections 2.138, 2.154, 2.164, 2.168 at 14, 28, 56, 112 panels; 80 × 56 −14.6%, 80 × 28 −15.0%,
// 40 × 14 −15.5%.) Checked at 80 × 56; 80 × 28 and the paper's 40 × 14 are reported. Findings
// (docs/ship-motions.md): the 2D demihull interaction in the strips lowers the peak by 14% (one demihull
// alone: 2.50), wholly through the memory part of the coupling, which is verified against the
// frequency-domain pair (verification_td_twin_release); Cs is not the cause (Cs = 0 raises the peak by 0.21,
// to 2.374). The paper's written sectional force (pressure form, reported below) gives −9.9% (−11.7% with first-order
// panels) but loses the pitch resonance; the default is not switched (docs/ship-motions.md). Nothing was tuned toward the tank.
#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>

#include "io/report/rao_plot.h"
#include "io/formats/tank_rao_reader.h"
#include "optimizer/rao_peak.h"
#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/rao_solver.h"
#include "support/delft372_hull.h"
#include "support/delft372_tank.h"

namespace sk = hullopt::sk;

TEST_CASE("Delft 372 Fn 0.75: peak heave against the tank", "[validation][delft372]") {
  constexpr double kG = 9.81, kRho = 1000.0, kL = 3.0;
  const double U = 0.75 * std::sqrt(kG * kL);
  const auto tank = hullopt::testing::Delft372TankRao(HULLOPT_SOURCE_DIR);
  const hullopt::io::MeasuredRao m = hullopt::testing::MeasuredFromTank(tank);
  const auto w = sk::WaveFrequencies(
      sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kLambdaOverL, 0.8, 3.0, 89), U, kG, kL);
  auto compute = [&](int sections, int panels, sk::StationLayout layout = sk::kDefaultStationLayout,
                     sk::SectionalForce force = sk::SectionalForce::kMomentum) {
    sk::RaoSolverOptions o;
    o.sections = sections;
    o.panels = panels;
    o.layout = layout;
    o.motion.damping_cs = 0.024;
    o.motion.hull_name = "delft372";
    return sk::ComputeRaos(hullopt::testing::Delft372Hull(HULLOPT_SOURCE_DIR), hullopt::testing::Delft372Mass(),
                           U, kRho, kG, w, o, sk::TransientGreenKernelBuilder(force));
  };
  // Checked at 80 × 56, the finest resolution measured (2.167; 80 × 28 2.162, 40 × 14 2.160). 80 × 28 and the
  // paper's 40 × 14 are reported.
  const auto rao = compute(80, 56);
  const auto rao_28 = compute(80, 28);
  const auto rao_paper = compute(40, 14);
  const auto rao_mid = compute(80, 28, hullopt::sk::StationLayout::kCellMidpoints);
  std::vector<double> lam, h, h_28, h_paper, h_mid;
  for (std::size_t i = 0; i < w.size(); ++i) {
    lam.push_back(2 * M_PI * kG / (w[i] * w[i]) / kL);
    h.push_back(std::abs(rao.heave[i]));
    h_28.push_back(std::abs(rao_28.heave[i]));
    h_paper.push_back(std::abs(rao_paper.heave[i]));
    h_mid.push_back(std::abs(rao_mid.heave[i]));
  }
  const auto computed_paper = hullopt::opt::InterpolatedPeak(lam, h_paper);
  const auto computed_mid = hullopt::opt::InterpolatedPeak(lam, h_mid);
  const auto computed = hullopt::opt::InterpolatedPeak(lam, h);
  const auto computed_28 = hullopt::opt::InterpolatedPeak(lam, h_28);
  const auto measured = hullopt::opt::InterpolatedPeak(m.lambda_over_L, m.heave_amp);
  hullopt::io::WriteSvg(
      hullopt::io::RaoFigure({rao, rao_paper}, {"time-domain strip, 80 × 56", "time-domain strip, 40 × 14"}, kL,
                             "Delft 372, Fn 0.75, both demihulls, Cs 0.024", &m),
      std::string(HULLOPT_BINARY_DIR) + "/delft372_rao_fn075.svg");
  std::cout << "Delft 372 Fn 0.75: computed peak heave " << computed.value << " at lambda/L " << computed.x
            << " (80 x 56; 80 x 28: " << computed_28.value << " at " << computed_28.x << "; 40 x 14: "
            << computed_paper.value << " at " << computed_paper.x << "); measured " << measured.value << " at "
            << measured.x << " -> " << 100 * (computed.value / measured.value - 1) << "% (80 x 28: "
            << 100 * (computed_28.value / measured.value - 1)
            << "%, 40 x 14: " << 100 * (computed_paper.value / measured.value - 1)
            << "%); midpoint layout 80 x 28 (reported): " << computed_mid.value << " at " << computed_mid.x
            << " -> " << 100 * (computed_mid.value / measured.value - 1) << "%\n";
  // Reported, not checked: the reference paper's written sectional force (fixed-point pressure integral,
  // strip_operators.h) at the paper's 40 × 14, and the mean |computed − measured| of heave and pitch over the
  // tank points for both forms (docs/ship-motions.md, "Sectional force form").
  const auto rao_pressure = compute(40, 14, sk::kDefaultStationLayout, sk::SectionalForce::kPressure);
  std::vector<double> h_pressure;
  for (const auto& r : rao_pressure.heave) h_pressure.push_back(std::abs(r));
  const auto computed_pressure = hullopt::opt::InterpolatedPeak(lam, h_pressure);
  auto mean_error = [&](const sk::RaoTable& r, bool pitch) {
    double sum = 0;
    for (const auto& p : tank) {
      std::size_t i = 0;  // lam falls with i: bracket p.lambda_over_L
      while (i + 2 < lam.size() && lam[i + 1] > p.lambda_over_L) ++i;
      const double t = (p.lambda_over_L - lam[i]) / (lam[i + 1] - lam[i]);
      const double a = std::abs(pitch ? r.pitch[i] : r.heave[i]), b = std::abs(pitch ? r.pitch[i + 1] : r.heave[i + 1]);
      sum += std::fabs(a + t * (b - a) - (pitch ? p.pitch_amp : p.heave_amp));
    }
    return sum / tank.size();
  };
  std::cout << "Delft 372 Fn 0.75, 40 x 14, sectional force in the paper's pressure form (reported): peak heave "
            << computed_pressure.value << " at lambda/L " << computed_pressure.x << " -> "
            << 100 * (computed_pressure.value / measured.value - 1) << "%; mean |error| over the " << tank.size()
            << " tank points, heave / pitch: momentum form " << mean_error(rao_paper, false) << " / "
            << mean_error(rao_paper, true) << ", pressure form " << mean_error(rao_pressure, false) << " / "
            << mean_error(rao_pressure, true) << "\n";
  constexpr double kPeakTol = 0.15, kLambdaTol = 0.10;  // the acceptance above
  CHECK(std::fabs(computed.x - measured.x) < kLambdaTol * measured.x);
  CHECK(std::fabs(computed.value - measured.value) < kPeakTol * measured.value);
  // Away from the peak the curve must follow the data: at λ/L = 1.0 (short waves) the computed heave is
  // within 0.15 (absolute, 6% of the measured peak) of the measured one. Whole-curve sanity, not the
  // acceptance.
  for (double l : {1.0}) {
    std::size_t i = 0;
    while (i + 1 < lam.size() && std::fabs(lam[i + 1] - l) < std::fabs(lam[i] - l)) ++i;
    double meas = 0, best = 1e9;
    for (const auto& p : tank)
      if (std::fabs(p.lambda_over_L - l) < best) best = std::fabs(p.lambda_over_L - l), meas = p.heave_amp;
    INFO("lambda/L = " << l << " computed " << h[i] << " measured " << meas);
    CHECK(std::fabs(h[i] - meas) < 0.15);
  }
}
