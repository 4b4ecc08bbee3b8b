#include "roomba_rrt/planning/nearest_neighbors/grid_nearest_neighbors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomba_rrt::planning {
namespace {

constexpr int kFirstGridCells = 512;
constexpr double kMaxPointsPerCell = 4;  // grow (double the cells) beyond this load
// Cell borders are computed in floating point; shrinking the "nothing closer outside" distance
// by this much keeps the answer exact (identical to brute force) despite rounding.
constexpr double kBorderSlack = 1e-9;
// Relative slack on the float pre-filter's bounds, far above the rounding of the double
// arithmetic that computes them (a few 1e-16).
constexpr double kRelativeSlack = 1e-9;

/// How far a point's float copy can lie from the point, when no coordinate exceeds max_abs: a
/// float is within 2^-24 |x| of x, so the copy is within sqrt(2) 2^-24 max_abs (2^-23 max_abs
/// rounds that up; the tiny term covers float's subnormal range).
double floatCopyError(double max_abs) { return max_abs * 0x1p-23 + 1e-40; }

}  // namespace

/// The slot of the nearest of `n` points, given as x[] and y[] padded with NaN to a multiple of 8,
/// to (qx, qy): the first slot, in array order, where dx*dx + dy*dy is smallest; -1 when no
/// distance is below +infinity (no points, or coordinates so large that the squares overflow).
///
/// The lab's trees have a few hundred nodes and this loop is most of a plan's time, so it works
/// on four points per instruction (GCC vector extensions: one AVX2 register, or two SSE2 ones on
/// a CPU without AVX2; target_clones compiles both and the loader picks one for this CPU). Two
/// groups of four lanes are independent, so one group's compare does not wait for the other's.
/// Each lane keeps the first slot at which it saw its own minimum (strict <); merging the eight
/// lanes, the smaller distance wins and the lower slot among equal ones. No FMA is enabled (AVX2
/// does not imply it), so every distance is rounded exactly as squaredDistance() rounds it and the
/// answer is bit for bit the brute-force one. The padding NaNs never compare less than anything.
__attribute__((target_clones("avx2", "default"))) int GridNearestNeighbors::linearNearest(
    const double* xs, const double* ys, int n, double qx, double qy) {
  using V = double __attribute__((vector_size(32)));
  constexpr double inf = std::numeric_limits<double>::infinity();
  const V vqx = {qx, qx, qx, qx}, vqy = {qy, qy, qy, qy};
  const V eight = {8, 8, 8, 8};
  V best_lo = {inf, inf, inf, inf}, best_hi = best_lo;  // slots i..i+3 and i+4..i+7
  // The i at which each lane saw its minimum (its slot is that plus the lane's offset, added
  // after the loop: one counter for all eight lanes).
  V slot_lo = {-1, -1, -1, -1}, slot_hi = slot_lo;
  V here = {0, 0, 0, 0};
  for (int i = 0; i < n; i += 8, here += eight) {
    V x_lo, y_lo, x_hi, y_hi;
    __builtin_memcpy(&x_lo, xs + i, sizeof(V));
    __builtin_memcpy(&y_lo, ys + i, sizeof(V));
    __builtin_memcpy(&x_hi, xs + i + 4, sizeof(V));
    __builtin_memcpy(&y_hi, ys + i + 4, sizeof(V));
    const V dx_lo = x_lo - vqx, dy_lo = y_lo - vqy;
    const V dx_hi = x_hi - vqx, dy_hi = y_hi - vqy;
    const V d2_lo = dx_lo * dx_lo + dy_lo * dy_lo;
    const V d2_hi = dx_hi * dx_hi + dy_hi * dy_hi;
    const auto closer_lo = d2_lo < best_lo;
    const auto closer_hi = d2_hi < best_hi;
    best_lo = closer_lo ? d2_lo : best_lo;
    slot_lo = closer_lo ? here : slot_lo;
    best_hi = closer_hi ? d2_hi : best_hi;
    slot_hi = closer_hi ? here : slot_hi;
  }
  slot_lo += V{0, 1, 2, 3};  // lanes that saw no distance below infinity never win below
  slot_hi += V{4, 5, 6, 7};
  // Merge the eight lanes into lane 0, halving each time and without branches (a data-dependent
  // branch per lane, mispredicted now and then, costs more than the scan of a small tree): of two
  // (distance, slot) pairs the smaller distance wins, the lower slot among equal distances.
  using Mask = long long __attribute__((vector_size(32)));
  auto keepNearer = [](V& best, V& slot, const V& other_best, const V& other_slot) {
    const Mask take = (other_best < best) | ((other_best == best) & (other_slot < slot));
    best = take ? other_best : best;
    slot = take ? other_slot : slot;
  };
  keepNearer(best_lo, slot_lo, best_hi, slot_hi);
  const Mask swap_pairs = {2, 3, 0, 1}, swap_neighbours = {1, 0, 3, 2};
  keepNearer(best_lo, slot_lo, __builtin_shuffle(best_lo, swap_pairs),
             __builtin_shuffle(slot_lo, swap_pairs));
  keepNearer(best_lo, slot_lo, __builtin_shuffle(best_lo, swap_neighbours),
             __builtin_shuffle(slot_lo, swap_neighbours));
  return best_lo[0] < inf ? static_cast<int>(slot_lo[0]) : -1;
}

