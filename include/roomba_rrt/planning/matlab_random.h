// A uniform random stream that reproduces MATLAB's default generator.
#pragma once

#include <cstdint>
#include <random>

namespace roomba_rrt::planning {

/// MATLAB's `rng(seed, 'twister'); rand()`: MT19937 seeded with `seed` (MATLAB maps seed 0 to
/// 5489, the reference seed of MT19937, and so does this class), and each double built from two
/// 32-bit outputs a, b as ((a >> 5) * 2^26 + (b >> 6)) / 2^53 — a value in [0, 1) with 53 random
/// bits. `rng(0); rand()` is 0.8147236863931789 in both.
class MatlabRandom {
 public:
  explicit MatlabRandom(std::uint32_t seed = 0) : engine_(seed == 0 ? 5489u : seed) {}

  /// The next `rand()`.
  double uniform() {
    const std::uint32_t a = static_cast<std::uint32_t>(engine_()) >> 5;
    const std::uint32_t b = static_cast<std::uint32_t>(engine_()) >> 6;
    return (a * 67108864.0 + b) / 9007199254740992.0;
  }

  /// `lo + (hi - lo) * rand()`, as the lab writes it.
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::mt19937 engine_;
};

}  // namespace roomba_rrt::planning
