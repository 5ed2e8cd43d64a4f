#include "seakeeping/green/transient_green.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "seakeeping/green/cerf_wrap.h"
#include "seakeeping/green/complex_log.h"
#include "seakeeping/green/dawson_integral_table.h"
#include "seakeeping/green/unit_arctangent.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace hullopt::sk {
namespace {

using cd = std::complex<double>;
constexpr cd kI(0.0, 1.0);
const double kSqrtPi = std::sqrt(M_PI);

// |x| from which the asymptotic series replaces the closed forms. With 30 terms the truncation error of the
// algebraic series at |x| = 6 is ~1e−15 relative (the terms fall as Π(2k−1)/(2|x|²)), while the closed forms
// of H_t and H' lose ~ε·2|x|² and ~ε·2|x|⁴ there.
constexpr double kAsymptoticRadius = 6.0;
constexpr int kAsymptoticTerms = 30;
// c_n = (2n−1)!!/2^{n+1}, n = 0.. (c_0 = 1/2): the coefficients of F(x) ~ Σ c_n x^{−(2n+1)}.
const std::array<double, kAsymptoticTerms + 1>& AsymptoticCoefficients() {
  static const auto c = [] {
    std::array<double, kAsymptoticTerms + 1> out{};
    out[0] = 0.5;
    for (int n = 1; n <= kAsymptoticTerms; ++n) out[n] = out[n - 1] * (2 * n - 1) / 2.0;
    return out;
  }();
  return c;
}

void CheckArguments(double Y, double Z, double t, double g) {
  if (!std::isfinite(Y) || !std::isfinite(Z) || !std::isfinite(t) || !std::isfinite(g))
    throw std::invalid_argument("transient Green function: non-finite argument");
  if (Z > 0.0)
    throw std::invalid_argument(
        "transient Green function: Z = z + zeta must be <= 0 (fluid below z = 0), got " + std::to_string(Z));
  if (t < 0.0)
    throw std::invalid_argument("transient Green function: lag t must be >= 0, got " + std::to_string(t));
  if (!(g > 0.0)) throw std::invalid_argument("transient Green function: g must be > 0");
  if (Y == 0.0 && Z == 0.0)
    throw std::domain_error(
        "transient Green function: field and source point coincide on the free surface (a = 0)");
}

// x for Y >= 0 (0 <= arg x <= π/4) and a.
struct Arg {
  cd a, sqrt_a, x;
};
Arg MakeArg(double Yabs, double Z, double t, double g) {
  // Hot path: principal sqrt of a = |Z| − i|Y| and x = √g t / (2√a) with real arithmetic only
  // (√a = (sqrt((r + |Z|)/2), −sqrt((r − |Z|)/2)), r = |a| = |√a|²; 1/√a = conj(√a)/r).
  Arg out;
  const double p = -Z, r = std::sqrt(p * p + Yabs * Yabs);
  out.a = cd(p, -Yabs);
  out.sqrt_a = cd(std::sqrt(0.5 * (r + p)), -std::sqrt(0.5 * std::fmax(r - p, 0.0)));
  const double scale = std::sqrt(g) * t / (2.0 * r);
  out.x = cd(scale * out.sqrt_a.real(), -scale * out.sqrt_a.imag());
  return out;
}

cd ConjIf(bool c, cd v) { return c ? std::conj(v) : v; }

}  // namespace

cd Dawson(cd x) {
  double fr = 0, fi = 0;
  hullopt_cdawson(x.real(), x.imag(), &fr, &fi);
  return {fr, fi};
}

