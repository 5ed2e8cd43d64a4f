// Delft 372 catamaran offsets (van 't Veer 1998, data/delft372/) read at T = 0.15 m in fresh water against
// the report's particulars: displacement 87.07 kg, LCG 1.41 m from AP (taken as the LCB, model trimmed
// level), heave restoring C33 = ρ g A_wp = 10782 N/m.
#include <catch2/catch.hpp>

#include "io/formats/offsets_csv.h"
#include "parametric_hull/hydrostatics.h"
#include "parametric_hull/section_geometry.h"

using namespace hullopt;

namespace {
// Acceptance. The offsets passed through an OCR copy and stop at x = 2.85 m (the stem, about 0.1 %
// of the volume, is not part of the offsets), so 2 % on volume and waterplane, 1 % L on the LCB.
constexpr double kDisplacementRelTol = 0.02, kStiffnessRelTol = 0.02, kLcbTolFractionL = 0.01;
constexpr double kRhoFresh = 1000.0, kG = 9.81, kDraught = 0.15, kLpp = 3.0, kSpacing = 0.70;

hull::HullForm Delft372() {
  hull::HullForm h;
  h.type = "offsets";
  h.draught_m = kDraught;
  h.length_m = kLpp;
  hull::Demihull d = io::ReadOffsetsCsv(HULLOPT_SOURCE_DIR "/data/delft372/delft372_offsets.csv", kDraught);
  d.y_centre_m = 0.5 * kSpacing;
  h.bodies = {d};
  return h;
}
}  // namespace

TEST_CASE("Delft 372 offsets: displacement, LCB and heave stiffness", "[delft372][validation]") {
  const hull::HullForm h = Delft372();
  REQUIRE(h.bodies[0].stations.size() == 23);
  const hull::Hydrostatics hs = hull::ComputeHydrostatics(h, kRhoFresh, 0.34);
  CHECK(hs.displacement_kg == Approx(87.07).epsilon(kDisplacementRelTol));
  CHECK(hs.lcb_m_from_ap == Approx(1.41).margin(kLcbTolFractionL * kLpp));
  CHECK(kRhoFresh * kG * hs.awp_m2 == Approx(10782.0).epsilon(kStiffnessRelTol));
  CHECK(hs.Cb == Approx(0.403).margin(0.01));  // report's C_B, same L, b, T
}

TEST_CASE("Delft 372 resampled to 41 stations keeps its hydrostatics", "[delft372][geometry]") {
  // Resampling interpolates between the measured stations, which changes the integrals only by the
  // difference between the two quadratures: well under 1 %.
  constexpr double kResampleRelTol = 0.01;
  const hull::HullForm h = Delft372();
  const hull::HullForm r = hull::Resample(h, 41);
  REQUIRE(r.bodies[0].stations.size() == 41);
  const auto a = hull::ComputeHydrostatics(h, kRhoFresh), b = hull::ComputeHydrostatics(r, kRhoFresh);
  CHECK(b.volume_m3 == Approx(a.volume_m3).epsilon(kResampleRelTol));
  CHECK(b.awp_m2 == Approx(a.awp_m2).epsilon(kResampleRelTol));
  CHECK(b.lcb_m_from_ap == Approx(a.lcb_m_from_ap).epsilon(kResampleRelTol));
}
