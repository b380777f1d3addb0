#pragma once
// Seeded random numbers for the game (arena layout, AI choices). Our own SplitMix64 so the same seed gives the
// same numbers with any standard library (std::uniform_*_distribution is implementation-defined).
#include <cstdint>

namespace boxing {

class Rng {
 public:
  explicit Rng(uint64_t seed) : s_(seed) {}
  uint64_t next_u64() {
    // SplitMix64 (Steele, Lea & Flood 2014).
    uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int below(int n) { return static_cast<int>(uniform() * n); }

 private:
  uint64_t s_;
};

}  // namespace boxing
