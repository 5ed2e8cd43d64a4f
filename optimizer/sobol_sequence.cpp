#include "optimizer/sobol_sequence.h"

#include <stdexcept>
#include <string>

namespace hullopt::opt {
namespace {
constexpr int kBits = 32;
// Joe–Kuo new-joe-kuo-6.21201, dimensions 2..16: degree s, coefficient a, initial m_1..m_s.
struct Primitive {
  int s;
  unsigned a;
  unsigned m[6];
};
constexpr Primitive kJoeKuo[SobolSequence::kMaxDimension - 1] = {
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
    {5, 4, {1, 1, 5, 5, 5}},
    {5, 7, {1, 1, 7, 11, 19}},
    {5, 11, {1, 1, 5, 1, 1}},
    {5, 13, {1, 1, 1, 3, 11}},
    {5, 14, {1, 3, 5, 5, 31}},
    {6, 1, {1, 3, 3, 9, 7, 49}},
    {6, 13, {1, 1, 1, 15, 21, 21}},
    {6, 16, {1, 3, 1, 13, 27, 49}},
};
}  // namespace

SobolSequence::SobolSequence(int dimension) : dimension_(dimension), v_(dimension * kBits) {
  if (dimension < 1 || dimension > kMaxDimension) {
    throw std::invalid_argument("Sobol sequence: dimension " + std::to_string(dimension) + " outside [1, " +
                                std::to_string(kMaxDimension) + "]");
  }
  // Dimension 1: all m_k = 1 (van der Corput in base 2).
  for (int k = 0; k < kBits; ++k) v_[k] = 1u << (kBits - 1 - k);
  for (int d = 1; d < dimension; ++d) {
    const Primitive& p = kJoeKuo[d - 1];
    std::uint32_t* v = &v_[d * kBits];
    // v[k] (k = 0-based bit) = m_{k+1} · 2^(32 − k − 1).
    for (int k = 0; k < p.s && k < kBits; ++k) v[k] = p.m[k] << (kBits - 1 - k);
    for (int k = p.s; k < kBits; ++k) {
      v[k] = v[k - p.s] ^ (v[k - p.s] >> p.s);
      for (int j = 1; j <= p.s - 1; ++j) {
        if ((p.a >> (p.s - 1 - j)) & 1u) v[k] ^= v[k - j];
      }
    }
  }
}

std::vector<double> SobolSequence::Point(std::uint64_t index) const {
  const std::uint64_t gray = index ^ (index >> 1);
  std::vector<double> x(dimension_);
  for (int d = 0; d < dimension_; ++d) {
    std::uint32_t acc = 0;
    for (int k = 0; k < kBits; ++k)
      if ((gray >> k) & 1u) acc ^= v_[d * kBits + k];
    x[d] = static_cast<double>(acc) * 0x1.0p-32;
  }
  return x;
}

}  // namespace hullopt::opt
