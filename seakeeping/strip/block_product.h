#pragma once
// The small matrix products of the strip-kernel reduction (strip_kernel_builder.cpp).
#include <Eigen/Core>
#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hullopt::sk {

namespace block_product {
// R rows (R <= 8) of one output column: R/2 pairs in SSE2 registers and a single row, all summed at once.
template <int R>
inline void AddRows(const double* a, std::size_t lda, const double* b, int p, double* out) {
  constexpr int kPairs = R / 2;
  double t = 0.0;
#if defined(__SSE2__)
  __m128d s[kPairs > 0 ? kPairs : 1];
  for (int q = 0; q < kPairs; ++q) s[q] = _mm_setzero_pd();
  for (int i = 0; i < p; ++i) {
    const double* ai = a + static_cast<std::size_t>(i) * lda;
    const __m128d bi = _mm_set1_pd(b[i]);
    for (int q = 0; q < kPairs; ++q) s[q] = _mm_add_pd(s[q], _mm_mul_pd(bi, _mm_loadu_pd(ai + 2 * q)));
    if constexpr (R % 2 == 1) t = t + ai[2 * kPairs] * b[i];
  }
  for (int q = 0; q < kPairs; ++q) _mm_storeu_pd(out + 2 * q, _mm_add_pd(_mm_loadu_pd(out + 2 * q), s[q]));
  if constexpr (R % 2 == 1) out[2 * kPairs] += t;
#else
  for (int r = 0; r < R; ++r) {
    t = 0.0;
    for (int i = 0; i < p; ++i) t = t + a[static_cast<std::size_t>(i) * lda + r] * b[i];
    out[r] += t;
  }
#endif
}
}  // namespace block_product

/// C += A·B for the small column-major blocks of the reduction (A n × p, B p × m, C n × m), each coefficient
/// as Eigen's coefficient-based product (lazyProduct) forms it: the products A(r, i)·B(i, c) summed from zero
/// in the order of i, then added to C(r, c), so the same bits (unit test: tests/unit/test_block_product.cpp; a
/// row vector times a block is not the same: Eigen sums that dot product in its vectorised order). Per output
/// column up to eight rows are summed at once, in up to four SSE2 registers and one scalar: independent
/// chains, where the lazy product keeps one running sum of two rows and waits on each addition.
inline void AddProduct(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, Eigen::MatrixXd* C) {
  using block_product::AddRows;
  const int n = static_cast<int>(A.rows()), p = static_cast<int>(A.cols()), m = static_cast<int>(B.cols());
  const std::size_t lda = static_cast<std::size_t>(n);
  for (int c = 0; c < m; ++c) {
    const double* b = B.data() + static_cast<std::size_t>(c) * p;
    double* out = C->data() + static_cast<std::size_t>(c) * n;
    int r = 0;
    for (; r + 7 < n; r += 8) AddRows<8>(A.data() + r, lda, b, p, out + r);
    const double* a = A.data() + r;
    switch (n - r) {
      case 1: AddRows<1>(a, lda, b, p, out + r); break;
      case 2: AddRows<2>(a, lda, b, p, out + r); break;
      case 3: AddRows<3>(a, lda, b, p, out + r); break;
      case 4: AddRows<4>(a, lda, b, p, out + r); break;
      case 5: AddRows<5>(a, lda, b, p, out + r); break;
      case 6: AddRows<6>(a, lda, b, p, out + r); break;
      case 7: AddRows<7>(a, lda, b, p, out + r); break;
      default: break;
    }
  }
}

}  // namespace hullopt::sk
