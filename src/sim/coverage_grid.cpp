#include "roomba_rrt/sim/coverage_grid.h"

#include <algorithm>
#include <cmath>

namespace roomba_rrt::sim {

namespace {

constexpr int kBitsPerWord = 64;

bool insideFurniture(const World& world, double x, double y) {
  for (const Circle& c : world.circles) {
    if (std::hypot(x - c.x, y - c.y) <= c.radius) return true;
  }
  for (const Rectangle& box : world.rectangles) {
    if (x >= box.min_x && x <= box.max_x && y >= box.min_y && y <= box.max_y) return true;
  }
  return false;
}

/// Bits first..last (inclusive) of one 64-bit word.
std::uint64_t spanMask(int first, int last) {
  const std::uint64_t upto_last = last == kBitsPerWord - 1 ? ~0ULL : (1ULL << (last + 1)) - 1;
  return upto_last & ~((1ULL << first) - 1);
}

}  // namespace

CoverageGrid::CoverageGrid(const World& world)
    : cell_(world.coverage_cell_size),
      columns_(static_cast<int>(std::ceil(world.width / cell_ - 1e-9))),
      rows_(static_cast<int>(std::ceil(world.height / cell_ - 1e-9))),
      words_per_row_((columns_ + kBitsPerWord - 1) / kBitsPerWord),
      free_(static_cast<std::size_t>(rows_) * words_per_row_, 0),
      swept_(free_.size(), 0) {
  for (int row = 0; row < rows_; ++row) {
    const double y = (row + 0.5) * cell_;
    for (int column = 0; column < columns_; ++column) {
      const double x = (column + 0.5) * cell_;
      if (x > world.width || y > world.height || insideFurniture(world, x, y)) continue;
      free_[row * words_per_row_ + column / kBitsPerWord] |= 1ULL << (column % kBitsPerWord);
      ++free_count_;
    }
  }
}

void CoverageGrid::markDisc(double x, double y, double r) {
  // Rows whose centre line (row + 0.5)·c is within r of y.
  const int first_row = std::max(0, static_cast<int>(std::ceil((y - r) / cell_ - 0.5)));
  const int last_row = std::min(rows_ - 1, static_cast<int>(std::floor((y + r) / cell_ - 0.5)));
  for (int row = first_row; row <= last_row; ++row) {
    const double dy = (row + 0.5) * cell_ - y;
    const double half_chord2 = r * r - dy * dy;
    if (half_chord2 < 0) continue;
    const double half_chord = std::sqrt(half_chord2);
    const int first = std::max(0, static_cast<int>(std::ceil((x - half_chord) / cell_ - 0.5)));
    const int last =
        std::min(columns_ - 1, static_cast<int>(std::floor((x + half_chord) / cell_ - 0.5)));
    std::uint64_t* swept = &swept_[row * words_per_row_];
    const std::uint64_t* free = &free_[row * words_per_row_];
    for (int word = first / kBitsPerWord; word <= last / kBitsPerWord && first <= last; ++word) {
      const int lo = std::max(first, word * kBitsPerWord) - word * kBitsPerWord;
      const int hi = std::min(last, word * kBitsPerWord + kBitsPerWord - 1) - word * kBitsPerWord;
      const std::uint64_t fresh = spanMask(lo, hi) & ~swept[word];
      swept_free_count_ += __builtin_popcountll(fresh & free[word]);
      swept[word] |= fresh;
    }
  }
}

void CoverageGrid::clear() {
  std::fill(swept_.begin(), swept_.end(), 0);
  swept_free_count_ = 0;
}

double CoverageGrid::coverage() const {
  return free_count_ > 0 ? static_cast<double>(swept_free_count_) / free_count_ : 0.0;
}

bool CoverageGrid::test(const std::vector<std::uint64_t>& bits, int column, int row) const {
  if (column < 0 || row < 0 || column >= columns_ || row >= rows_) return false;
  return (bits[row * words_per_row_ + column / kBitsPerWord] >> (column % kBitsPerWord)) & 1ULL;
}

}  // namespace roomba_rrt::sim
