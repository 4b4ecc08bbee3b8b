// The uniform stream a plan draws from: MATLAB's (the lab's answers, bit for bit) or a small fast
// generator for every plan that does not need to match MATLAB.
#pragma once

#include <cstdint>
#include <optional>

#include "roomba_rrt/planning/lab/matlab_random.h"
#include "roomba_rrt/planning/planner_options.h"

namespace roomba_rrt::planning {

/// xoshiro256+ (Blackman and Vigna, "Scrambled linear pseudorandom number generators", 2021), the
/// generator its authors recommend for floating-point numbers: 256 bits of state, period 2^256 − 1,
/// a double from the upper 53 bits of one 64-bit output. Its state is filled from the seed by
/// SplitMix64, as they recommend, so seeding is four multiplications instead of MT19937's chain of
/// 623 (1.3 µs, more than a whole plan in the furnished room). Not MATLAB's stream: plans drawn
/// from it are as random, but not the lab's.
class FastRandom {
 public:
  explicit FastRandom(std::uint64_t seed = 0) {
    for (std::uint64_t& word : s_) word = splitMix64(seed);
  }

  /// Uniform in [0, 1), a multiple of 2^-53.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// `lo + (hi - lo) * uniform()`, as MatlabRandom's.
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  /// The next 64-bit output.
  std::uint64_t next() {
    const std::uint64_t result = s_[0] + s_[3];
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = (s_[3] << 45) | (s_[3] >> 19);
    return result;
  }

 private:
  /// Advances `x` and returns the next SplitMix64 output (never four zeros in a row).
  static std::uint64_t splitMix64(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
  }

  std::uint64_t s_[4];
};

/// What the planners draw from: either stream, chosen once per plan (PlannerOptions::stream), or a
/// MATLAB stream the caller keeps across plans (rrt_monte_carlo's runs continue one, as MATLAB's
/// rng(seed) once does). The choice is one well-predicted branch per draw; neither stream changes
/// the other's numbers. Not copyable: it may point into itself.
class PlanRandom {
 public:
  PlanRandom(std::uint32_t seed, RandomStream stream) : fast_(seed) {
    if (stream == RandomStream::kMatlab) lab_ = &own_lab_.emplace(seed);
  }
  /// Continues `lab`, which must outlive this object.
  explicit PlanRandom(MatlabRandom& lab) : lab_(&lab) {}
  PlanRandom(const PlanRandom&) = delete;
  PlanRandom& operator=(const PlanRandom&) = delete;

  double uniform() { return lab_ != nullptr ? lab_->uniform() : fast_.uniform(); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  RandomStream stream() const {
    return lab_ != nullptr ? RandomStream::kMatlab : RandomStream::kFast;
  }

 private:
  MatlabRandom* lab_ = nullptr;  ///< the MATLAB stream drawn from; nullptr: fast_
  FastRandom fast_;
  std::optional<MatlabRandom> own_lab_;  ///< seeded only when this object owns the MATLAB stream
};

}  // namespace roomba_rrt::planning
