// A uniform random stream that reproduces MATLAB's default generator.
#pragma once

#include <array>
#include <cstdint>

namespace roomba_rrt::planning {

/// MATLAB's `rng(seed, 'twister'); rand()`: MT19937 seeded with `seed` (MATLAB maps seed 0 to
/// 5489, the reference seed of MT19937, and so does this class), and each double built from two
/// 32-bit outputs a, b as ((a >> 5) * 2^26 + (b >> 6)) / 2^53 — a value in [0, 1) with 53 random
/// bits. `rng(0); rand()` is 0.8147236863931789 in both.
///
/// The generator is MT19937 exactly as std::mt19937 (the same seeding, twist and tempering, so
/// the same 32-bit outputs in the same order; a test compares the two), written out here for
/// speed: a plan draws a few thousand numbers, so the per-number cost shows. MT19937 works in
/// batches anyway: every 624 outputs it "twists" its whole state. This class twists and then
/// tempers all 624 outputs in two simple loops over arrays, which the compiler turns into SIMD
/// code, and a rand() is then just two array reads and the conversion to double.
class MatlabRandom {
 public:
  explicit MatlabRandom(std::uint32_t seed = 0) {
    // MT19937's init_genrand (the std::mt19937 constructor).
    state_[0] = seed == 0 ? 5489u : seed;
    for (std::uint32_t i = 1; i < kN; ++i) {
      state_[i] = 1812433253u * (state_[i - 1] ^ (state_[i - 1] >> 30)) + i;
    }
  }

  /// The next `rand()`.
  double uniform() {
    // Outputs are consumed in pairs and 624 is even, so a pair never straddles two batches.
    if (next_ == kN) refill();
    const std::uint32_t a = output_[next_] >> 5;
    const std::uint32_t b = output_[next_ + 1] >> 6;
    next_ += 2;
    return (a * 67108864.0 + b) / 9007199254740992.0;
  }

  /// `lo + (hi - lo) * rand()`, as the lab writes it.
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  static constexpr std::uint32_t kN = 624, kM = 397;

  /// Twists the state (the next 624 words of the recurrence) and tempers them into output_.
  void refill() {
    auto twisted = [](std::uint32_t current, std::uint32_t next, std::uint32_t far) {
      const std::uint32_t y = (current & 0x80000000u) | (next & 0x7fffffffu);
      return far ^ (y >> 1) ^ (0x9908b0dfu & (0u - (y & 1u)));  // y odd: xor the matrix row
    };
    std::uint32_t* s = state_.data();
    for (std::uint32_t k = 0; k < kN - kM; ++k) s[k] = twisted(s[k], s[k + 1], s[k + kM]);
    for (std::uint32_t k = kN - kM; k < kN - 1; ++k) {
      s[k] = twisted(s[k], s[k + 1], s[k + kM - kN]);
    }
    s[kN - 1] = twisted(s[kN - 1], s[0], s[kM - 1]);
    for (std::uint32_t k = 0; k < kN; ++k) {
      std::uint32_t y = s[k];
      y ^= y >> 11;
      y ^= (y << 7) & 0x9d2c5680u;
      y ^= (y << 15) & 0xefc60000u;
      output_[k] = y ^ (y >> 18);
    }
    next_ = 0;
  }

  std::array<std::uint32_t, kN> state_;
  std::array<std::uint32_t, kN> output_;
  std::uint32_t next_ = kN;  ///< next unread output; kN: twist first
};

}  // namespace roomba_rrt::planning
