#pragma once
// ln x for positive normal x (finite, >= 2^−1022) without std::log's range and special-value handling, as the
// same operations on one value and on four in an AVX register: the strip kernel takes ln|w| once per
// field-point/source-point pair (transient_green.h), where std::log, one call at a time, was about a sixteenth of
// the kernel's time.
//
// The algorithm of fdlibm's e_log.c (Sun Microsystems, 1993): x = 2^k (1 + f) with √2/2 < 1 + f <= √2,
// s = f/(2 + f), ln(1 + f) = f − f²/2 + s(f²/2 + R(s²)) with fdlibm's minimax polynomial R (error below
// 2^−58.45 on that range), and k ln 2 in two parts; below 1 ulp (unit test: against std::log). Both forms do the
// same operations in the same order (the build has no FMA contraction), so they give the same bits.
#include <cstdint>
#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace hullopt::sk {
namespace positive_logarithm {
constexpr double kLn2Hi = 6.93147180369123816490e-01, kLn2Lo = 1.90821492927058770002e-10;
constexpr double kSqrt2 = 1.4142135623730951;
constexpr double kLg1 = 6.666666666666735130e-01, kLg2 = 3.999999999940941908e-01, kLg3 = 2.857142874366239149e-01,
                 kLg4 = 2.222219843214978396e-01, kLg5 = 1.818357216161805012e-01, kLg6 = 1.531383769920937332e-01,
                 kLg7 = 1.479819860511658591e-01;
constexpr std::uint64_t kMantissa = 0x000FFFFFFFFFFFFFull, kOne = 0x3FF0000000000000ull;
}  // namespace positive_logarithm

inline double PositiveLogarithm(double x) {
  using namespace positive_logarithm;
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  double k = static_cast<double>(static_cast<std::int64_t>(bits >> 52)) - 1023.0;
  const std::uint64_t m_bits = (bits & kMantissa) | kOne;
  double m;
  std::memcpy(&m, &m_bits, sizeof m);  // in [1, 2)
  if (m > kSqrt2) m = m * 0.5, k = k + 1.0;
  const double f = m - 1.0, s = f / (2.0 + f), z = s * s, w = z * z;
  const double r = z * (kLg1 + w * (kLg3 + w * (kLg5 + w * kLg7))) + w * (kLg2 + w * (kLg4 + w * kLg6));
  const double hfsq = 0.5 * f * f;
  return k * kLn2Hi - ((hfsq - (s * (hfsq + r) + k * kLn2Lo)) - f);
}

#if defined(__x86_64__) && defined(__GNUC__)
namespace positive_logarithm {
__attribute__((target("avx"))) inline __m256d add(__m256d a, __m256d b) { return _mm256_add_pd(a, b); }
__attribute__((target("avx"))) inline __m256d mul(__m256d a, __m256d b) { return _mm256_mul_pd(a, b); }
__attribute__((target("avx"))) inline __m256d c(double v) { return _mm256_set1_pd(v); }
}  // namespace positive_logarithm

/// PositiveLogarithm of four values at once (AVX): per lane the same operations.
__attribute__((target("avx"))) inline __m256d PositiveLogarithmAvx(__m256d x) {
  using namespace positive_logarithm;
  const __m256i bits = _mm256_castpd_si256(x);
  // The biased exponent as a double: bits >> 52 (two 128-bit halves, AVX has no 256-bit integer shift) under
  // the exponent of 2^52, minus 2^52 + 1023: exact, as the scalar conversion.
  const __m128i lo = _mm_srli_epi64(_mm256_castsi256_si128(bits), 52);
  const __m128i hi = _mm_srli_epi64(_mm256_extractf128_si256(bits, 1), 52);
  const __m256d two52 = _mm256_castsi256_pd(_mm256_set1_epi64x(0x4330000000000000ll));
  const __m256d biased = _mm256_or_pd(_mm256_castsi256_pd(_mm256_insertf128_si256(_mm256_castsi128_si256(lo), hi, 1)), two52);
  __m256d k = _mm256_sub_pd(_mm256_sub_pd(biased, two52), _mm256_set1_pd(1023.0));
  __m256d m = _mm256_or_pd(_mm256_and_pd(x, _mm256_castsi256_pd(_mm256_set1_epi64x(static_cast<long long>(kMantissa)))),
                           _mm256_castsi256_pd(_mm256_set1_epi64x(static_cast<long long>(kOne))));
  const __m256d above = _mm256_cmp_pd(m, _mm256_set1_pd(kSqrt2), _CMP_GT_OQ);
  m = _mm256_blendv_pd(m, _mm256_mul_pd(m, _mm256_set1_pd(0.5)), above);
  k = _mm256_blendv_pd(k, _mm256_add_pd(k, _mm256_set1_pd(1.0)), above);
  const __m256d f = _mm256_sub_pd(m, _mm256_set1_pd(1.0));
  const __m256d s = _mm256_div_pd(f, _mm256_add_pd(_mm256_set1_pd(2.0), f));
  const __m256d z = _mm256_mul_pd(s, s), w = _mm256_mul_pd(z, z);
  const __m256d r = add(mul(z, add(c(kLg1), mul(w, add(c(kLg3), mul(w, add(c(kLg5), mul(w, c(kLg7)))))))),
                        mul(w, add(c(kLg2), mul(w, add(c(kLg4), mul(w, c(kLg6)))))));
  const __m256d hfsq = mul(mul(c(0.5), f), f);
  return _mm256_sub_pd(mul(k, c(kLn2Hi)),
                       _mm256_sub_pd(_mm256_sub_pd(hfsq, add(mul(s, add(hfsq, r)), mul(k, c(kLn2Lo)))), f));
}

/// The same from and to memory: x[0..4) -> out[0..4) (callable from code built without AVX).
__attribute__((target("avx"))) inline void PositiveLogarithmAvx4(const double* x, double* out) {
  _mm256_storeu_pd(out, PositiveLogarithmAvx(_mm256_loadu_pd(x)));
}
#endif

}  // namespace hullopt::sk
