// E1 of complex argument against reference values from mpmath 1.3 (mp.e1 at 30 digits; on the negative real
// axis from above −Ei(x) − iπ), in every region of the implementation: power series, continued fraction, the
// strip near the negative real axis, the asymptotic series, and both sides of the |z| = 5 switch.
#include <catch2/catch.hpp>
#include <complex>

#include "seakeeping/green/exponential_integral.h"

using C = std::complex<double>;
using hullopt::sk::ExpIntE1;
using hullopt::sk::ScaledExpIntE1;
using hullopt::sk::ScaledExpIntE1AndPlusLog;
using hullopt::sk::ScaledExpIntE1PlusLog;

namespace {
// Double-precision evaluation of series/continued fractions: ~1e-15 achievable; 1e-13 leaves room for the
// cancellation of the power series at |z| ≈ 5 on the imaginary axis (terms up to e^5/5 ≈ 30 times the
// result).
constexpr double kRelTol = 1e-13;

struct Ref {
  C z, e1, scaled;
};
const Ref kRefs[] = {
    {{1, 0}, {0.21938393439552027, 0}, {0.59634736232319407, 0}},
    {{0, 1}, {-0.33740392290096813, -0.6247132564277136}, {0.34337796155642703, -0.62144962423581336}},
    {{0, 10}, {0.045456433004455373, 0.08755126742397743}, {0.0094885390163548074, -0.098191035010170169}},
    {{-1, 0}, {-1.8951178163559368, -3.1415926535897932}, {-0.69717488323506607, -1.1557273497909217}},
    {{-3, 4}, {4.1540916516426898, 1.1528259664345642}, {-0.091749299387567048, -0.19403834119702349}},
    {{-8, 4.1}, {338.4779348206326, -147.32352615160461}, {-0.10570987348664459, -0.064503980525815011}},
    {{-8, 3.9}, {364.07001720590189, -85.874005361381252}, {-0.10847231753255831, -0.063085868248511894}},
    {{6, 0}, {0.00036008245216265866, 0}, {0.14526762923388689, 0}},
    {{-0.5, 7}, {-0.14015990776612508, -0.18358519086611527}, {0.0090652919656277423, -0.13979832397027251}},
    {{0.2, 0.1}, {1.1132682676313774, -0.37306082481368842}, {1.3984456988074728, -0.31763274899821719}},
    {{-12, 0}, {-14959.532666397529, -3.1415926535897932}, {-0.091914545408896589, -1.9302612391311559e-5}},
    {{0, 20}, {-0.044419820845353317, -0.022554625751456779}, {0.0024642063857782465, -0.049757002659021293}},
    {{-0.001, 0.002}, {5.5248214084747379, -2.0324429359070639}, {5.5233491302718696, -2.0193688566942564}},
    {{-4.9, 0.1}, {-37.223452574655056, -0.40406751703899265}, {-0.27550235769117973, -0.03066646860310776}},
    {{-5.1, 0.1}, {-43.146512399776578, 0.070854279696059025}, {-0.26178230631908721, -0.025831692336634712}},
};
}  // namespace

TEST_CASE("E1 and e^z E1 match mpmath in every region", "[e1]") {
  for (const auto& r : kRefs) {
    INFO("z = " << r.z);
    CHECK(std::abs(ExpIntE1(r.z) - r.e1) <= kRelTol * std::abs(r.e1));
    CHECK(std::abs(ScaledExpIntE1(r.z) - r.scaled) <= kRelTol * std::abs(r.scaled));
  }
}

TEST_CASE("e^z E1 far out near the negative axis (asymptotic branch) matches mpmath", "[e1]") {
  // mpmath: e^z E1(z) at −30 + i, −45 + 2i.
  CHECK(std::abs(ScaledExpIntE1({-30, 1}) - C(-0.034485832885438426, -0.0011923563131977415)) <=
        1e-13 * 0.035);
  CHECK(std::abs(ScaledExpIntE1({-45, 2}) - C(-0.022692589178397231, -0.0010326278566187338)) <=
        1e-13 * 0.023);
}

