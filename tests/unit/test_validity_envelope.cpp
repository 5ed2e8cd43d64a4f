// The validity envelope, one test per rule: a value inside the flag range gives nothing, one between the flag
// and the hard limit a warning, one beyond the hard limit a refusal. The values come from closed forms: a box
// hull L x B x T displaces V = L B T and has BM_L = I_L / V = L^2 / (12 T); Fn = U / sqrt(g L),
// Fn_vol = U / sqrt(g V^(1/3)); the peak wave length is g Tp^2 / (2 pi).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "evaluation/validity_envelope.h"
#include "parametric_hull/hydrostatics.h"
#include "parametric_hull/plausibility.h"

using namespace hullopt;
using eval::EnvelopeQuantity;
using Q = eval::EnvelopeQuantity;

namespace {
constexpr double kG = 9.81;

hull::Demihull Box(double L, double b, double D) {
  hull::Demihull d;
  d.role = "main";
  for (int i = 0; i < 11; ++i) {
    hull::Station s;
    s.x_m = L * i / 10;
    for (double y : {0.0, b, b}) s.y_m.push_back(y);
    for (double z : {0.0, 0.0, D}) s.z_m.push_back(z);
    d.stations.push_back(s);
  }
  return d;
}
// Box hull of depth 2 T; a catamaran of two such demihulls when spacing > 0.
hull::HullForm BoxHull(double L, double B, double T, double spacing = 0.0) {
  hull::HullForm h;
  h.type = spacing > 0 ? "catamaran" : "monohull";
  h.draught_m = T;
  hull::Demihull d = Box(L, B / 2, 2 * T);
  if (spacing > 0) d.role = "demihull", d.y_centre_m = spacing / 2;
  h.bodies = {d};
  return h;
}

// The findings of one quantity: 0 none, 1 a warning, 2 a refusal.
int Level(const std::vector<eval::EnvelopeFinding>& f, Q q) {
  int level = 0;
  for (const auto& x : f)
    if (x.quantity == q) level = std::max(level, x.refuse ? 2 : 1);
  return level;
}
int Level(Q q, double v) { return Level(eval::CheckEnvelopeValue(q, v, "key"), q); }

eval::EnvelopeInput AtSpeed(const hull::Hydrostatics& hs, double U) {
  eval::EnvelopeInput in;
  in.g_m_s2 = kG;
  in.hs = &hs;
  in.speed_m_s = U;
  return in;
}
}  // namespace

TEST_CASE("every row: flag range inside the hard range, sources given, one row per quantity", "[envelope]") {
  for (const auto& r : eval::EnvelopeRules()) {
    INFO(r.name);
    CHECK(r.hard_min <= r.flag_min);
    CHECK(r.flag_max <= r.hard_max);
    CHECK(std::string(r.flag_source).size() > 10);
    CHECK(std::string(r.hard_source).size() > 10);
    CHECK(&eval::EnvelopeRuleOf(r.quantity) == &r);
  }
  CHECK(eval::EnvelopeRules().size() == 13);
}

TEST_CASE("Fn: flagged above 1.2, refused above 3", "[envelope]") {
  const hull::HullForm h = BoxHull(20.0, 2.0, 1.0);  // V = 40 m^3, L/V^(1/3) = 5.85
  const hull::Hydrostatics hs = hull::ComputeHydrostatics(h);
  const double c = std::sqrt(kG * 20.0);
  CHECK(Level(eval::CheckEnvelope(AtSpeed(hs, 1.1 * c)), Q::kFroudeNumber) == 0);
  CHECK(Level(eval::CheckEnvelope(AtSpeed(hs, 1.5 * c)), Q::kFroudeNumber) == 1);
  CHECK(Level(eval::CheckEnvelope(AtSpeed(hs, 3.2 * c)), Q::kFroudeNumber) == 2);
  // Refusals first, naming the key.
  const auto f = eval::CheckEnvelope(AtSpeed(hs, 3.2 * c));
  REQUIRE(!f.empty());
  CHECK(f.front().refuse);
  CHECK(f.front().key == "speed");
}

