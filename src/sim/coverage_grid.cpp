#include "roomba_rrt/sim/coverage_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace roomba_rrt::sim {

namespace {

constexpr int kBitsPerWord = 64;

bool insideFurniture(const world::World& world, double x, double y) {
  if (world.room.map && world.room.map->blocked(world.room.map->column(x), world.room.map->row(y)))
    return true;
  for (const geometry::Circle& c : world.room.circles) {
    if (std::hypot(x - c.center.x, y - c.center.y) <= c.radius) return true;
  }
  for (const geometry::Rectangle& box : world.room.rectangles) {
    if (geometry::contains(box, {x, y})) return true;
  }
  return false;
}

// floor and ceil without a libm call (the baseline x86-64 target has no SSE4.1 rounding), for
// the values near the grid's range this code needs.
int floorToInt(double v) {
  const int i = static_cast<int>(v);
  return i - (i > v);
}
int ceilToInt(double v) {
  const int i = static_cast<int>(v);
  return i + (i < v);
}

/// Number of set bits; a moving disc adds only a few cells per row, so this loop is short (and
/// needs no popcnt instruction, which the baseline x86-64 target lacks).
int countBits(std::uint64_t bits) {
  int count = 0;
  for (; bits != 0; bits &= bits - 1) ++count;
  return count;
}

/// Bits first..last (inclusive) of one 64-bit word.
std::uint64_t spanMask(int first, int last) {
  const std::uint64_t upto_last = last == kBitsPerWord - 1 ? ~0ULL : (1ULL << (last + 1)) - 1;
  return upto_last & ~((1ULL << first) - 1);
}

}  // namespace

CoverageGrid::CoverageGrid(const world::World& world)
    : cell_(world.coverage_cell_size),
      inverse_cell_(1.0 / cell_),
      origin_(world.room.origin),
      columns_(static_cast<int>(std::ceil(world.room.width / cell_ - 1e-9))),
      rows_(static_cast<int>(std::ceil(world.room.height / cell_ - 1e-9))),
      words_per_row_((columns_ + kBitsPerWord - 1) / kBitsPerWord),
      free_(static_cast<std::size_t>(rows_) * words_per_row_, 0),
      swept_(free_.size(), 0) {
  for (int row = 0; row < rows_; ++row) {
    const double y = origin_.y + (row + 0.5) * cell_;
    for (int column = 0; column < columns_; ++column) {
      const double x = origin_.x + (column + 0.5) * cell_;
      if (x > origin_.x + world.room.width || y > origin_.y + world.room.height ||
          insideFurniture(world, x, y)) {
        continue;
      }
      free_[row * words_per_row_ + column / kBitsPerWord] |= 1ULL << (column % kBitsPerWord);
      ++free_count_;
    }
  }
}

void CoverageGrid::markDisc(double x, double y, double r) {
  // In cell units, cell (i, j) has its centre at (i + 0.5, j + 0.5).
  const double cx = (x - origin_.x) * inverse_cell_ - 0.5;
  const double cy = (y - origin_.y) * inverse_cell_ - 0.5;
  const double cr = r * inverse_cell_;
  if (!(std::isfinite(cx) && std::isfinite(cy) && cr >= 0 && cr < 1e6)) return;
  // Rows whose centre line is within r of y (clamped before converting, so far-away discs are
  // safe).
  const int last_row = std::min(rows_ - 1, floorToInt(std::clamp(cy + cr, -1.0, double(rows_))));
  for (int first_row = std::max(0, ceilToInt(std::clamp(cy - cr, -1.0, double(rows_))));
       first_row <= last_row; first_row += kRowsPerBatch) {
    markRows(first_row, std::min(last_row - first_row + 1, kRowsPerBatch), cx, cy, cr);
  }
}

void CoverageGrid::markRows(int first_row, int row_count, double cx, double cy, double cr) {
  // Pass 1, independent per row (the compiler vectorises it): each row's half chord.
  double half_chord[kRowsPerBatch];
  for (int k = 0; k < row_count; ++k) {
    const double dy = first_row + k - cy;
    half_chord[k] = std::sqrt(std::max(cr * cr - dy * dy, 0.0));
  }
  // Pass 2: set the row's span of cells, counting the free ones swept for the first time.
  for (int k = 0; k < row_count; ++k) {
    const int first =
        std::max(0, ceilToInt(std::clamp(cx - half_chord[k], -1.0, double(columns_))));
    const int last =
        std::min(columns_ - 1, floorToInt(std::clamp(cx + half_chord[k], -1.0, double(columns_))));
    if (first > last) continue;
    const std::size_t row_start = static_cast<std::size_t>(first_row + k) * words_per_row_;
    for (int word = first / kBitsPerWord; word <= last / kBitsPerWord; ++word) {
      const int lo = std::max(first - word * kBitsPerWord, 0);
      const int hi = std::min(last - word * kBitsPerWord, kBitsPerWord - 1);
      const std::uint64_t fresh = spanMask(lo, hi) & ~swept_[row_start + word];
      swept_[row_start + word] |= fresh;
      swept_free_count_ += countBits(fresh & free_[row_start + word]);
    }
  }
}

void CoverageGrid::merge(const CoverageGrid& other) {
  if (other.swept_.size() != swept_.size() || other.columns_ != columns_) {
    throw std::invalid_argument("CoverageGrid::merge: the grids belong to different worlds");
  }
  swept_free_count_ = 0;
  for (std::size_t i = 0; i < swept_.size(); ++i) {
    swept_[i] |= other.swept_[i];
    swept_free_count_ += countBits(swept_[i] & free_[i]);
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