TEST_CASE("the cut: Im z = +0 and −0 give the two sides", "[e1]") {
  const C above = ExpIntE1(C(-2.0, +0.0)), below = ExpIntE1(C(-2.0, -0.0));
  CHECK(above.imag() == Approx(-M_PI).epsilon(1e-14));
  CHECK(below.imag() == Approx(M_PI).epsilon(1e-14));
  CHECK(above.real() == Approx(below.real()).epsilon(1e-14));
}

TEST_CASE("e^z E1 + ln z is continuous at 0 with value −γ and matches the definition away from 0", "[e1]") {
  constexpr double kGamma = 0.57721566490153286;
  CHECK(std::abs(ScaledExpIntE1PlusLog(0.0) - C(-kGamma, 0)) < 1e-15);
  // Near 0 the remainder behaves like −γ − z ln z: at |z| = 1e-8 it differs from −γ by < 1e-6.
  CHECK(std::abs(ScaledExpIntE1PlusLog(C(0, 1e-8)) - C(-kGamma, 0)) < 1e-6);
  for (const auto& r : kRefs) {
    const C expect = r.scaled + std::log(r.z);
    CHECK(std::abs(ScaledExpIntE1PlusLog(r.z) - expect) <= 1e-13 * (1 + std::abs(expect)));
  }
}

TEST_CASE("e^z E1 and e^z E1 + ln z together match mpmath where the wave Green function evaluates them",
          "[e1]") {
  // The second quadrant (z = ν(Z + i|Y|), Z <= 0): |z| ≈ 1 (where ln|z| ≈ 0 is taken as ½ ln(x² + y²)), the
  // power series near the negative real axis out to |z| = 40 (up to ~120 terms), the cut from above, tiny
  // |z|. mpmath 1.3 at 40 digits: e^z E1(z) (on the cut e^z (−Ei(−z) − iπ)) and that + ln z. Tolerances as
  // above: 1e-13 of the value (plus_log: of 1 + its magnitude, ln z being added to O(1) terms).
  struct Pair {
    C z, scaled, plus_log;
  };
  const Pair refs[] = {
      {{-0.6, 0.8}, {0.057385771136300314, -0.85636315320123314}, {0.057385771136300336, 1.3579342823869478}},
      {{-0.999, 0.01}, {-0.68536806515596327, -1.1537850675440936}, {-0.68631846784920395, 1.9777979103509275}},
      {{0.3, 0.95}, {0.43745385625491144, -0.50514662599290443}, {0.43368972304451561, 0.75977082939714005}},
      {{-2.5, 4.3}, {-0.067035077774510239, -0.19966071697042909}, {1.5371756057076607, 1.8977628812582182}},
      {{-4.99, 0.2}, {-0.26660984435737031, -0.035149603997886939}, {1.3416286305761034, 3.066384330455982}},
      {{-20, 3}, {-0.051491555836674155, -0.0081838101913215643}, {2.9553660221847267, 2.9845188957889744}},
      {{-39, 0.5}, {-0.026330527721424368, -0.00034697873932592736}, {3.6373132944294441, 3.1284258643775667}},
      {{-10, 4.9}, {-0.085583634919109738, -0.047775298533415967}, {2.3245974688382308, 2.6382017018451528}},
      {{-0.05, 0.02}, {2.2336076495444654, -2.5627620789334398}, {-0.68791462145038886, 0.19832419754398858}},
      {{-1e-05, 3e-05}, {9.7843661807240864, -1.8922044258334692}, {-0.57726673774911913, 0.00034245535806958815}},
      {{-3.0, 0.0}, {-0.49457640134864124, -0.15641068822825414}, {0.60403588731946846, 2.9851819653615391}},
      {{-1.2, 2.9}, {-0.029197266124086022, -0.31519712917335248}, {1.1145384614679127, 1.6479393418370599}},
  };
  for (const auto& r : refs) {
    INFO("z = " << r.z);
    for (const auto& v : {ScaledExpIntE1AndPlusLog(r.z), ScaledExpIntE1AndPlusLog(r.z, std::exp(r.z))}) {
      CHECK(std::abs(v.scaled - r.scaled) <= kRelTol * std::abs(r.scaled));
      CHECK(std::abs(v.plus_log - r.plus_log) <= kRelTol * (1 + std::abs(r.plus_log)));
    }
    CHECK(std::abs(ScaledExpIntE1(r.z) - r.scaled) <= kRelTol * std::abs(r.scaled));
  }
}
