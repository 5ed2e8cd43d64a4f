// E1 of complex argument against reference values from mpmath 1.3 (mp.e1 at 30 digits; on the negative real
// axis from above −Ei(x) − iπ), in every region of the implementation: power series, continued fraction, the
// strip near the negative real axis, the asymptotic series, and both sides of the |z| = 5 switch.
#include <catch2/catch.hpp>
#include <complex>

#include "seakeeping/green/exponential_integral.h"

using C = std::complex<double>;
using hullopt::sk::ExpIntE1;
using hullopt::sk::ScaledExpIntE1;
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