namespace {
// Φ (first table) and G (second table, for K) below |x| = 6 from the tables of
// seakeeping/green/dawson_integral_table.h (Taylor coefficients per node, evaluated by Horner's rule): this
// lookup is the hot spot of the strip-kernel build. The tables are embedded in the library (computed when
// hullopt is built). A table is described by its data, its coefficients per node and its node layout.
using dawson_table::kGridStep;
using dawson_table::kInvGridStep;
using dawson_table::kPhiConstant;

struct PhiTable {  // Φ over the quadrant's square of nodes
  static constexpr int kTerms = dawson_table::kCoefficients;
  static const cd* Data() { return dawson_table::Table(); }
  static std::size_t Offset(int i, int j) { return dawson_table::NodeOffset(i, j); }
};
struct KernelTable {  // G over the sector 0 <= arg x <= π/4 (j <= i): K = 8a(G + x² ln x)
  static constexpr int kTerms = dawson_table::kKernelCoefficients;
  static const cd* Data() { return dawson_table::KernelTable(); }
  static std::size_t Offset(int i, int j) { return dawson_table::KernelNodeOffset(i, j); }
};

template <class Tab>
const cd* NodeCoefficients(const cd* table, cd x, cd* delta) {
  // x is in the first quadrant: rounding by +0.5 truncation (cheaper than lround on this hot path).
  // Multiplication by 1/step rather than division: a point halfway between nodes may round to either, and
  // both are within the Taylor radius. For KernelTable, Im x <= Re x gives j <= i (rounding is monotonic).
  const int i = static_cast<int>(x.real() * kInvGridStep + 0.5);
  const int j = static_cast<int>(x.imag() * kInvGridStep + 0.5);
  *delta = x - cd(i * kGridStep, j * kGridStep);
  return table + Tab::Offset(i, j);
}

// Horner's rule in real arithmetic: std::complex multiplication carries a NaN/infinity recovery branch
// (C99 Annex G) on every step; the values here are finite, and the products are the same.
template <class Tab>
cd TableValue(cd x) {
  cd d;
  const cd* c = NodeCoefficients<Tab>(Tab::Data(), x, &d);
  const double dr = d.real(), di = d.imag();
  double pr = c[Tab::kTerms - 1].real(), pi = c[Tab::kTerms - 1].imag();
  for (int k = Tab::kTerms - 2; k >= 0; --k) {
    const double t = pr * dr - pi * di + c[k].real();
    pi = pr * di + pi * dr + c[k].imag();
    pr = t;
  }
  return {pr, pi};
}

// The same for L points at once, their Horner chains interleaved: each chain is a sequence of dependent
// multiply-adds (latency-bound), so independent chains fill the pipeline; the arithmetic per point is that
// of TableValue.
#if defined(__SSE2__)
// One complex Horner step p·d + c with p, c as [re, im] in one SSE2 register and d given as [dr, dr] and
// [−di, di]: [pr·dr + (−pi·di), pi·dr + pr·di] + c, the same products and sums (in the same order up to the
// exact commutation of one addition and an exact negation) as the scalar form, so the same bits, with half
// the arithmetic instructions (no FMA contraction in either: the build has no -mfma).
inline __m128d ComplexMulAdd(__m128d p, __m128d d_re, __m128d d_im_signed, __m128d c) {
  const __m128d swapped = _mm_shuffle_pd(p, p, 1);  // [pi, pr]
  return _mm_add_pd(_mm_add_pd(_mm_mul_pd(p, d_re), _mm_mul_pd(swapped, d_im_signed)), c);
}
inline __m128d Load(const cd* c) { return _mm_loadu_pd(reinterpret_cast<const double*>(c)); }
inline cd Store(__m128d v) {
  double out[2];
  _mm_storeu_pd(out, v);
  return {out[0], out[1]};
}
#endif

template <class Tab, int L>
void TableValuesN(const cd* x, cd* out) {
  constexpr int T = Tab::kTerms;
  const cd* table = Tab::Data();
  const cd* c[L];
#if defined(__SSE2__)
  __m128d d_re[L], d_im[L], p[L];
  for (int n = 0; n < L; ++n) {
    cd d;
    c[n] = NodeCoefficients<Tab>(table, x[n], &d);
    d_re[n] = _mm_set1_pd(d.real()), d_im[n] = _mm_set_pd(d.imag(), -d.imag());
    p[n] = Load(&c[n][T - 1]);
  }
  for (int k = T - 2; k >= 0; --k)
    for (int n = 0; n < L; ++n) p[n] = ComplexMulAdd(p[n], d_re[n], d_im[n], Load(&c[n][k]));
  for (int n = 0; n < L; ++n) out[n] = Store(p[n]);
#else
  double dr[L], di[L], pr[L], pi[L];
  for (int n = 0; n < L; ++n) {
    cd d;
    c[n] = NodeCoefficients<Tab>(table, x[n], &d);
    dr[n] = d.real(), di[n] = d.imag();
    pr[n] = c[n][T - 1].real(), pi[n] = c[n][T - 1].imag();
  }
  for (int k = T - 2; k >= 0; --k)
    for (int n = 0; n < L; ++n) {
      const double t = pr[n] * dr[n] - pi[n] * di[n] + c[n][k].real();
      pi[n] = pr[n] * di[n] + pi[n] * dr[n] + c[n][k].imag();
      pr[n] = t;
    }
  for (int n = 0; n < L; ++n) out[n] = cd(pr[n], pi[n]);
#endif
}

#if defined(__x86_64__) && defined(__GNUC__)
#define HULLOPT_AVX_TABLE 1
// The four-point forms again with two points per 256-bit AVX register (the lanes of points 0, 1 and of 2, 3
// side by side): per lane exactly the operations of the SSE2 form, so the same bits, at twice the arithmetic
// per instruction. Chosen at run time on processors with AVX (no FMA: none is enabled here).
__attribute__((target("avx"))) inline __m256d ComplexMulAdd256(__m256d p, __m256d d_re, __m256d d_im_signed,
                                                                __m256d c) {
  const __m256d swapped = _mm256_permute_pd(p, 0x5);  // [pi, pr] in each half
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(p, d_re), _mm256_mul_pd(swapped, d_im_signed)), c);
}
__attribute__((target("avx"))) inline __m256d Load2(const cd* lo, const cd* hi) {
  return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(reinterpret_cast<const double*>(lo))),
                              _mm_loadu_pd(reinterpret_cast<const double*>(hi)), 1);
}
__attribute__((target("avx"))) inline void Store2(__m256d v, cd* lo, cd* hi) {
  alignas(32) double out[4];
  _mm256_store_pd(out, v);
  *lo = cd(out[0], out[1]), *hi = cd(out[2], out[3]);
}

