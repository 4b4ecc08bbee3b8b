#include "roomba_rrt/geometry/distance_transform.h"

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace roomba_rrt::geometry {
namespace {

// "No blocked cell in this column" for the first pass: larger than any distance in a grid.
constexpr std::int64_t kFar = std::numeric_limits<std::int32_t>::max();

// The second pass along one row: out[i] = min over k of (i − k)² + g[k]², exactly, for the
// columns k whose g[k] is finite (the lower envelope of their parabolas). `hull` and `starts`
// are scratch of width + 1 entries each.
void envelopeRow(const std::int32_t* g, int width, std::int32_t* out, std::vector<int>& hull,
                 std::vector<double>& starts) {
  // f(k) = g[k]² as a 64-bit integer; the parabola of column k is (i − k)² + f(k).
  auto f = [g](int k) { return static_cast<std::int64_t>(g[k]) * g[k]; };
  // Where the parabolas of columns q > v are equal (the right one is lower after it).
  auto meet = [&f](int q, int v) {
    return static_cast<double>((f(q) + std::int64_t{q} * q) - (f(v) + std::int64_t{v} * v)) /
           (2.0 * (q - v));
  };
  int n = 0;  // parabolas on the envelope: hull[0, n), parabola hull[m] lowest in [starts[m], ...)
  for (int q = 0; q < width; ++q) {
    if (g[q] >= kFar) continue;  // no blocked cell in this column
    // Drop the parabolas that q's is lower than from where they start; q's starts where it meets
    // the last one kept (each meeting point computed once: the division is the loop's cost).
    double start = -std::numeric_limits<double>::infinity();  // when it is the only one left
    while (n > 0) {
      const double at = meet(q, hull[n - 1]);
      if (at > starts[n - 1]) {
        start = at;
        break;
      }
      --n;
    }
    starts[n] = start;
    hull[n++] = q;
  }
  if (n == 0) {
    std::fill(out, out + width, kNoBlockedCell);
    return;
  }
  int m = 0;
  for (int i = 0; i < width; ++i) {
    while (m + 1 < n && starts[m + 1] <= i) ++m;
    const std::int64_t d = std::int64_t{i - hull[m]} * (i - hull[m]) + f(hull[m]);
    out[i] = static_cast<std::int32_t>(std::min<std::int64_t>(d, kNoBlockedCell));
  }
}

/// n zeros in memory the kernel may back with 2 MB pages: asked (madvise; transparent huge pages
/// in "madvise" mode) before the first write, so a large map's array costs one page fault per
/// 2 MB instead of one per 4 KB (a fifth of the transform's time on a 20 M-cell map), and its
/// queries fewer TLB misses. Where the kernel says no, it is an ordinary vector.
std::vector<std::int32_t> largeArray(std::size_t n) {
  std::vector<std::int32_t> v;
  v.reserve(n);
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  const auto begin = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + n * sizeof(std::int32_t)) & ~(kHugePage - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  v.resize(n);
  return v;
}

}  // namespace

std::vector<std::int32_t> squaredDistanceTransform(const OccupancyGrid& grid,
                                                   bool unknown_is_free) {
  const int width = grid.width, height = grid.height;
  const std::size_t w = static_cast<std::size_t>(width);
  // First pass: g = distance along the column to the nearest blocked cell (kFar: none), by a
  // sweep up and a sweep down, row by row so memory is read in order. This sweep up leaves in
  // each cell the distance to the nearest blocked cell below it (or in it).
  std::vector<std::int32_t> g = largeArray(w * static_cast<std::size_t>(height));
  for (int j = 0; j < height; ++j) {
    std::int32_t* row = &g[j * w];
    const std::int8_t* cells = &grid.cells[j * w];
    const std::int32_t* below = j > 0 ? &g[(j - 1) * w] : nullptr;
    for (int i = 0; i < width; ++i) {
      if (OccupancyGrid::blockedValue(cells[i], unknown_is_free)) {
        row[i] = 0;
      } else {
        row[i] = below && below[i] < kFar ? below[i] + 1 : static_cast<std::int32_t>(kFar);
      }
    }
  }
  // The sweep down, fused with the second pass so the grid is read and written once more, not
  // twice: going down from the top row, a row's column distances are final once the row above
  // has been swept, so they are completed in scratch (from the row above's, kept there) and the
  // row is overwritten by its envelope (second pass, along the row) straight away.
  std::vector<std::int32_t> column_distance(w);  // the row's column distances; the row above's
  std::vector<int> hull(w + 1);
  std::vector<double> starts(w + 1);
  for (int j = height - 1; j >= 0; --j) {
    std::int32_t* row = &g[j * w];
    for (int i = 0; i < width; ++i) {
      const std::int32_t above = column_distance[i];
      column_distance[i] =
          j + 1 < height && above < kFar && above + 1 < row[i] ? above + 1 : row[i];
    }
    envelopeRow(column_distance.data(), width, row, hull, starts);
  }
  return g;
}

}  // namespace roomba_rrt::geometry