/// What a grid query has seen so far. The grid lives in "float space": each point is stored,
/// and put in its cell, by its float copy, and distances here are from those copies ("float
/// distances"). `error` bounds how far a float copy lies from its exact point, so a point's exact
/// distance is within `error` of its float distance.
///  - best_d2: the smallest squared float distance seen.
///  - The exact nearest point is at least as close as the float-best point, whose exact distance
///    is at most sqrt(best_d2) + error; so its float distance is at most sqrt(best_d2) + 2 error.
///    Points within that bound are kept as candidates (nearly always just one), and so is the
///    ring search's radius: reachD2(). No float copy beyond it can be the nearest point's.
struct GridNearestNeighbors::Search {
  static constexpr int kMaxCandidates = 16;
  Point2 q;
  double error = 0;
  const Point2* positions = nullptr;  ///< to prefetch the exact coordinates of a new best
  double best_d2 = std::numeric_limits<double>::infinity();
  double keep_d2 = std::numeric_limits<double>::infinity();  ///< (sqrt(best_d2) + 2 error)^2
  int count = 0;
  bool overflowed = false;  ///< more candidates than fit: exactNearest() looks again
  std::int32_t index[kMaxCandidates];
  double d2[kMaxCandidates];

  double floatD2(const Entry& e) const {
    const double dx = static_cast<double>(e.x) - q.x;
    const double dy = static_cast<double>(e.y) - q.y;
    return dx * dx + dy * dy;
  }
  void consider(const Entry& e) {
    const double d2_e = floatD2(e);
    if (d2_e > keep_d2) return;
    if (d2_e < best_d2) {
      // Its exact coordinates will be read at the end: start loading them now (at 10^6 nodes
      // that is a cache miss, which then overlaps the rest of the search).
      __builtin_prefetch(positions + e.index);
      best_d2 = d2_e;
      const double keep = (std::sqrt(best_d2) + 2 * error) * (1 + kRelativeSlack);
      keep_d2 = keep * keep;
    }
    if (count == kMaxCandidates) {  // drop the candidates that a closer point has ruled out
      int kept = 0;
      for (int k = 0; k < count; ++k) {
        if (d2[k] <= keep_d2) {
          index[kept] = index[k];
          d2[kept++] = d2[k];
        }
      }
      count = kept;
    }
    if (count == kMaxCandidates) {
      overflowed = true;
      return;
    }
    index[count] = e.index;
    d2[count++] = d2_e;
  }
  double reachD2() const { return keep_d2; }
};