// The node offsets of points n and n + 1 as [dr, dr | dr', dr'] and [−di, di | −di', di'].
__attribute__((target("avx"))) inline void Offsets2(cd d0, cd d1, __m256d* d_re, __m256d* d_im) {
  *d_re = _mm256_set_pd(d1.real(), d1.real(), d0.real(), d0.real());
  *d_im = _mm256_set_pd(d1.imag(), -d1.imag(), d0.imag(), -d0.imag());
}


// P = 2H points, H registers: with H = 4 eight independent dependency chains, enough to hide the latency of a
// complex step (shuffle, multiply, two adds); with two registers it is latency-bound.
template <class Tab, int H>
__attribute__((target("avx"))) void TableValuesAvx(const cd* x, cd* out) {
  constexpr int T = Tab::kTerms;
  const cd* table = Tab::Data();
  const cd* c[2 * H];
  cd d[2 * H];
  for (int n = 0; n < 2 * H; ++n) c[n] = NodeCoefficients<Tab>(table, x[n], &d[n]);
  __m256d d_re[H], d_im[H], p[H];
  for (int h = 0; h < H; ++h) {
    Offsets2(d[2 * h], d[2 * h + 1], &d_re[h], &d_im[h]);
    p[h] = Load2(&c[2 * h][T - 1], &c[2 * h + 1][T - 1]);
  }
  for (int k = T - 2; k >= 0; --k)
    for (int h = 0; h < H; ++h) p[h] = ComplexMulAdd256(p[h], d_re[h], d_im[h], Load2(&c[2 * h][k], &c[2 * h + 1][k]));
  for (int h = 0; h < H; ++h) Store2(p[h], &out[2 * h], &out[2 * h + 1]);
}

