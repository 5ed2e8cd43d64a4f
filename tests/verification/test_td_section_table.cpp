// Time-domain heave added mass and damping tables for comparison with the frequency-domain solver (energy
// balance, local and peak agreement, convergence with the panels). Hidden from the default run (minutes of
// CPU): reproduce with
//   ./build/tests/verification_td_section_table "[table]"          (sections, 14 panels per body)
//   ./build/tests/verification_td_section_table "[convergence]"    (semicircle, 14/28/56 panels)
// Output (stdout) is CSV with the section.csv columns (docs/file-formats.md) plus the case and normalised
// values.
#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "seakeeping/green/panel.h"
#include "seakeeping/sections/section_shapes.h"
#include "seakeeping/strip/td_heave_coefficients.h"

using namespace hullopt::sk;

namespace {
constexpr double kG = 9.81;
constexpr double kRho = 1025.0;
// ω²(B/2)/g from 0.1 to 3, the range of the comparison with the frequency-domain solver.
const std::vector<double> kNondimensional = {0.1, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0};

std::string Table(const std::string& name, const std::vector<Panel>& panels, double half_beam, double area) {
  std::vector<double> w;
  for (double k : kNondimensional) w.push_back(std::sqrt(k * kG / half_beam));
  const auto c = TimeDomainHeaveCoefficients(panels, w, kRho, kG);
  std::ostringstream out;
  out.precision(6);
  out << name << ": dt = " << c.dt_s << " s, lags = " << c.lags << ", a33(t=0+) = " << c.a33_infinite_kg_per_m
      << " kg/m (" << c.a33_infinite_kg_per_m / (kRho * area) << " rho A)\n";
  out << "case,w2b_over_g,method,omega_rad_s,a33_kg_per_m,b33_kg_per_m_s,a33_over_rhoA,b33_over_rhoA_omega,"
         "b33_energy_over_b33\n";
  for (std::size_t i = 0; i < w.size(); ++i)
    out << name << "," << kNondimensional[i] << ",time_domain," << w[i] << "," << c.a33_kg_per_m[i] << ","
        << c.b33_kg_per_m_s[i] << "," << c.a33_kg_per_m[i] / (kRho * area) << ","
        << c.b33_kg_per_m_s[i] / (kRho * area * w[i]) << ","
        << c.b33_energy_kg_per_m_s[i] / c.b33_kg_per_m_s[i] << "\n";
  return out.str();
}
}  // namespace

TEST_CASE("time-domain heave coefficients of the reference sections", "[.][table]") {
  const double R = 1.0;
  std::cout << Table("semicircle_R1", PanelSymmetricSection(SemicircleContour(R), 14), R, M_PI * R * R / 2)
            << std::flush;
  std::cout << Table("lewis_B2_T1_sigma0.6", PanelSymmetricSection(LewisContour(2.0, 1.0, 0.6), 14), 1.0,
                     0.6 * 2.0)
            << std::flush;
  std::cout << Table("rectangle_B2_T1", PanelSymmetricSection(RectangleContour(2.0, 1.0), 14), 1.0, 2.0)
            << std::flush;
  auto twin = PanelSymmetricSection(SemicircleContour(R), 14, -1.5 * R);
  const auto other = PanelSymmetricSection(SemicircleContour(R), 14, 1.5 * R);
  twin.insert(twin.end(), other.begin(), other.end());
  std::cout << Table("two_semicircles_R1_spacing3R", twin, R, M_PI * R * R) << std::flush;
}

TEST_CASE("panel convergence of the semicircle", "[.][convergence]") {
  const double R = 1.0;
  for (int np : {14, 28, 56})
    std::cout << Table("semicircle_" + std::to_string(np) + "_panels",
                       PanelSymmetricSection(SemicircleContour(R), np), R, M_PI * R * R / 2)
              << std::flush;
}
