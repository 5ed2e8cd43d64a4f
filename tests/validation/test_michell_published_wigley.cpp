// Michell's wave resistance of the standard Wigley hull (B/L = 0.1, T/L = 0.0625) against the published
// thin-ship value of Doctors & Beck (1987, Table 1; data/doctors-beck-1987/SOURCE.md): hullopt's Michell
// integral on the hull's stations at the campaign resolution (41 stations, default options) and at a fine
// resolution, C_W on hullopt's own wetted surface.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "resistance/calm_water_resistance.h"
#include "support/data_table.h"
#include "support/wigley_hull.h"

using namespace hullopt;

namespace {
constexpr double L = 1.0, B = 0.1, T = 0.0625, g = 9.81, rho = 1000.0;

struct Published {
  double Fn, C_W;
};

std::vector<Published> ReadPublished() {
  std::vector<Published> out;
  for (const auto& r : test::ReadDataTable("doctors-beck-1987/wigley_thin_ship_cw.csv")) {
    REQUIRE(r.size() == 2);
    out.push_back({r[0], 1e-3 * r[1]});
  }
  return out;
}
}  // namespace

TEST_CASE("Wigley hull: Michell C_W against the published thin-ship value (Doctors & Beck 1987)", "[validation]") {
  // Tolerance 0.5 %, from the error budget, not from the comparison: the source prints 5 digits (0.004 %);
  // the 41-station hull's C_W is within 0.17 % of the analytic-amplitude quadrature (verification_michell_wigley);
  // the wetted-surface convention may differ by up to 0.3 % (hullopt's ruled surface includes the longitudinal
  // slope, +0.3 % over the girth integral on this hull).
  constexpr double kTol = 0.005;
  const auto pts = ReadPublished();
  REQUIRE(pts.size() == 1);
  res::ResistanceOptions coarse;  // the campaign's defaults
  res::ResistanceOptions fine;
  fine.michell.depth_points = 48;
  fine.michell.intervals_per_wave = 4.0;
  fine.michell.lambda_max = 80.0;
  const res::CalmWaterResistance m41(test::WigleyHull(L, B, T, 41, 41), coarse);
  const res::CalmWaterResistance m81(test::WigleyHull(L, B, T, 81, 41), fine);
  std::printf("Wigley B/L 0.1, T/L 0.0625   Fn   C_W x1e3 published   hullopt 41 st.   hullopt 81 st.\n");
  for (const Published& p : pts) {
    const double U = p.Fn * std::sqrt(g * L);
    const double c41 = m41.At(U, rho, g).C_W, c81 = m81.At(U, rho, g).C_W;
    std::printf("                              %.2f  %.4f               %.4f (%+.2f %%)   %.4f (%+.2f %%)\n", p.Fn,
                1e3 * p.C_W, 1e3 * c41, 100.0 * (c41 / p.C_W - 1.0), 1e3 * c81, 100.0 * (c81 / p.C_W - 1.0));
    CHECK(c41 / p.C_W == Approx(1.0).margin(kTol));
    CHECK(c81 / p.C_W == Approx(1.0).margin(kTol));
  }
}