void GridNearestNeighbors::clear(const Bounds& bounds, const std::vector<Point2>& positions) {
  bounds_ = bounds;
  positions_ = &positions;
  max_abs_coordinate_ = 0;
  size_ = 0;
  cells_.clear();
  overflow_.clear();
  linear_x_.clear();
  linear_y_.clear();
  linear_ids_.clear();
  linear_ids_increasing_ = true;
  // The linear phase never grows beyond this: allocate once per plan, not while growing.
  linear_x_.reserve(kLinearScanLimit + 64);
  linear_y_.reserve(kLinearScanLimit + 64);
  linear_ids_.reserve(kLinearScanLimit);
}

void GridNearestNeighbors::openLinearSlots() {
  const std::size_t slots = linear_x_.size() + 64;
  linear_x_.resize(slots, std::numeric_limits<double>::quiet_NaN());
  linear_y_.resize(slots, std::numeric_limits<double>::quiet_NaN());
}

void GridNearestNeighbors::resize(int target_cells) {
  // Take every entry out (12 bytes a point), free the old cells, lay a finer grid, put the entries
  // back. Reading them cell by cell keeps both the reads and the writes local.
  std::vector<Entry> entries;
  entries.reserve(size_);
  for (const Cell& c : cells_) forEachInCell(c, [&](const Entry& e) { entries.push_back(e); });
  for (std::size_t i = 0; i < linear_ids_.size(); ++i) {
    entries.push_back(
        {static_cast<float>(linear_x_[i]), static_cast<float>(linear_y_[i]), linear_ids_[i]});
    max_abs_coordinate_ =
        std::max({max_abs_coordinate_, std::abs(linear_x_[i]), std::abs(linear_y_[i])});
  }
  linear_x_ = {};
  linear_y_ = {};
  linear_ids_ = {};
  decltype(cells_)().swap(cells_);
  decltype(overflow_)().swap(overflow_);
  // About square cells, but never more cells along one axis than in total (thin bounds).
  const double width = bounds_.x_max - bounds_.x_min;
  const double height = bounds_.y_max - bounds_.y_min;
  // A NaN or infinite shape (degenerate bounds, which validate() refuses) gets one column.
  const double columns = std::round(std::sqrt(target_cells * width / height));
  nx_ = columns >= 1 ? static_cast<int>(std::min(columns, static_cast<double>(target_cells))) : 1;
  ny_ = std::max(1, target_cells / nx_);
  cell_w_ = width / nx_;
  cell_h_ = height / ny_;
  inv_cell_w_ = nx_ / width;
  inv_cell_h_ = ny_ / height;
  cells_.assign(static_cast<std::size_t>(nx_) * ny_, Cell{});
  bx_ = (nx_ + kBlock - 1) / kBlock;
  by_ = (ny_ + kBlock - 1) / kBlock;
  block_count_.assign(static_cast<std::size_t>(bx_) * by_, 0);
  for (const Entry& e : entries) insert(e);
}

inline void GridNearestNeighbors::insert(const Entry& e) {
  const int cx = cellX(e.x), cy = cellY(e.y);  // the float copy decides the cell
  ++block_count_[blockOf(cx, cy)];
  Cell& cell = cells_[static_cast<std::size_t>(cy) * nx_ + cx];
  for (Entry& slot : cell.inline_entries) {
    if (slot.index < 0) {
      slot = e;
      return;
    }
  }
  overflow_.push_back({e, cell.overflow});
  cell.overflow = static_cast<std::int32_t>(overflow_.size() - 1);
}

void GridNearestNeighbors::addToGrid(const Point2& p, int index) {
  if (cells_.empty()) {
    resize(kFirstGridCells);
  } else if (size_ > kMaxPointsPerCell * cellCount()) {
    resize(2 * cellCount());
  }
  max_abs_coordinate_ = std::max({max_abs_coordinate_, std::abs(p.x), std::abs(p.y)});
  insert({static_cast<float>(p.x), static_cast<float>(p.y), index});
}

