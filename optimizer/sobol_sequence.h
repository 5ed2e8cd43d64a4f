#pragma once
// Sobol low-discrepancy sequence in up to 16 dimensions with the Joe–Kuo direction numbers
// (new-joe-kuo-6.21201; S. Joe and F. Y. Kuo, SIAM J. Sci. Comput. 30 (2008) 2635–2654), Gray-code order
// (Antonov–Saleev), 32-bit resolution. Points are computed directly from their index, so any process can
// produce any point (MPI ranks, resume).
#include <cstdint>
#include <vector>

namespace hullopt::opt {

class SobolSequence {
 public:
  static constexpr int kMaxDimension = 16;
  /// Throws std::invalid_argument unless 1 <= dimension <= kMaxDimension.
  explicit SobolSequence(int dimension);
  int dimension() const { return dimension_; }
  /// Point `index` of the sequence in [0, 1)^d; index 0 is the origin.
  std::vector<double> Point(std::uint64_t index) const;

 private:
  int dimension_;
  std::vector<std::uint32_t> v_;  // direction numbers, v_[d * 32 + bit]
};

}  // namespace hullopt::opt
