// The oblique-sea strip theory (seakeeping/motions/oblique_strip_theory.h) solves its (frequency, station)
// sections and then its frequencies (at speed: its (heading, frequency) pairs) in parallel loops. Each
// iteration writes its own results only, so one and two OpenMP threads must give the same bits: every
// coefficient, load and RAO is compared exactly (==, no tolerance), at zero speed and at speed over several
// headings, and with the viscous roll damping, which is evaluated inside the frequency loop.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "seakeeping/motions/oblique_strip_theory.h"
#include "support/wigley_oblique.h"

using namespace hullopt;

namespace {

bool SameBits(const void* a, const void* b, std::size_t n) { return std::memcmp(a, b, n) == 0; }

template <class M>
bool SameMatrix(const M& a, const M& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         SameBits(a.data(), b.data(), sizeof(typename M::Scalar) * a.size());
}

// Every number of two results, bit for bit.
void CheckIdentical(const sk::ObliqueStripResult& one, const sk::ObliqueStripResult& two) {
  REQUIRE(one.frequencies.size() == two.frequencies.size());
  REQUIRE(one.waves.size() == two.waves.size());
  for (std::size_t e = 0; e < one.frequencies.size(); ++e) {
    const auto &a = one.frequencies[e], &b = two.frequencies[e];
    CHECK(SameBits(&a.omega_rad_s, &b.omega_rad_s, sizeof(double)));
    CHECK(SameMatrix(a.added_mass, b.added_mass));
    CHECK(SameMatrix(a.damping, b.damping));
    REQUIRE(a.sections.size() == b.sections.size());
    for (std::size_t s = 0; s < a.sections.size(); ++s) {
      CHECK(SameMatrix(a.sections[s].added_mass, b.sections[s].added_mass));
      CHECK(SameMatrix(a.sections[s].damping, b.sections[s].damping));
    }
  }
  for (std::size_t i = 0; i < one.waves.size(); ++i) {
    const auto &a = one.waves[i], &b = two.waves[i];
    CHECK(a.frequency_entry == b.frequency_entry);
    CHECK(SameBits(&a.omega_e_rad_s, &b.omega_e_rad_s, sizeof(double)));
    CHECK(SameBits(&a.viscous_roll_damping, &b.viscous_roll_damping, sizeof(double)));
    CHECK(SameMatrix(a.added_mass, b.added_mass));
    CHECK(SameMatrix(a.damping, b.damping));
    CHECK(SameBits(a.froude_krylov.data(), b.froude_krylov.data(), sizeof a.froude_krylov));
    CHECK(SameBits(a.diffraction.data(), b.diffraction.data(), sizeof a.diffraction));
    CHECK(SameBits(a.excitation.data(), b.excitation.data(), sizeof a.excitation));
    CHECK(SameBits(a.rao.data(), b.rao.data(), sizeof a.rao));
  }
}

sk::ObliqueStripResult Solve(int threads, double speed_m_s, bool viscous_roll) {
#ifdef _OPENMP
  omp_set_num_threads(threads);
#else
  (void)threads;
#endif
  sk::ObliqueStripOptions o = test::WigleyObliqueOptions(speed_m_s);
  if (viscous_roll) {
    // The Wigley hull's own particulars: Cb 4/9 and Cm 2/3 of its parabolic sections and waterlines; the CG
    // 0.13 m above the keel, so OG = T - KG below the waterline.
    o.roll_damping.model = sk::RollDampingModel::kIkeda;
    o.roll_damping_hull.length_m = test::kWigleyL;
    o.roll_damping_hull.breadth_m = test::kWigleyB;
    o.roll_damping_hull.draught_m = test::kWigleyT;
    o.roll_damping_hull.block_coefficient = 4.0 / 9.0;
    o.roll_damping_hull.midship_coefficient = 2.0 / 3.0;
    o.roll_damping_hull.og_m = test::kWigleyT - 0.13;
  }
  // Beam to head seas (at speed every heading has its own encounter frequencies; 90 deg shares the waves').
  const std::vector<double> omegas{2.0, 3.0, 4.0, 5.0, 6.0, 7.0};
  return sk::SolveObliqueStripTheory(test::WigleyObliqueStations(12, 10), test::WigleyObliqueMass(0.13), omegas,
                                     {180.0, 150.0, 120.0, 90.0}, o);
}

}  // namespace

#ifdef _OPENMP
TEST_CASE("oblique strip theory: bitwise the same with 1 and 2 threads at zero speed", "[oblique][openmp]") {
  const auto one = Solve(1, 0.0, false);
  const auto two = Solve(2, 0.0, false);
  CheckIdentical(one, two);
}

TEST_CASE("oblique strip theory: bitwise the same with 1 and 2 threads at speed", "[oblique][openmp]") {
  const double U = 0.3 * std::sqrt(9.81 * test::kWigleyL);  // Fn 0.3
  const auto one = Solve(1, U, false);
  const auto two = Solve(2, U, false);
  REQUIRE(one.frequencies.size() > 6);  // the headings' own encounter frequencies
  CheckIdentical(one, two);
}

TEST_CASE("oblique strip theory: bitwise the same with 1 and 2 threads with viscous roll damping",
          "[oblique][openmp]") {
  const double U = 0.3 * std::sqrt(9.81 * test::kWigleyL);
  const auto one = Solve(1, U, true);
  const auto two = Solve(2, U, true);
  REQUIRE(one.waves[0].viscous_roll_damping > 0.0);
  CheckIdentical(one, two);
}
#endif