// MakeTransientGreenPairsInFluid four at a time in 256-bit registers: per lane the operations of
// MakeTransientGreenPairInFluid and UnitArctangent (the sector chosen by masks, both reduced arguments
// computed), in the same order, so the same bits; returns how many pairs it made.
__attribute__((target("avx"))) int MakeTransientGreenPairsAvx(const double* Y, const double* Z, int n,
                                                               double half_sqrt_g, bool with_log,
                                                               TransientGreenPair* out) {
  const __m256d sign = _mm256_set1_pd(-0.0), zero = _mm256_setzero_pd(), half = _mm256_set1_pd(0.5);
  const __m256d one = _mm256_set1_pd(1.0), hsg = _mm256_set1_pd(half_sqrt_g);
  const __m256d tan_pi16 = _mm256_set1_pd(0.198912367379658), tan_3pi16 = _mm256_set1_pd(0.6681786379192989);
  const __m256d tan_pi8 = _mm256_set1_pd(0.41421356237309503);
  const __m256d pi8 = _mm256_set1_pd(0.39269908169872414), pi4 = _mm256_set1_pd(0.78539816339744828);
  int k = 0;
  for (; k + 3 < n; k += 4) {
    const __m256d y = _mm256_loadu_pd(Y + k), z = _mm256_loadu_pd(Z + k);
    const __m256d p = _mm256_xor_pd(z, sign), ya = _mm256_andnot_pd(sign, y);
    const __m256d r = _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(p, p), _mm256_mul_pd(ya, ya)));
    const __m256d scale = _mm256_div_pd(hsg, r);
    const __m256d r_plus_p = _mm256_add_pd(r, p);
    const __m256d wr = _mm256_mul_pd(scale, _mm256_sqrt_pd(_mm256_mul_pd(half, r_plus_p)));
    const __m256d wi =
        _mm256_mul_pd(scale, _mm256_sqrt_pd(_mm256_mul_pd(half, _mm256_max_pd(_mm256_sub_pd(r, p), zero))));
    alignas(32) double a_re[4], a_im[4], w_re[4], w_im[4], arg[4] = {0.0, 0.0, 0.0, 0.0};
    alignas(32) double log_abs[4] = {0.0, 0.0, 0.0, 0.0};
    _mm256_store_pd(a_re, p), _mm256_store_pd(a_im, _mm256_xor_pd(ya, sign));
    _mm256_store_pd(w_re, wr), _mm256_store_pd(w_im, wi);
    if (with_log) {
      // ½ ln|w|² (|w|² as std::norm: re·re + im·im).
      const __m256d norm = _mm256_add_pd(_mm256_mul_pd(wr, wr), _mm256_mul_pd(wi, wi));
      _mm256_store_pd(log_abs, _mm256_mul_pd(half, PositiveLogarithmAvx(norm)));
      const __m256d u = _mm256_div_pd(ya, r_plus_p);
      const __m256d high = _mm256_cmp_pd(u, tan_3pi16, _CMP_GT_OQ);
      const __m256d mid = _mm256_andnot_pd(high, _mm256_cmp_pd(u, tan_pi16, _CMP_GT_OQ));
      // v = (u − tan c)/(1 + u tan c) with tan c = 1, tan(π/8) or 0 per lane: one division, and the values of
      // UnitArctangent's three branches (u − 0 = u, 1 + u·0 = 1, u/1 = u, 1 + u·1 = u + 1 exactly).
      const __m256d tan_c = _mm256_or_pd(_mm256_and_pd(high, one), _mm256_and_pd(mid, tan_pi8));
      const __m256d v = _mm256_div_pd(_mm256_sub_pd(u, tan_c), _mm256_add_pd(one, _mm256_mul_pd(u, tan_c)));
      const __m256d c = _mm256_or_pd(_mm256_and_pd(high, pi4), _mm256_and_pd(mid, pi8));
      const __m256d s = _mm256_mul_pd(v, v);
      __m256d q = _mm256_set1_pd(-1.0 / 21);
      const double coef[9] = {1.0 / 19, -1.0 / 17, 1.0 / 15, -1.0 / 13, 1.0 / 11, -1.0 / 9, 1.0 / 7, -1.0 / 5, 1.0 / 3};
      for (double a : coef)  // p·s + 1/19, p·s − 1/17, ...: subtracting 1/17 is adding −1/17 exactly
        q = _mm256_add_pd(_mm256_mul_pd(q, s), _mm256_set1_pd(a));
      _mm256_store_pd(arg, _mm256_add_pd(c, _mm256_sub_pd(v, _mm256_mul_pd(_mm256_mul_pd(v, s), q))));
    }
    for (int m = 0; m < 4; ++m) {
      TransientGreenPair& o = out[k + m];
      o.a = cd(a_re[m], a_im[m]);
      o.w = cd(w_re[m], w_im[m]);
      o.log_w = with_log ? cd(log_abs[m], arg[m]) : cd(0.0);
      o.conj = Y[k + m] < 0;
    }
  }
  return k;
}

bool HasAvx() {
  static const bool has = __builtin_cpu_supports("avx");
  return has;
}
#endif

// P points (P = 4 or 8): the AVX form where the processor has it, else the SSE2 (or scalar) form; the same
// bits either way.
template <class Tab, int P>
void TableValuesP(const cd* x, cd* out) {
#ifdef HULLOPT_AVX_TABLE
  if (HasAvx()) return TableValuesAvx<Tab, P / 2>(x, out);
#endif
  for (int n = 0; n < P; n += 4) TableValuesN<Tab, 4>(x + n, out + n);
}


