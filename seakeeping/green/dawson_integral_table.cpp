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
  // G's coefficients (dawson_integral_table.h) from Φ's: G0 = −c_0 − x0 c_1 + 2x0²(C − c_0),
  // G1 = −2c_1 − x0(1 + 4(c_0 − C)), the δ² coefficient 2C − 3/2 − 2c_0, then −4c_k/((k + 1)(k + 2)).
  std::vector<cd> out = std::move(t.coef);
  out.resize(kValues + kKernelValues);
  for (int i = 0; i <= kGridN; ++i)
    for (int j = 0; j <= i; ++j) {
      const cd x0(i * kGridStep, j * kGridStep);
      const cd* c = &out[NodeOffset(i, j)];
      cd* e = &out[kValues + KernelNodeOffset(i, j)];
      e[0] = -c[0] - x0 * c[1] + 2.0 * x0 * x0 * (kPhiConstant - c[0]);
      e[1] = -2.0 * c[1] - x0 * (1.0 + 4.0 * (c[0] - kPhiConstant));
      e[2] = (2.0 * kPhiConstant - 1.5) - 2.0 * c[0];
      for (int k = 1; k <= kKernelTerms; ++k) e[k + 2] = (-4.0 / ((k + 1) * (k + 2))) * c[k];
    }
  return out;
}

}  // namespace hullopt::sk::dawson_table