Neighbor GridNearestNeighbors::searchNearest(const Point2& q) const {
  if (size_ == 0) return {};
  if (cells_.empty()) {
    const int n = static_cast<int>(linear_ids_.size());
    if (linear_ids_increasing_) {
      const int slot = linearNearest(linear_x_.data(), linear_y_.data(), n, q.x, q.y);
      if (slot >= 0) return linearNeighbor(slot);
    }
    // Indices out of order, or every distance overflowed: compare them one by one.
    int best = 0;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i) {
      const double dx = linear_x_[i] - q.x;
      const double dy = linear_y_[i] - q.y;
      const double d2 = dx * dx + dy * dy;
      if (d2 < best_d2 || (d2 == best_d2 && linear_ids_[i] < linear_ids_[best])) {
        best_d2 = d2;
        best = i;
      }
    }
    return linearNeighbor(best);
  }
  const int cx = cellX(q.x);
  const int cy = cellY(q.y);
  // At 10^6 points every cell is a cache miss: ask for the 3 x 3 block at once, so the
  // misses overlap instead of queueing (each row of the block is contiguous).
  for (int y = std::max(0, cy - 1); y <= std::min(ny_ - 1, cy + 1); ++y) {
    const Cell* row = &cell(std::max(0, cx - 1), y);
    for (int x = std::max(0, cx - 1); x <= std::min(nx_ - 1, cx + 1); ++x, ++row) {
      __builtin_prefetch(row);
    }
  }
  Search search;
  search.q = q;
  search.error = floatCopyError(max_abs_coordinate_);
  search.positions = positions_->data();
  auto consider = [&](const Entry& e) { search.consider(e); };
  // 1. Rings of cells around the query's cell; enough whenever the tree is near.
  constexpr int kCellRings = 3;
  for (int r = 0; r < kCellRings; ++r) {
    forEachOnRing(cx, cy, r, nx_, ny_, [&](int x, int y) {
      // Skip a cell that lies wholly beyond the candidates' radius (most of the ring around a
      // query, once its own cell has given a near point).
      if (r > 0 && cellGapD2(q, x, y) > search.keep_d2) return;
      forEachInCell(cell(x, y), consider);
    });
    if (ringSearchDone(q, cx, cy, r, nx_, ny_, cell_w_, cell_h_, search.reachD2())) {
      return exactNearest(q, search);
    }
  }
  // 2. Far from every point: rings of blocks, visiting only blocks that hold points. (Cells of
  //    step 1 may be visited again; the minimum stays the same.)
  //    A block, and a cell of it, wholly beyond the candidates' radius is skipped too.
  auto visitBlock = [&](int x, int y) {
    if (block_count_[static_cast<std::size_t>(y) * bx_ + x] == 0) return;
    const int fx0 = x * kBlock, fx1 = std::min(nx_, (x + 1) * kBlock) - 1;
    const int fy0 = y * kBlock, fy1 = std::min(ny_, (y + 1) * kBlock) - 1;
    if (rangeGapD2(q, fx0, fx1, fy0, fy1) > search.keep_d2) return;
    for (int fy = fy0; fy <= fy1; ++fy) {
      for (int fx = fx0; fx <= fx1; ++fx) {
        const Cell& c = cell(fx, fy);
        if (c.inline_entries[0].index < 0 || cellGapD2(q, fx, fy) > search.keep_d2) continue;
        forEachInCell(c, consider);
      }
    }
  };
  const int bx = cx / kBlock, by = cy / kBlock;
  for (int r = 0;; ++r) {
    forEachOnRing(bx, by, r, bx_, by_, visitBlock);
    if (ringSearchDone(q, bx, by, r, bx_, by_, kBlock * cell_w_, kBlock * cell_h_,
                       search.reachD2())) {
      break;
    }
  }
  return exactNearest(q, search);
}

inline Neighbor GridNearestNeighbors::exactNearest(const Point2& q, const Search& search) const {
  // Among the candidates, the exact answer: the smallest squaredDistance(), then the lowest index.
  int best = -1;
  double best_d2 = 0;
  auto decide = [&](int index) {
    const double d2 = squaredDistance((*positions_)[index], q);
    if (best < 0 || d2 < best_d2 || (d2 == best_d2 && index < best)) {
      best = index;
      best_d2 = d2;
    }
  };
  if (!search.overflowed) {
    for (int k = 0; k < search.count; ++k) {
      if (search.d2[k] <= search.keep_d2) decide(search.index[k]);
    }
  } else {
    // More than kMaxCandidates points within the float error of each other (duplicates): look
    // again at every cell that can hold a candidate.
    const double r = std::sqrt(search.keep_d2);
    for (int y = cellY(q.y - r); y <= cellY(q.y + r); ++y) {
      for (int x = cellX(q.x - r); x <= cellX(q.x + r); ++x) {
        forEachInCell(cell(x, y), [&](const Entry& e) {
          if (search.floatD2(e) <= search.keep_d2) decide(e.index);
        });
      }
    }
  }
  return {best, (*positions_)[best]};
}

