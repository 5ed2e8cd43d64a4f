#pragma once
// A small, portable seeded random stream (SplitMix64). The standard library's distributions differ between
// implementations; campaigns must give the same start points and samples on every platform, so the uniform
// doubles are produced here bit-exactly.
#include <cstdint>

namespace hullopt::opt {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : state_(seed) {}
  /// Next 64 random bits (SplitMix64, Steele, Lea & Flood 2014).
  std::uint64_t NextBits() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1) with 53 random bits.
  double Uniform() { return static_cast<double>(NextBits() >> 11) * 0x1.0p-53; }
  /// Uniform integer in [0, n) (n > 0); the tiny modulo bias is irrelevant for shuffling samples.
  std::uint64_t Below(std::uint64_t n) { return NextBits() % n; }

 private:
  std::uint64_t state_;
};

}  // namespace hullopt::opt
