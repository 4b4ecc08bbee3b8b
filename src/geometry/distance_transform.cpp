#include "roomba_rrt/geometry/distance_transform.h"

#include <algorithm>
#include <cstddef>
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
    while (n > 0 && meet(q, hull[n - 1]) <= starts[n - 1]) --n;
    starts[n] = n == 0 ? -std::numeric_limits<double>::infinity() : meet(q, hull[n - 1]);
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

}  // namespace

std::vector<std::int32_t> squaredDistanceTransform(const OccupancyGrid& grid,
                                                   bool unknown_is_free) {
  const int width = grid.width, height = grid.height;
  const std::size_t w = static_cast<std::size_t>(width);
  // First pass: g = distance along the column to the nearest blocked cell (kFar: none), by a
  // sweep up and a sweep down, row by row so memory is read in order.
  std::vector<std::int32_t> g(w * static_cast<std::size_t>(height));
  for (int j = 0; j < height; ++j) {
    std::int32_t* row = &g[j * w];
    const std::int32_t* below = j > 0 ? &g[(j - 1) * w] : nullptr;
    for (int i = 0; i < width; ++i) {
      if (grid.blocked(i, j, unknown_is_free)) {
        row[i] = 0;
      } else {
        row[i] = below && below[i] < kFar ? below[i] + 1 : static_cast<std::int32_t>(kFar);
      }
    }
  }
  for (int j = height - 2; j >= 0; --j) {
    std::int32_t* row = &g[j * w];
    const std::int32_t* above = &g[(j + 1) * w];
    for (int i = 0; i < width; ++i) {
      if (above[i] < kFar && above[i] + 1 < row[i]) row[i] = above[i] + 1;
    }
  }
  // Second pass, row by row, in place: each row's input is copied to scratch first.
  std::vector<std::int32_t> column_distance(w);
  std::vector<int> hull(w + 1);
  std::vector<double> starts(w + 1);
  for (int j = 0; j < height; ++j) {
    std::int32_t* row = &g[j * w];
    std::copy(row, row + width, column_distance.begin());
    envelopeRow(column_distance.data(), width, row, hull, starts);
  }
  return g;
}

}  // namespace roomba_rrt::geometry