inline double GridNearestNeighbors::cellGapD2(const Point2& q, int cx, int cy) const {
  return rangeGapD2(q, cx, cx, cy, cy);
}

inline double GridNearestNeighbors::rangeGapD2(const Point2& q, int cx0, int cx1, int cy0,
                                               int cy1) const {
  // The cells' extent; the outermost cells also hold anything beyond the bounds (cellX clamps).
  double gap_x = 0, gap_y = 0;
  if (cx0 > 0) gap_x = std::max(gap_x, bounds_.x_min + cx0 * cell_w_ - q.x);
  if (cx1 < nx_ - 1) gap_x = std::max(gap_x, q.x - (bounds_.x_min + (cx1 + 1) * cell_w_));
  if (cy0 > 0) gap_y = std::max(gap_y, bounds_.y_min + cy0 * cell_h_ - q.y);
  if (cy1 < ny_ - 1) gap_y = std::max(gap_y, q.y - (bounds_.y_min + (cy1 + 1) * cell_h_));
  gap_x = std::max(0.0, gap_x - kBorderSlack);
  gap_y = std::max(0.0, gap_y - kBorderSlack);
  return gap_x * gap_x + gap_y * gap_y;
}

inline bool GridNearestNeighbors::ringSearchDone(const Point2& q, int ux, int uy, int r,
                                                 int units_x, int units_y, double unit_w,
                                                 double unit_h, double best_d2) const {
  const bool left = ux - r > 0, right = ux + r < units_x - 1;
  const bool down = uy - r > 0, up = uy + r < units_y - 1;
  if (!left && !right && !down && !up) return true;  // the whole grid has been visited
  double gap = std::numeric_limits<double>::infinity();
  if (left) gap = std::min(gap, q.x - (bounds_.x_min + (ux - r) * unit_w));
  if (right) gap = std::min(gap, bounds_.x_min + (ux + r + 1) * unit_w - q.x);
  if (down) gap = std::min(gap, q.y - (bounds_.y_min + (uy - r) * unit_h));
  if (up) gap = std::min(gap, bounds_.y_min + (uy + r + 1) * unit_h - q.y);
  gap -= kBorderSlack;
  return gap > 0 && best_d2 < gap * gap;
}

void GridNearestNeighbors::withinRadius(const Point2& q, double radius,
                                        std::vector<int>& out) const {
  out.clear();
  const double r2 = radius * radius;
  for (std::size_t i = 0; i < linear_ids_.size(); ++i) {
    const double dx = linear_x_[i] - q.x;
    const double dy = linear_y_[i] - q.y;
    if (dx * dx + dy * dy <= r2) out.push_back(linear_ids_[i]);
  }
  if (cells_.empty()) return;
  // Pre-select by the float copies (see Search), decide by the exact coordinates.
  Search search;
  search.q = q;
  // A point within `radius` has its float copy within `reach`.
  const double reach = (radius + floatCopyError(max_abs_coordinate_)) * (1 + kRelativeSlack);
  for (int y = cellY(q.y - reach); y <= cellY(q.y + reach); ++y) {
    for (int x = cellX(q.x - reach); x <= cellX(q.x + reach); ++x) {
      forEachInCell(cell(x, y), [&](const Entry& e) {
        if (search.floatD2(e) <= reach * reach &&
            squaredDistance((*positions_)[e.index], q) <= r2) {
          out.push_back(e.index);
        }
      });
    }
  }
}

}  // namespace roomba_rrt::planning
