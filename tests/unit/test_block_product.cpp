// The reduction's block product C += A·B against Eigen's coefficient-based product (lazyProduct), whose
// summation order it keeps: bit for bit, for every shape up to 17 × 17 × 9 (the kernel's blocks are P × P with
// P up to the panels per section), with random entries. (Not for a row vector times a block: Eigen sums that
// dot product in its vectorised order, so the momentum rows keep lazyProduct.)
#include <catch2/catch.hpp>
#include <Eigen/Dense>
#include <cstring>
#include <random>

#include "seakeeping/strip/block_product.h"

TEST_CASE("AddProduct: bitwise Eigen's lazyProduct", "[unit][strip]") {
  std::mt19937 rng(3);
  std::normal_distribution<double> normal;
  auto fill = [&](auto* m) {
    for (Eigen::Index i = 0; i < m->size(); ++i) m->data()[i] = normal(rng);
  };
  int differing = 0, shapes = 0;
  for (int n = 1; n <= 17; ++n)
    for (int p = 1; p <= 17; ++p)
      for (int m : {1, 2, 7, 9}) {
        Eigen::MatrixXd A(n, p), B(p, m), C(n, m);
        fill(&A), fill(&B), fill(&C);
        Eigen::MatrixXd lazy = C, ours = C;
        lazy.noalias() += A.lazyProduct(B);
        hullopt::sk::AddProduct(A, B, &ours);
        if (std::memcmp(lazy.data(), ours.data(), sizeof(double) * lazy.size()) != 0) ++differing;
        ++shapes;
      }
  INFO(differing << " of " << shapes << " shapes differ");
  CHECK(differing == 0);
}