TEST_CASE("Fn_vol: flagged above 3 (planing), refused above 6", "[envelope]") {
  const hull::HullForm h = BoxHull(100.0, 2.0, 1.0);  // V = 200 m^3, V^(1/3) = 5.848 m
  const hull::Hydrostatics hs = hull::ComputeHydrostatics(h);
  const double c = std::sqrt(kG * std::cbrt(200.0));
  CHECK(hs.volume_m3 == Approx(200.0).epsilon(1e-9));
  CHECK(Level(eval::CheckEnvelope(AtSpeed(hs, 2.9 * c)), Q::kVolumetricFroude) == 0);
  CHECK(Level(eval::CheckEnvelope(AtSpeed(hs, 4.0 * c)), Q::kVolumetricFroude) == 1);
  CHECK(Level(eval::CheckEnvelope(AtSpeed(hs, 4.0 * c)), Q::kFroudeNumber) == 0);  // Fn 0.97: only planing
  CHECK(Level(eval::CheckEnvelope(AtSpeed(hs, 6.5 * c)), Q::kVolumetricFroude) == 2);
}

TEST_CASE("Hs/lambda_p: flagged above 1/20, refused above 1/7 (breaking)", "[envelope]") {
  const double Tp = 8.0, lambda_p = kG * Tp * Tp / (2 * M_PI);  // 99.9 m
  CHECK(eval::PeakWaveLength(sk::SeaState::JonswapTp(2.0, Tp), kG) == Approx(lambda_p).epsilon(1e-12));
  CHECK(Level(Q::kWaveSteepness, lambda_p / 25 / lambda_p) == 0);
  CHECK(Level(Q::kWaveSteepness, 1.0 / 15) == 1);
  CHECK(Level(Q::kWaveSteepness, 1.0 / 5) == 2);
  sk::DesignEvaluation ev;
  sk::SeaEvaluation s;
  s.sea = sk::SeaState::JonswapTp(lambda_p / 15, Tp);
  s.Tp_s = Tp;
  s.positions.resize(1);
  s.positions[0].position = "forward";
  s.positions[0].rms_accel_g = 0.2;
  ev.seas = {s};
  const auto w = eval::ResponseEnvelopeWarnings(ev, kG);
  REQUIRE(w.size() == 1);
  CHECK(w[0].find("Hs/lambda_p = 0.06667") != std::string::npos);
  ev.seas[0].sea.Hs_m = lambda_p / 25;
  CHECK(eval::ResponseEnvelopeWarnings(ev, kG).empty());
}

TEST_CASE("rms vertical acceleration above 1 g is flagged (the hull leaves the water)", "[envelope]") {
  sk::DesignEvaluation ev;
  sk::SeaEvaluation s;
  s.sea = sk::SeaState::JonswapTp(1.0, 8.0);
  s.Tp_s = 8.0;
  s.positions.resize(3);
  s.positions[0].position = "forward";
  s.positions[0].rms_accel_g = 1.15;
  s.positions[1].position = "lcg";
  s.positions[1].rms_accel_g = 0.5;
  ev.seas = {s};
  const auto w = eval::ResponseEnvelopeWarnings(ev, kG);
  REQUIRE(w.size() == 1);
  CHECK(w[0].find("rms a/g = 1.15") != std::string::npos);
  CHECK(w[0].find("forward") != std::string::npos);
  ev.seas[0].positions[0].rms_accel_g = 0.99;
  CHECK(eval::ResponseEnvelopeWarnings(ev, kG).empty());
}

TEST_CASE("Cs: flagged outside [0, 0.2], refused above 1", "[envelope]") {
  CHECK(Level(Q::kDampingCs, 0.135) == 0);
  CHECK(Level(Q::kDampingCs, 0.5) == 1);
  CHECK(Level(Q::kDampingCs, 100.0) == 2);
  CHECK(Level(Q::kDampingCs, -0.01) == 2);
}

TEST_CASE("g: flagged outside Earth's 9.78-9.84, refused outside 9.5-10.5", "[envelope]") {
  CHECK(Level(Q::kGravity, 9.81) == 0);
  CHECK(Level(Q::kGravity, 10.0) == 1);
  CHECK(Level(Q::kGravity, 1.0) == 2);
  CHECK(Level(Q::kGravity, 32.2) == 2);  // ft/s^2
}

TEST_CASE("rho: flagged outside 990-1030, refused outside 900-1100", "[envelope]") {
  CHECK(Level(Q::kWaterDensity, 1000.0) == 0);
  CHECK(Level(Q::kWaterDensity, 1025.0) == 0);
  CHECK(Level(Q::kWaterDensity, 1050.0) == 1);
  CHECK(Level(Q::kWaterDensity, 1.025) == 2);  // t/m^3
}

