// The mirror-symmetric reduction of the strip kernel (StripOperatorOptions::use_mirror_symmetry) against the
// full solve of the same strips: the vertical force must be the same for ANY normal-velocity input, because
// the antisymmetric part of an input produces no vertical force. The full solve is the independent second
// method here (it never combines mirror columns).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/strip_kernel_builder.h"
#include "seakeeping/strip/strip_operators.h"

using namespace hullopt::sk;

namespace {
constexpr double kG = 9.81;
constexpr double kRho = 1025.0;
// Round-off only: the reduced solve adds mirror columns before the LU instead of after, so the two differ by
// the conditioning of the (well-conditioned, diagonally dominant) systems times machine epsilon.
constexpr double kTolMirror = 1e-9;

std::vector<Panel> Mirrored(const std::vector<Panel>& body, double y_centre_offset) {
  // `body` panelled about y = 0; return it shifted to +offset and its mirror image at −offset (reversed).
  std::vector<Panel> out;
  for (const Panel& p : body) out.push_back({p.y1 + y_centre_offset, p.z1, p.y2 + y_centre_offset, p.z2});
  for (auto it = body.rbegin(); it != body.rend(); ++it)
    out.push_back({-(it->y2 + y_centre_offset), it->z2, -(it->y1 + y_centre_offset), it->z1});
  return out;
}

// Strips of a hull passing by: sections whose size changes with the step.
std::vector<std::vector<Panel>> Strips(int steps, int kind) {
  std::vector<std::vector<Panel>> out;
  for (int n = 0; n < steps; ++n) {
    const double r = 0.3 + 0.5 * std::sin(M_PI * (n + 1) / (steps + 1));
    const auto section = PanelSymmetricSection(LewisContour(2 * r, 0.8 * r, 0.75, 80), 8);
    switch (kind) {
      case 0:  // monohull on y = 0
        out.push_back(section);
        break;
      case 1:  // catamaran: demihulls at ±1.2 m
        out.push_back(Mirrored(section, 1.2));
        break;
      case 2: {  // one demihull alone, centred at y = 0.7 (symmetric about its own centreline)
        std::vector<Panel> s;
        for (const Panel& p : section) s.push_back({p.y1 + 0.7, p.z1, p.y2 + 0.7, p.z2});
        out.push_back(s);
        break;
      }
      default: {  // not symmetric: one demihull and a smaller one beside it
        auto s = Mirrored(section, 1.2);
        s.resize(section.size());
        const auto q = PanelSymmetricSection(SemicircleContour(0.2, 60), 4, -1.0);
        s.insert(s.end(), q.begin(), q.end());
        out.push_back(s);
      }
    }
  }
  return out;
}
}  // namespace

TEST_CASE("mirror-reduced strip kernel gives the full solve's vertical force for any input",
          "[td][kernel][verification]") {
  const int N = 6;
  const double dt = 0.05;
  std::vector<double> x(N);
  for (int n = 0; n < N; ++n) x[n] = 5.0 - 0.5 * n;
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  for (int case_index = 0; case_index < 8; ++case_index) {
    // Both ways of taking the current sources' potential: the reduction must hold for each.
    const int kind = case_index % 4;
    const auto potential = case_index < 4 ? BodyPotential::kSourceSum : BodyPotential::kGreenIdentity;
    INFO("strip kind " << kind << ", Green's identity " << (potential == BodyPotential::kGreenIdentity));
    const auto panels = Strips(N, kind);
    StripOperatorOptions full_options, mirror_options;
    full_options.body_potential = mirror_options.body_potential = potential;
    mirror_options.use_mirror_symmetry = true;
    const auto reduced_ops = BuildStripOperators(panels, dt, kRho, kG, mirror_options);
    CHECK(reduced_ops.MirrorReduced() == (kind != 3));
    if (kind != 3) CHECK(reduced_ops.PanelCount(N - 1) * 2 == static_cast<int>(panels[N - 1].size()));
    const StripKernel full = BuildStripKernel(BuildStripOperators(panels, dt, kRho, kG, full_options), x);
    const StripKernel reduced = BuildStripKernel(reduced_ops, x);
    REQUIRE(reduced.panels.size() == full.panels.size());
    for (int n = 0; n < N; ++n) REQUIRE(reduced.panels[n].size() == full.panels[n].size());
    for (int trial = 0; trial < 3; ++trial) {
      // Random input with no symmetry at all.
      for (int n = 0; n < N; ++n) {
        double f_full = 0, f_reduced = 0, scale = 0;
        for (int m = 0; m <= n; ++m) {
          const Eigen::VectorXd V = Eigen::VectorXd::NullaryExpr(panels[m].size(), [&] { return normal(rng); });
          f_full += full.force[n][m].dot(V);
          f_reduced += reduced.force[n][m].dot(V);
          scale += full.force[n][m].cwiseAbs().sum();
        }
        CHECK(std::fabs(f_reduced - f_full) <= kTolMirror * scale);
      }
    }
  }
}