// Σ_{n>=1} c_n/(2n) x^{−2n}: the algebraic part of Φ − ½ ln x − (γ + ln 4)/4 (with a minus sign).
cd PhiAlgebraicSeries(cd x) {
  const auto& c = AsymptoticCoefficients();
  const cd inv2 = 1.0 / (x * x);
  cd p = inv2, series = 0.0;
  for (int n = 1; n <= kAsymptoticTerms; ++n, p *= inv2) {
    const cd add = c[n] / (2.0 * n) * p;
    series += add;
    if (std::norm(add) < 1e-34) break;  // |term| < 1e−17; terms fall monotonically until n ~ |x|² >= 36
  }
  return series;
}

// erfc(x) for 0 <= arg x <= π/4, |x| >= 6; |erfc(x)| <= e^{−Re x²}/(|x|√π) is below 1e−18 once Re x² > 40.
cd ErfcFirstQuadrant(cd x) {
  double er = 0, ei = 0;
  if ((x * x).real() < 40.0) hullopt_cerfc(x.real(), x.imag(), &er, &ei);
  return {er, ei};
}


void CheckAsymptoticSector(cd x) {
  if (x.imag() > x.real() * (1.0 + 1e-12))
    throw std::domain_error("Dawson integral: asymptotic form needs |arg x| <= pi/4, got arg " +
                            std::to_string(std::arg(x)));
}

}  // namespace

cd DawsonIntegral(cd x) {
  // Reduce to the first quadrant: Φ is even and real on the real axis.
  if (x.real() < 0) x = -x;
  const bool conj = x.imag() < 0;
  if (conj) x = std::conj(x);
  cd out;
  // std::norm, not std::abs: |x|² comparisons avoid a hypot call on this hot path.
  if (std::norm(x) < kAsymptoticRadius * kAsymptoticRadius) {
    out = TableValue<PhiTable>(x);
  } else {
    CheckAsymptoticSector(x);
    out = kPhiConstant + 0.5 * LogWithoutHypot(x) - PhiAlgebraicSeries(x) - kI * (M_PI / 4.0) * ErfcFirstQuadrant(x);
  }
  return ConjIf(conj, out);
}

TransientGreenValues TransientGreen(double Y, double Z, double t, double g) {
  CheckArguments(Y, Z, t, g);
  const bool conj = Y < 0;
  const Arg s = MakeArg(std::fabs(Y), Z, t, g);
  const cd x = s.x;
  const double sg = std::sqrt(g);
  cd F, one_minus_2xF, dz_bracket;  // F, 1 − 2xF, x + (1 − 2x²)F
  if (std::norm(x) < kAsymptoticRadius * kAsymptoticRadius) {
    F = Dawson(x);
    one_minus_2xF = 1.0 - 2.0 * x * F;
    dz_bracket = x + (1.0 - 2.0 * x * x) * F;
  } else {
    // F ~ Σ c_n x^{−(2n+1)} + E, E = i(√π/2) e^{−x²} (Im x >= 0):
    //   1 − 2xF ~ −Σ_{n>=1} 2 c_n x^{−2n} − 2xE,   x + (1 − 2x²)F ~ −Σ_{n>=1} 2n c_n x^{−(2n+1)} + (1 −
    //   2x²)E.
    const auto& c = AsymptoticCoefficients();
    const cd E = kI * (0.5 * kSqrtPi) * std::exp(-x * x);
    const cd inv = 1.0 / x, inv2 = inv * inv;
    cd p = inv;  // x^{−(2n+1)}
    cd sF = 0.0, sT = 0.0, sZ = 0.0;
    for (int n = 0; n <= kAsymptoticTerms; ++n, p *= inv2) {
      sF += c[n] * p;
      if (n >= 1) {
        sT += 2.0 * c[n] * p * x;
        sZ += 2.0 * n * c[n] * p;
      }
    }
    F = sF + E;
    one_minus_2xF = -sT - 2.0 * x * E;
    dz_bracket = -sZ + (1.0 - 2.0 * x * x) * E;
  }
  TransientGreenValues v;
  v.h = ConjIf(conj, 4.0 * sg * F / s.sqrt_a);
  v.h_t = ConjIf(conj, (2.0 * g / s.a) * one_minus_2xF);
  v.h_z = ConjIf(conj, (2.0 * sg / (s.a * s.sqrt_a)) * dz_bracket);
  return v;
}