TEST_CASE("static trim from LCG - LCB: flagged above 1 deg, refused above 5 deg", "[envelope]") {
  const hull::HullForm h = BoxHull(20.0, 2.0, 1.0);
  const hull::Hydrostatics hs = hull::ComputeHydrostatics(h);
  CHECK(hs.bm_l_m == Approx(20.0 * 20.0 / 12.0).epsilon(1e-6));  // L^2 / (12 T)
  hull::MassProperties m{hs.displacement_kg, hs.lcb_m_from_ap, 5.0, 1.0};
  eval::EnvelopeInput in;
  in.hull = &h;
  in.hs = &hs;
  in.mass = &m;
  auto at = [&](double offset) {
    m.lcg_m_from_ap = hs.lcb_m_from_ap + offset;
    return Level(eval::CheckEnvelope(in), Q::kStaticTrimDeg);
  };
  const double bml = hs.bm_l_m;
  CHECK(at(bml * std::tan(0.5 * M_PI / 180)) == 0);
  CHECK(at(bml * std::tan(2.0 * M_PI / 180)) == 1);
  CHECK(at(-bml * std::tan(6.0 * M_PI / 180)) == 2);
}

TEST_CASE("KG against the hull's depth: flagged above 2 D, refused above 4 D", "[envelope]") {
  const hull::HullForm h = BoxHull(20.0, 2.0, 1.0);  // depth D = 2 m
  const hull::Hydrostatics hs = hull::ComputeHydrostatics(h);
  CHECK(eval::HullDepth(h) == 2.0);
  hull::MassProperties m{hs.displacement_kg, hs.lcb_m_from_ap, 5.0, 3.0};
  eval::EnvelopeInput in;
  in.hull = &h;
  in.hs = &hs;
  in.mass = &m;
  CHECK(Level(eval::CheckEnvelope(in), Q::kKgOverDepth) == 0);
  m.kg_m = 5.0;
  CHECK(Level(eval::CheckEnvelope(in), Q::kKgOverDepth) == 1);
  m.kg_m = 9.0;
  CHECK(Level(eval::CheckEnvelope(in), Q::kKgOverDepth) == 2);
}

TEST_CASE("k_yy row: the mass plausibility rule's numbers", "[envelope]") {
  const hull::PlausibilityLimits lim;
  const auto& r = eval::EnvelopeRuleOf(Q::kKyyOverL);
  CHECK(r.flag_min == lim.kyy_usual_min_over_L);
  CHECK(r.flag_max == lim.kyy_usual_max_over_L);
  CHECK(r.hard_min == lim.kyy_min_over_L);
  CHECK(r.hard_max == lim.kyy_max_over_L);
  CHECK(Level(Q::kKyyOverL, 0.25) == 0);
  CHECK(Level(Q::kKyyOverL, 0.4) == 1);
  CHECK(Level(Q::kKyyOverL, 2.0) == 2);
}

TEST_CASE("hull spacing: flagged above 0.6 L, refused above 2 L", "[envelope]") {
  for (const auto& [s_over_L, level] : {std::pair{0.25, 0}, std::pair{1.0, 1}, std::pair{800.0, 2}}) {
    const hull::HullForm h = BoxHull(20.0, 2.0, 1.0, s_over_L * 20.0);
    const hull::Hydrostatics hs = hull::ComputeHydrostatics(h);
    CHECK(eval::LargestHullSpacing(h) == Approx(s_over_L * 20.0));
    eval::EnvelopeInput in;
    in.hull = &h;
    in.hs = &hs;
    CHECK(Level(eval::CheckEnvelope(in), Q::kHullSpacingOverL) == level);
  }
}

TEST_CASE("hull length and displacement: a hull in millimetres is refused", "[envelope]") {
  hull::Hydrostatics hs;
  hs.L_m = 60000.0;  // a 60 m hull read in millimetres
  hs.displacement_t = 4.9e11;
  eval::EnvelopeInput in;
  in.hs = &hs;
  CHECK(Level(eval::CheckEnvelope(in), Q::kHullLength) == 2);
  CHECK(Level(eval::CheckEnvelope(in), Q::kDisplacementTonnes) == 2);
  hs.L_m = 450.0;
  hs.displacement_t = 6e5;
  CHECK(Level(eval::CheckEnvelope(in), Q::kHullLength) == 1);
  CHECK(Level(eval::CheckEnvelope(in), Q::kDisplacementTonnes) == 1);
  hs.L_m = 3.0;
  hs.displacement_t = 0.0864;
  CHECK(eval::CheckEnvelope(in).empty());
  CHECK(Level(Q::kHullLength, 0.01) == 2);
}
