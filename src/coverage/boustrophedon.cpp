#include "roomba_rrt/coverage/boustrophedon.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

namespace roomba_rrt::coverage {
namespace {

/// What one lattice column along a row holds of the floor only that row sweeps: how many points,
/// and how far the row must reach to sweep them all: from lo or before to hi or after (lo is the
/// least of the points' x + reach, hi the greatest x − reach, where reach is the half chord of
/// the disc at the point's height).
struct OwnColumn {
  int points = 0;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();

  void add(const OwnColumn& other) {
    points += other.points;
    lo = std::min(lo, other.lo);
    hi = std::max(hi, other.hi);
  }
};

/// The stretch [lo, hi] a row keeps, given the floor only it sweeps column by column along it
/// (`columns`, lattice step h): the columns with such floor form bunches (a gap of more than
/// kBunchGap starts a new one); the row keeps the stretch that reaches every bunch of at least
/// kMinRowGain (h² per point). nullopt when no bunch is worth it.
std::optional<std::pair<double, double>> keptStretch(const std::vector<OwnColumn>& columns,
                                                     double h) {
  const std::size_t gap = static_cast<std::size_t>(std::floor(kBunchGap / h));
  std::optional<std::pair<double, double>> kept;
  std::size_t k = 0;
  while (k < columns.size()) {
    if (columns[k].points == 0) {
      ++k;
      continue;
    }
    OwnColumn bunch;
    for (std::size_t last = k; k < columns.size() && k - last <= gap; ++k) {
      if (columns[k].points == 0) continue;
      bunch.add(columns[k]);
      last = k;
    }
    if (bunch.points * h * h < kMinRowGain) continue;
    kept = kept ? std::pair{std::min(kept->first, bunch.lo), std::max(kept->second, bunch.hi)}
                : std::pair{bunch.lo, bunch.hi};
  }
  return kept;
}

}  // namespace

std::vector<Cell> decompose(const FreeSpace& space, const Mask& region) {
  std::vector<Cell> cells;
  std::vector<std::pair<Slice, int>> below, here;  // the slices of a lattice row, with their cell
  auto overlap = [](const Slice& s, const Slice& t) { return s.a <= t.b && t.a <= s.b; };
  for (int j = 0; j < space.height(); ++j) {
    here.clear();
    for (int i = 0; i < space.width(); ++i) {
      if (!region[space.index(i, j)]) continue;
      const int a = i;
      while (i + 1 < space.width() && region[space.index(i + 1, j)]) ++i;
      here.push_back({Slice{j, a, i}, -1});
    }
    for (auto& [slice, cell] : here) {
      int overlaps = 0, parent = -1;
      for (std::size_t p = 0; p < below.size(); ++p) {
        if (overlap(slice, below[p].first)) ++overlaps, parent = static_cast<int>(p);
      }
      if (overlaps == 1) {
        const Slice& parent_slice = below[parent].first;
        const auto above = std::count_if(here.begin(), here.end(), [&](const auto& other) {
          return overlap(parent_slice, other.first);
        });
        if (above == 1) cell = below[parent].second;
      }
      if (cell < 0) {
        cell = static_cast<int>(cells.size());
        cells.emplace_back();
      }
      cells[cell].push_back(slice);
    }
    std::swap(below, here);
  }
  return cells;
}

std::vector<Row> cellRows(const FreeSpace& space, const Cell& cell, double swath) {
  const int top = static_cast<int>(cell.size()) - 1;  // the cell's highest slice
  const double h = space.resolution();
  auto height = [](const Row& row) { return row.left.y; };
  auto shifted = [](const Row& row, double dy) {
    return Row{{row.left.x, row.left.y + dy}, {row.right.x, row.right.y + dy}};
  };
  auto free = [&](const Row& row) { return space.segmentFree(row.left, row.right); };
  auto along = [&](int index) {  // the row along a slice
    const Slice& s = cell[index];
    return Row{space.point(s.a, s.j), space.point(s.b, s.j)};
  };
  const double y0 = height(along(0));
  // The row at height y between the slices below and above it, along the stretch they share, or
  // (when that is not free) along the nearer slice.
  auto between = [&](double y) {
    const double f = std::clamp((y - y0) / h, 0.0, double(top));
    const int below = std::min(static_cast<int>(std::floor(f)), top - 1);
    const int a = std::max(cell[below].a, cell[below + 1].a);
    const int b = std::min(cell[below].b, cell[below + 1].b);
    const Row row{{space.point(a, 0).x, y}, {space.point(b, 0).x, y}};
    return a <= b && free(row) ? row : along(f - below < 0.5 ? below : below + 1);
  };

  std::vector<Row> out{along(0)};
  if (top > 0) {
    const Row lowest = along(0), highest = along(top);
    out[0] = shifted(lowest, -farthestFree(h, [&](double t) { return free(shifted(lowest, -t)); }));
    out.push_back(
        shifted(highest, farthestFree(h, [&](double t) { return free(shifted(highest, t)); })));
    const double low = height(out[0]);
    const double gap = height(out[1]) - low;
    const int parts = static_cast<int>(std::ceil(gap / swath - 1e-9));
    for (int p = 1; p < parts; ++p) out.push_back(between(low + gap * p / parts));
  }
  // Each end may move out to where the widest slice within a step of the row ends, and a step more.
  for (Row& row : out) {
    const double f = (height(row) - y0) / h;
    int a = std::numeric_limits<int>::max(), b = std::numeric_limits<int>::min();
    for (int j = std::max(0, static_cast<int>(std::floor(f)));
         j <= std::min(top, static_cast<int>(std::ceil(f))); ++j) {
      a = std::min(a, cell[j].a);
      b = std::max(b, cell[j].b);
    }
    const double left_reach = std::max(0.0, row.left.x - space.point(a, 0).x) + h;
    const double right_reach = std::max(0.0, space.point(b, 0).x - row.right.x) + h;
    row.left.x -= farthestFree(left_reach, [&](double t) {
      return space.segmentFree({row.left.x - t, row.left.y}, row.left);
    });
    row.right.x += farthestFree(right_reach, [&](double t) {
      return space.segmentFree(row.right, {row.right.x + t, row.right.y});
    });
  }
  if (top > 0) {
    // Along the stretch of slice j beyond the narrower slice `other` (a step), on either side, out
    // to the free end.
    const int step = std::max(1, static_cast<int>(std::lround(kMinStepWidth / h)));
    // Moved towards the step (`towards` −1: it is below, +1: above) as far as it stays free, as
    // the outer rows are, so that the disc brushes what the step is the edge of.
    auto beside = [&](int j, const Slice& other, double towards) {
      const Slice& s = cell[j];
      auto towardsStep = [&](const Row& row) {
        return shifted(row, towards * farthestFree(h, [&](double t) {
                              return free(shifted(row, towards * t));
                            }));
      };
      if (s.a + step <= other.a) {
        Row row = towardsStep({space.point(s.a, s.j), space.point(other.a, s.j)});
        row.left.x -= farthestFree(h, [&](double t) {
          return space.segmentFree({row.left.x - t, row.left.y}, row.left);
        });
        out.push_back(row);
      }
      if (s.b >= other.b + step) {
        Row row = towardsStep({space.point(other.b, s.j), space.point(s.b, s.j)});
        row.right.x += farthestFree(h, [&](double t) {
          return space.segmentFree(row.right, {row.right.x + t, row.right.y});
        });
        out.push_back(row);
      }
    };
    for (int j = 1; j < top; ++j) {
      beside(j, cell[j - 1], -1);
      beside(j, cell[j + 1], +1);
    }
    std::sort(out.begin(), out.end(),
              [&](const Row& x, const Row& y) { return height(x) < height(y); });
  }
  return out;
}

void pruneRows(const FreeSpace& space, const Mask& floor, std::vector<std::vector<Row>>& cells) {
  const double r = space.robotRadius();
  std::vector<int> sweeps(space.size(), 0);  // how many rows sweep each floor point
  auto stamp = [&](const Row& row, int add) {
    forPointsNear(space, row.left, row.right, r, [&](int k) { sweeps[k] += floor[k] ? add : 0; });
  };
  std::vector<std::pair<int, Row*>> order;  // (floor points only this row sweeps, row)
  for (auto& rows : cells) {
    for (Row& row : rows) stamp(row, +1);
  }
  for (auto& rows : cells) {
    for (Row& row : rows) {
      int own = 0;
      forPointsNear(space, row.left, row.right, r,
                    [&](int k) { own += floor[k] && sweeps[k] == 1; });
      order.emplace_back(own, &row);
    }
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  const double h = space.resolution();
  std::vector<OwnColumn> columns;  // of the row being pruned, from lattice column `first` on
  for (auto& entry : order) {
    Row* const row = entry.second;  // (not a structured binding: lambdas capture it, C++20)
    // The floor only this row sweeps, column by column, and the stretch it keeps to sweep it.
    const int first =
        std::max(0, static_cast<int>(std::floor((row->left.x - r - space.point(0, 0).x) / h)));
    columns.assign(
        static_cast<std::size_t>(std::ceil((row->right.x - row->left.x + 2 * r) / h)) + 2,
        OwnColumn{});
    forPointsNear(space, row->left, row->right, r, [&](int k) {
      if (!floor[k] || sweeps[k] != 1) return;
      const Point2 p = space.point(k);
      const double reach = std::sqrt(r * r - (p.y - row->left.y) * (p.y - row->left.y));
      OwnColumn& column = columns[static_cast<std::size_t>(space.column(k) - first)];
      ++column.points;
      column.lo = std::min(column.lo, p.x + reach - kMinLegLength);
      column.hi = std::max(column.hi, p.x - reach + kMinLegLength);
    });
    stamp(*row, -1);
    const auto kept = keptStretch(columns, h);
    if (!kept) {  // dropped
      *row = Row{{0, 0}, {-1, 0}};
      continue;
    }
    double lo = kept->first, hi = kept->second;
    if (hi - lo < kMinRowLength) {  // one point reaches them all: a short row around it
      const double middle = (lo + hi) / 2;
      lo = middle - kMinRowLength / 2;
      hi = middle + kMinRowLength / 2;
    }
    row->left.x = std::clamp(lo, row->left.x, row->right.x);
    row->right.x = std::clamp(hi, row->left.x, row->right.x);
    stamp(*row, +1);
  }
  for (auto& rows : cells) {
    rows.erase(std::remove_if(rows.begin(), rows.end(),
                              [](const Row& row) { return row.left.x > row.right.x; }),
               rows.end());
  }
}

}  // namespace roomba_rrt::coverage
