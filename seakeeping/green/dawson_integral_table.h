#pragma once
// The table of the Dawson integral Φ(x) = ∫_0^x F(u) du (F the complex Dawson function) from which the transient
// Green function takes Φ and F below |x| = 6 (seakeeping/green/transient_green.cpp).
//
// Grid x = (i + i·j)·h, 0 <= i, j <= N, covering the first quadrant of |x| < 6. Between nodes
// Φ(x0 + δ) = Φ(x0) + Σ_k F⁽ᵏ⁾(x0) δ^{k+1}/(k+1)!, with F' = 1 − 2xF and F⁽ᵏ⁺¹⁾ = −2x F⁽ᵏ⁾ − 2k F⁽ᵏ⁻¹⁾. With
// h = 0.05, |δ| <= 0.036 and 2|x||δ| <= 0.43, 11 terms reach a few 1e−15 relative (measured against quadrature of
// F over the quadrant: 9 terms 1e−12, 10 terms 3e−14); a 0.1 grid needed 18, and the shorter Horner chain
// outweighs the larger table (3 MB, ~1.2 MB of it in the sector 0 <= arg x <= π/4 the kernel uses). The Taylor
// coefficients c_0 = Φ(x0), c_{k+1} = F⁽ᵏ⁾(x0)/(k+1)! are stored per node, so that evaluation is Horner's rule
// (Φ = Σ c_k δ^k, F = Φ' = Σ k c_k δ^{k−1}).
//
// The table is computed once, when hullopt is built: the build tool hullopt_make_dawson_table
// (tools/make_dawson_table.cpp) writes the bytes of ComputeDawsonIntegralTable() and
// dawson_integral_table_data.c embeds them into the library, so no process spends its start-up on it
// (computing it takes ~15 000 libcerf calls, a few ms). tests/unit/test_dawson_integral_table.cpp checks the
// embedded table against ComputeDawsonIntegralTable() bit for bit.
//
// A second table, after the first, serves the space-time integral K of the transient Green function
// (transient_green.h): K = 8a(G(x) + x² ln x) with the entire function
//   G(x) = −Φ − xF + 2x²(C − Φ),   C = (γ + ln 4)/4,   G' = −2F − x(1 + 4(Φ − C)),   G'' = 4C − 3 − 4Φ,
// so that G's Taylor coefficients about a node are those of Φ divided by (k + 1)(k + 2) (shifted by two):
//   G(x0 + δ) = G0 + G1 δ + δ²(2C − 3/2 − 2c_0) + Σ_{k>=1} (−4 c_k/((k + 1)(k + 2))) δ^{k+2}.
// One Horner chain gives K where Φ and F took two; the division by (k + 1)(k + 2) makes the series converge two
// orders faster, so 8 of Φ's terms (11 coefficients) reach the round-off of the bracket G + x² ln x (a few
// 1e−14 of max(1, |G + x² ln x|), measured against Φ from the first table and F from libcerf; the Φ-and-F form
// it replaces reached ~9e−14). The kernel uses it only for 0 <= arg x <= π/4 (x = t·w, Re w >= Im w), where
// the nearest node has j <= i: the nodes are stored for j <= i only (row i holds i + 1 nodes).
#include <complex>
#include <cstddef>
#include <vector>

/// The embedded table (dawson_integral_table_data.c) as doubles, real and imaginary parts in turn.
extern "C" __attribute__((visibility("hidden"))) const double hullopt_dawson_integral_table[];
extern "C" __attribute__((visibility("hidden"))) const double hullopt_dawson_integral_table_end[];

namespace hullopt::sk::dawson_table {

constexpr double kGridStep = 0.05;
constexpr double kInvGridStep = 20.0;
constexpr int kGridN = 122;
constexpr int kTaylorTerms = 11;
constexpr int kCoefficients = kTaylorTerms + 2;  // c_0 .. c_{T+1}
constexpr std::size_t kValues = static_cast<std::size_t>((kGridN + 1) * (kGridN + 1) * kCoefficients);

/// Offset of node (i, j)'s first coefficient: the table is node-major, kCoefficients per node.
constexpr std::size_t NodeOffset(int i, int j) {
  return static_cast<std::size_t>((i * (kGridN + 1) + j) * kCoefficients);
}

/// The second table (G, for K): Φ's first kKernelTerms + 1 coefficients c_0 .. c_8 make kKernelCoefficients
/// Horner coefficients per node (G0, G1, the δ² one, then one per c_k, k >= 1), nodes 0 <= j <= i <= kGridN.
constexpr int kKernelTerms = 8;
constexpr int kKernelCoefficients = kKernelTerms + 3;
constexpr std::size_t kKernelNodes = static_cast<std::size_t>((kGridN + 1) * (kGridN + 2) / 2);
constexpr std::size_t kKernelValues = kKernelNodes * kKernelCoefficients;

/// Offset of node (i, j), j <= i, in the second table: rows of i + 1 nodes one after another.
constexpr std::size_t KernelNodeOffset(int i, int j) {
  return static_cast<std::size_t>((i * (i + 1) / 2 + j) * kKernelCoefficients);
}

/// C = (γ + ln 4)/4: Φ(x) − ½ ln x → C as x → +∞.
constexpr double kPhiConstant = (0.57721566490153286060651209 + 1.38629436111989061883446424) / 4.0;

/// The embedded table of Φ, kValues complex values.
inline const std::complex<double>* Table() {
  return reinterpret_cast<const std::complex<double>*>(hullopt_dawson_integral_table);
}

/// The embedded table of G (for K), kKernelValues complex values, right after Φ's.
inline const std::complex<double>* KernelTable() { return Table() + kValues; }

/// The tables computed now, Φ's (kValues) followed by G's (kKernelValues): F and its derivatives from libcerf
/// at every node (the only special-function calls), then Φ by integrating F along the real axis and up each
/// column (each step adds ~1e−16 relative), then G's coefficients from Φ's.
std::vector<std::complex<double>> ComputeDawsonIntegralTable();

}  // namespace hullopt::sk::dawson_table
