// The viscous roll damping's options and hull (seakeeping/motions/roll_damping.h): IsValid names the field,
// the range check names the parameter outside the published range, and the oblique strip theory refuses
// invalid roll damping options only when a model is chosen.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

#include "seakeeping/motions/oblique_strip_theory.h"
#include "seakeeping/motions/roll_damping.h"

using namespace hullopt;

namespace {

sk::RollDampingHull InRange() {  // a cargo ship inside Kawahara et al.'s range
  sk::RollDampingHull h;
  h.length_m = 150.0;
  h.breadth_m = 25.0;
  h.draught_m = 8.0;
  h.block_coefficient = 0.7;
  h.midship_coefficient = 0.97;
  h.og_m = -2.0;
  return h;
}

sk::RollDampingOptions IkedaOptions() {
  sk::RollDampingOptions o;
  o.model = sk::RollDampingModel::kIkeda;
  return o;
}

bool Contains(const std::vector<std::string>& flags, const std::string& what) {
  for (const auto& f : flags)
    if (f.find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("roll damping options: IsValid names the field and the rule") {
  std::string err;
  CHECK(sk::RollDampingOptions{}.IsValid(&err));
  sk::RollDampingOptions o = IkedaOptions();
  o.roll_amplitude_rad = 0.0;
  CHECK_FALSE(o.IsValid(&err));
  CHECK(err.find("roll_amplitude_rad") != std::string::npos);
  o = IkedaOptions();
  o.roll_amplitude_rad = 0.6;
  CHECK_FALSE(o.IsValid(&err));
  o = IkedaOptions();
  o.kinematic_viscosity_m2_s = NAN;
  CHECK_FALSE(o.IsValid(&err));
  CHECK(err.find("kinematic_viscosity_m2_s") != std::string::npos);
  o = IkedaOptions();
  o.damping_cs = -0.1;
  CHECK_FALSE(o.IsValid(&err));
  CHECK(err.find("damping_cs") != std::string::npos);

  sk::RollDampingHull h = InRange();
  CHECK(h.IsValid(&err));
  h.block_coefficient = 1.2;
  CHECK_FALSE(h.IsValid(&err));
  CHECK(err.find("block_coefficient") != std::string::npos);
  h = InRange();
  h.bilge_keel_length_m = 30.0;  // a length without a breadth
  CHECK_FALSE(h.IsValid(&err));
  CHECK(err.find("bilge keels") != std::string::npos);
  h = InRange();
  h.body_offset_m = {5.0, 5.0};
  h.body_waterplane_m2 = {100.0};
  CHECK_FALSE(h.IsValid(&err));
  CHECK(err.find("one entry per body") != std::string::npos);
  CHECK_THROWS_AS(sk::ViscousRollDamping(InRange(), 0.0, 0.0, IkedaOptions()), std::invalid_argument);
}

TEST_CASE("roll damping: the range check names each parameter outside the published range") {
  const sk::RollDampingOptions o = IkedaOptions();
  const double w_hat_one = 1.0 / std::sqrt(25.0 / (2.0 * 9.81));  // ω̂ = 1
  CHECK(sk::RollDampingRangeFlags(InRange(), 0.5 * w_hat_one, 5.0, o).empty());
  CHECK(sk::RollDampingRangeFlags(InRange(), 0.5 * w_hat_one, 5.0, sk::RollDampingOptions{}).empty());  // model none
  sk::RollDampingHull h = InRange();
  h.block_coefficient = 0.40;
  h.midship_coefficient = 0.8;
  auto flags = sk::RollDampingRangeFlags(h, 1.2 * w_hat_one, 5.0, o);
  REQUIRE(flags.size() == 4);
  // Kawahara's fit at Cb 0.40, B/d 3.125: A_E = f_E1 + f_E2 = 0.0191 − 0.0600 < 0 (by hand): no eddy damping,
  // and said so.
  CHECK(Contains(flags, "its eddy damping is taken as 0"));
  CHECK(sk::KawaharaEddyCoefficient(h) == 0.0);
  CHECK(Contains(flags, "Cb = 0.4 is outside the range [0.5, 0.85]"));
  CHECK(Contains(flags, "Cm = 0.8 is outside the range [0.9, 0.99]"));
  CHECK(Contains(flags, "omega_hat"));
  h = InRange();
  h.draught_m = 12.0;  // B/d 2.08, OG/d −0.17
  CHECK(Contains(sk::RollDampingRangeFlags(h, 0.5 * w_hat_one, 5.0, o), "B/d = 2.08333"));
  h = InRange();
  h.og_m = 3.0;  // CG 3 m below the waterline: OG/d 0.375
  CHECK(Contains(sk::RollDampingRangeFlags(h, 0.5 * w_hat_one, 5.0, o), "OG/d = 0.375"));
  h = InRange();
  h.bilge_keel_length_m = 100.0;  // l/L 0.67
  h.bilge_keel_breadth_m = 0.5;   // b/B 0.02
  flags = sk::RollDampingRangeFlags(h, 0.5 * w_hat_one, 5.0, o);
  REQUIRE(flags.size() == 1);
  CHECK(Contains(flags, "bilge keel l/L"));

  // A demihull pair: Ikeda's range does not cover it; at zero speed (or Cs = 0) its Cs term is zero.
  h = InRange();
  h.body_offset_m = {10.0, 10.0};
  h.body_waterplane_m2 = {200.0, 200.0};
  sk::RollDampingOptions cs = o;
  cs.damping_cs = 0.1;
  flags = sk::RollDampingRangeFlags(h, 0.5 * w_hat_one, 5.0, cs);
  REQUIRE(flags.size() == 1);
  CHECK(Contains(flags, "do not cover a demihull pair"));
  CHECK(Contains(sk::RollDampingRangeFlags(h, 0.5 * w_hat_one, 0.0, cs), "zero speed"));
  CHECK(Contains(sk::RollDampingRangeFlags(h, 0.5 * w_hat_one, 5.0, o), "Cs = 0"));
  // Its B44: Σ y_i² ½ Cs ρ U A_wp,i = 2·100·0.5·0.1·1025·5·200 = 1.025e7 N m s, nothing of Ikeda's.
  const auto c = sk::ViscousRollDamping(h, 0.5, 5.0, cs);
  CHECK(c.demihull_cs == Approx(1.025e7).epsilon(1e-12));
  CHECK(c.friction == 0.0);
  CHECK(c.equivalent == Approx(1.025e7).epsilon(1e-12));
}

TEST_CASE("oblique strip options: roll damping options are checked only with a model") {
  sk::ObliqueStripOptions o;
  std::string err;
  o.roll_damping.roll_amplitude_rad = -1.0;  // ignored with model none
  CHECK(o.IsValid(&err));
  o.roll_damping.model = sk::RollDampingModel::kIkeda;
  CHECK_FALSE(o.IsValid(&err));
  CHECK(err.find("roll_damping: roll_amplitude_rad") != std::string::npos);
  o.roll_damping.roll_amplitude_rad = 0.1;
  CHECK_FALSE(o.IsValid(&err));  // no hull described
  CHECK(err.find("roll_damping_hull") != std::string::npos);
  o.roll_damping_hull = InRange();
  CHECK(o.IsValid(&err));
}