cd TransientGreenTimeIntegral(double Y, double Z, double t, double g) {
  CheckArguments(Y, Z, t, g);
  return TransientGreenTimeIntegral(MakeTransientGreenPair(Y, Z, g), t);
}

namespace {

// K inside the table's radius from G at x (dawson_integral_table.h): 8a(G + x² ln x) in real arithmetic, the
// products and sums of std::complex's (a finite product is (ac − bd) + i(ad + bc)) without its NaN-recovery
// branches.
cd KFromTable(cd x, cd a, cd log_x, cd G) {
  const double x2r = x.real() * x.real() - x.imag() * x.imag(), x2i = x.real() * x.imag() + x.imag() * x.real();
  const double br = G.real() + (x2r * log_x.real() - x2i * log_x.imag());
  const double bi = G.imag() + (x2r * log_x.imag() + x2i * log_x.real());
  const double mr = 8.0 * a.real(), mi = 8.0 * a.imag();
  return {mr * br - mi * bi, mr * bi + mi * br};
}

// K at x for |Y| (first quadrant), with a = |Z| − i|Y| and ln x.
cd SpaceTimeIntegralFirstQuadrant(cd x, cd a, cd log_x) {
  cd K;
  if (std::norm(x) < kAsymptoticRadius * kAsymptoticRadius) {
    // K = −8a(Φ + xF) + 2gt²(ln x − 2Φ + 2C): dK/da = −8Φ (F' = 1 − 2xF, dx/da = −x/2a), so dK/dζc = 8Φ.
    // With gt² = 4a x² it is 8a(G(x) + x² ln x), G = −Φ − xF + 2x²(C − Φ) entire, from its own table (one
    // Horner chain). The constant 4C·gt² makes it the same function as the asymptotic form below; here
    // |x|² < 36, so the cancellation between G ~ −x² ln x and x² ln x costs at most ~2 digits.
    K = KFromTable(x, a, log_x, TableValue<KernelTable>(x));
  } else {
    // ln x − 2Φ + 2C = 2Σ c_n/(2n) x^{−2n} + i(π/2) erfc(x) with gt² = 4a x²: no gt²-sized cancellation left.
    CheckAsymptoticSector(x);
    const cd erfc = ErfcFirstQuadrant(x);
    const cd series = PhiAlgebraicSeries(x);
    const cd phi = kPhiConstant + 0.5 * log_x - series - kI * (M_PI / 4.0) * erfc;
    // F ~ Σ c_n x^{−(2n+1)} + i(√π/2) e^{−x²}; xF is needed.
    const auto& c = AsymptoticCoefficients();
    const cd inv2 = 1.0 / (x * x);
    cd p = 1.0, xf = 0.0;
    for (int n = 0; n <= kAsymptoticTerms; ++n, p *= inv2) {
      const cd add = c[n] * p;
      xf += add;
      if (n > 0 && std::norm(add) < 1e-34) break;
    }
    const cd x2 = x * x;
    // The two e^{−x²}-sized pieces, −8a·x·i(√π/2)e^{−x²} and 4πi a x² erfc(x), cancel at leading order; both
    // are kept (|e^{−x²}| <= 1 in this sector) and skipped together when negligible.
    const cd exp_part = (x2.real() < 40.0) ? x * kI * (0.5 * kSqrtPi) * std::exp(-x2) : cd(0.0);
    K = -8.0 * a * (phi + xf + exp_part) + 16.0 * a * x2 * series + 4.0 * M_PI * kI * a * x2 * erfc;
  }
  return K;
}

}  // namespace

TransientGreenPair MakeTransientGreenPair(double Y, double Z, double g, bool with_log) {
  CheckArguments(Y, Z, 0.0, g);
  return MakeTransientGreenPairInFluid(Y, Z, 0.5 * std::sqrt(g), with_log);
}

void MakeTransientGreenPairsInFluid(const double* Y, const double* Z, int n, double half_sqrt_g, bool with_log,
                                    TransientGreenPair* out) {
  int k = 0;
#ifdef HULLOPT_AVX_TABLE
  if (HasAvx()) k = MakeTransientGreenPairsAvx(Y, Z, n, half_sqrt_g, with_log, out);
#endif
  // The rest (and all of it without AVX) one at a time: independent iterations, which overlap anyway.
  for (; k < n; ++k) out[k] = MakeTransientGreenPairInFluid(Y[k], Z[k], half_sqrt_g, with_log);
}

