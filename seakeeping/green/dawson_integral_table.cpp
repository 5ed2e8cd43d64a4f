#include "seakeeping/green/dawson_integral_table.h"

#include "seakeeping/green/cerf_wrap.h"

namespace hullopt::sk::dawson_table {
namespace {

using cd = std::complex<double>;

struct Builder {
  std::vector<cd> coef = std::vector<cd>(kValues);
  cd* At(int i, int j) { return &coef[NodeOffset(i, j)]; }
  // Σ_{k>=1} c_k δ^k = Φ(x0 + δ) − Φ(x0) from the node's F coefficients.
  static cd Increment(const cd* c, cd d) {
    cd sum = c[kCoefficients - 1];
    for (int k = kCoefficients - 2; k >= 1; --k) sum = sum * d + c[k];
    return sum * d;
  }
  // Φ at node (i, j) from Φ at its neighbour (i0, j0): the integral of F over each half of the step from the
  // Taylor series of the nearer node (|δ| = h/2, inside the series' accuracy radius).
  void Step(int i0, int j0, int i, int j) {
    const cd d(0.5 * (i - i0) * kGridStep, 0.5 * (j - j0) * kGridStep);
    cd* c = At(i, j);
    c[0] = At(i0, j0)[0] + Increment(At(i0, j0), d) - Increment(c, -d);
  }
};

}  // namespace

std::vector<cd> ComputeDawsonIntegralTable() {
  Builder t;
  for (int i = 0; i <= kGridN; ++i)
    for (int j = 0; j <= kGridN; ++j) {
      const cd x(i * kGridStep, j * kGridStep);
      cd* c = t.At(i, j);
      double fr = 0, fi = 0;
      hullopt_cdawson(x.real(), x.imag(), &fr, &fi);
      cd fk_prev(fr, fi), fk = 1.0 - 2.0 * x * fk_prev;  // F⁽⁰⁾, F⁽¹⁾
      double factorial = 1.0;                           // (k+1)!
      c[1] = fk_prev;
      for (int k = 1; k <= kTaylorTerms; ++k) {
        factorial *= (k + 1);
        c[k + 1] = fk / factorial;
        const cd next = -2.0 * x * fk - 2.0 * k * fk_prev;
        fk_prev = fk;
        fk = next;
      }
    }
  t.At(0, 0)[0] = 0.0;  // Φ(0)
  for (int i = 1; i <= kGridN; ++i) t.Step(i - 1, 0, i, 0);
  for (int i = 0; i <= kGridN; ++i)
    for (int j = 1; j <= kGridN; ++j) t.Step(i, j - 1, i, j);
  return std::move(t.coef);
}

}  // namespace hullopt::sk::dawson_table
