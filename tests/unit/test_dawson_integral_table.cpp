// The Dawson-integral table embedded in the library at build time (seakeeping/green/dawson_integral_table.h) is,
// bit for bit, the table ComputeDawsonIntegralTable computes from libcerf at run time; its values against libcerf
// and quadrature are checked in test_transient_green.cpp.
#include <catch2/catch.hpp>
#include <cstring>

#include "seakeeping/green/dawson_integral_table.h"

using namespace hullopt::sk::dawson_table;

TEST_CASE("embedded Dawson-integral table: the size of the table the layout describes") {
  const std::size_t doubles = static_cast<std::size_t>(hullopt_dawson_integral_table_end - hullopt_dawson_integral_table);
  CHECK(doubles == 2 * (kValues + kKernelValues));
}

TEST_CASE("embedded Dawson-integral table: bit for bit the table computed at run time") {
  const auto computed = ComputeDawsonIntegralTable();
  REQUIRE(computed.size() == kValues + kKernelValues);
  std::size_t differing = 0;
  for (std::size_t k = 0; k < computed.size(); ++k)
    if (std::memcmp(&computed[k], &Table()[k], sizeof computed[k]) != 0) ++differing;
  CHECK(differing == 0);
  // A spot check that the layout is the one the evaluation assumes: node (0, 0) holds Φ(0) = 0 and F(0) = 0, and
  // F'(0) = 1 as the coefficient of δ² (c_2 = F'(0)/2!).
  CHECK(Table()[NodeOffset(0, 0)] == std::complex<double>(0.0, 0.0));
  CHECK(Table()[NodeOffset(0, 0) + 1] == std::complex<double>(0.0, 0.0));
  CHECK(Table()[NodeOffset(0, 0) + 2] == std::complex<double>(0.5, 0.0));
  // G's table right after it: at x0 = 0, G0 = −Φ(0) = 0, G1 = −2F(0) = 0, the δ² coefficient 2C − 3/2 − 2Φ(0)
  // (C = (γ + ln 4)/4), and the δ³ one −4c_1/6 = 0; the last node of the last row is (kGridN, kGridN).
  CHECK(KernelTable() == Table() + kValues);
  CHECK(KernelTable()[KernelNodeOffset(0, 0)] == std::complex<double>(0.0, 0.0));
  CHECK(KernelTable()[KernelNodeOffset(0, 0) + 1] == std::complex<double>(0.0, 0.0));
  CHECK(KernelTable()[KernelNodeOffset(0, 0) + 2] == std::complex<double>(2.0 * kPhiConstant - 1.5, 0.0));
  CHECK(KernelTable()[KernelNodeOffset(0, 0) + 3] == std::complex<double>(0.0, 0.0));
  CHECK(KernelNodeOffset(kGridN, kGridN) + kKernelCoefficients == kKernelValues);
}