cd TransientGreenTimeIntegral(const TransientGreenPair& pair, double t) {
  return ConjIf(pair.conj, 8.0 * DawsonIntegral(t * pair.w));
}

cd TransientGreenSpaceTimeIntegral(const TransientGreenPair& pair, double t, double log_t, double /*g*/) {
  // g enters through pair.w (gt² = 4a x²).
  const cd x = t * pair.w;
  return ConjIf(pair.conj, SpaceTimeIntegralFirstQuadrant(x, pair.a, cd(log_t, 0.0) + pair.log_w));
}

cd TransientGreenSpaceTimeIntegral(double Y, double Z, double t, double g) {
  CheckArguments(Y, Z, t, g);
  if (t == 0.0) return 0.0;
  return TransientGreenSpaceTimeIntegral(MakeTransientGreenPair(Y, Z, g), t, std::log(t), g);
}

}  // namespace hullopt::sk

namespace hullopt::sk {

namespace {

// The table forms for 2P points (P pairs at two lags): the SSE2 two-point form for one pair, the four- or
// eight-point form (AVX where available) for two or four.
template <class Tab, int P>
void TableGroup(const cd* x, cd* out) {
  if constexpr (P == 1) TableValuesN<Tab, 2>(x, out);
  else TableValuesP<Tab, 2 * P>(x, out);
}

// P pairs at two lags in one interleaved table call when every x is inside the table's radius; otherwise
// the two halves (down to one pair, whose points then go one at a time). out[2p + n] is pair[p] at t[n].
template <int P>
void TimeIntegralsGroup(const TransientGreenPair* pair, const double t[2], cd* out) {
  cd x[2 * P];
  for (int n = 0; n < 2 * P; ++n) x[n] = t[n % 2] * pair[n / 2].w;
  constexpr double r2 = kAsymptoticRadius * kAsymptoticRadius;
  for (int n = 0; n < 2 * P; ++n)
    if (!(std::norm(x[n]) < r2)) {
      if constexpr (P == 1) {
        for (int m = 0; m < 2; ++m) out[m] = TransientGreenTimeIntegral(pair[0], t[m]);
      } else {
        TimeIntegralsGroup<P / 2>(pair, t, out);
        TimeIntegralsGroup<P / 2>(pair + P / 2, t, out + P);
      }
      return;
    }
  TableGroup<PhiTable, P>(x, out);
  for (int n = 0; n < 2 * P; ++n) out[n] = ConjIf(pair[n / 2].conj, 8.0 * out[n]);
}

#ifdef HULLOPT_AVX_TABLE
// p·q for [re, im | re, im] registers with q given as [qr, qr | ...] and [−qi, qi | ...]: per lane the products
// and sum of the scalar (pr·qr − pi·qi, pr·qi + pi·qr) (the sums commute exactly), without ComplexMulAdd256's
// addition (which would turn a −0 into +0).
__attribute__((target("avx"))) inline __m256d ComplexMul256(__m256d p, __m256d q) {
  const __m256d q_re = _mm256_movedup_pd(q);
  const __m256d q_im = _mm256_xor_pd(_mm256_permute_pd(q, 0xF), _mm256_set_pd(0.0, -0.0, 0.0, -0.0));
  return _mm256_add_pd(_mm256_mul_pd(p, q_re), _mm256_mul_pd(_mm256_permute_pd(p, 0x5), q_im));
}

// SpaceTimeIntegralsGroup's table branch for P = 2 or 4 pairs in AVX registers, one pair's two lags per
// register: x = t·w, the radius test, G from the table and K = 8a(G + x² ln x) (KFromTable), per lane the
// scalar operations, so the same bits. Returns false, with nothing written, when a point is beyond the table's
// radius.
template <int P>
__attribute__((target("avx"))) bool SpaceTimeIntegralsAvx(const TransientGreenPair* pair, const double t[2],
                                                          const double log_t[2], cd* out) {
  const __m256d tt = _mm256_set_pd(t[1], t[1], t[0], t[0]);
  const __m256d r2 = _mm256_set1_pd(kAsymptoticRadius * kAsymptoticRadius);
  __m256d X[P];
  cd x[2 * P];
  int inside = 0xF;
  for (int p = 0; p < P; ++p) {
    X[p] = _mm256_mul_pd(tt, _mm256_broadcast_pd(reinterpret_cast<const __m128d*>(&pair[p].w)));
    const __m256d sq = _mm256_mul_pd(X[p], X[p]);
    inside &= _mm256_movemask_pd(_mm256_cmp_pd(_mm256_hadd_pd(sq, sq), r2, _CMP_LT_OQ));  // |x|² < r²
    Store2(X[p], &x[2 * p], &x[2 * p + 1]);
  }
  if (inside != 0xF) return false;
  cd G[2 * P];
  TableValuesAvx<KernelTable, P>(x, G);
  const __m256d lt = _mm256_set_pd(0.0, log_t[1], 0.0, log_t[0]), eight = _mm256_set1_pd(8.0);
  for (int p = 0; p < P; ++p) {
    const __m256d log_x = _mm256_add_pd(lt, _mm256_broadcast_pd(reinterpret_cast<const __m128d*>(&pair[p].log_w)));
    const __m256d b = _mm256_add_pd(ComplexMul256(ComplexMul256(X[p], X[p]), log_x), Load2(&G[2 * p], &G[2 * p + 1]));
    const __m256d m = _mm256_mul_pd(eight, _mm256_broadcast_pd(reinterpret_cast<const __m128d*>(&pair[p].a)));
    __m256d k = ComplexMul256(b, m);
    if (pair[p].conj) k = _mm256_xor_pd(k, _mm256_set_pd(-0.0, 0.0, -0.0, 0.0));
    Store2(k, &out[2 * p], &out[2 * p + 1]);
  }
  return true;
}
#endif

template <int P>
void SpaceTimeIntegralsGroup(const TransientGreenPair* pair, const double t[2], const double log_t[2], double g,
                             cd* out) {
#ifdef HULLOPT_AVX_TABLE
  if constexpr (P > 1)
    if (HasAvx() && SpaceTimeIntegralsAvx<P>(pair, t, log_t, out)) return;
#endif
  cd x[2 * P];
  for (int n = 0; n < 2 * P; ++n) x[n] = t[n % 2] * pair[n / 2].w;
  constexpr double r2 = kAsymptoticRadius * kAsymptoticRadius;
  for (int n = 0; n < 2 * P; ++n)
    if (!(std::norm(x[n]) < r2)) {
      if constexpr (P == 1) {
        for (int m = 0; m < 2; ++m) out[m] = TransientGreenSpaceTimeIntegral(pair[0], t[m], log_t[m], g);
      } else {
        SpaceTimeIntegralsGroup<P / 2>(pair, t, log_t, g, out);
        SpaceTimeIntegralsGroup<P / 2>(pair + P / 2, t, log_t, g, out + P);
      }
      return;
    }
  cd G[2 * P];
  TableGroup<KernelTable, P>(x, G);
  for (int n = 0; n < 2 * P; ++n) {
    const TransientGreenPair& pr = pair[n / 2];
    out[n] = ConjIf(pr.conj, KFromTable(x[n], pr.a, cd(log_t[n % 2], 0.0) + pr.log_w, G[n]));
  }
}

}  // namespace

void TransientGreenTimeIntegrals2(const TransientGreenPair& pair, const double t[2], cd out[2]) {
  TimeIntegralsGroup<1>(&pair, t, out);
}
void TransientGreenSpaceTimeIntegrals2(const TransientGreenPair& pair, const double t[2], const double log_t[2],
                                       double g, cd out[2]) {
  SpaceTimeIntegralsGroup<1>(&pair, t, log_t, g, out);
}
void TransientGreenTimeIntegrals2x2(const TransientGreenPair pair[2], const double t[2], cd out[4]) {
  TimeIntegralsGroup<2>(pair, t, out);
}
void TransientGreenSpaceTimeIntegrals2x2(const TransientGreenPair pair[2], const double t[2], const double log_t[2],
                                         double g, cd out[4]) {
  SpaceTimeIntegralsGroup<2>(pair, t, log_t, g, out);
}
void TransientGreenTimeIntegrals4x2(const TransientGreenPair pair[4], const double t[2], cd out[8]) {
  TimeIntegralsGroup<4>(pair, t, out);
}
void TransientGreenSpaceTimeIntegrals4x2(const TransientGreenPair pair[4], const double t[2], const double log_t[2],
                                         double g, cd out[8]) {
  SpaceTimeIntegralsGroup<4>(pair, t, log_t, g, out);
}

}  // namespace hullopt::sk
