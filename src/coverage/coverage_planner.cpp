#include "roomba_rrt/coverage/coverage_planner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <utility>

#include "roomba_rrt/coverage/wall_loop.h"
#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::coverage {
namespace {

using Mask = std::vector<std::uint8_t>;  ///< one flag per lattice point

/// The most lattice points a planner samples (about 20 MB of working memory): a 100 m × 100 m
/// map at 0.025 m; a larger world needs a coarser resolution.
constexpr double kMaxLatticePoints = 2e7;

/// A leg shorter than this (m) is not worth driving: a resumed row's last millimetres, a
/// transit between points that coincide.
constexpr double kMinLegLength = 1e-6;

/// The shortest row pruneRows() leaves (m), unless the free space is shorter: a row that must only
/// reach a spot still has a direction for the follower to drive in.
constexpr double kMinRowLength = 0.05;

/// A cell that widens or narrows by this much (m) from one lattice row to the next gets a row
/// along the step (cellRows): the strip of up to a swath beside a narrower step is not worth the
/// U-turns and the transit to it. 0.4 m: the 0.8 m sideboard of the furnished room gets one; 1 m
/// left an 0.8 m × 0.2 m strip unswept there.
constexpr double kMinStepWidth = 0.4;

/// A row that would sweep less floor than this (m²) that no other row sweeps is not planned: a
/// spot of a few square centimetres is not worth a transit and two turns.
constexpr double kMinRowGain = 0.01;

/// Floor only one row sweeps comes in bunches along it (pruneRows): lattice columns of it further
/// apart than this (m) are in different bunches, and a bunch of less than kMinRowGain is not worth
/// driving the row to. Two cells that meet each have a row along where they meet, a few
/// centimetres apart; the one pruned first sweeps slivers of its own beyond the other's ends, and
/// it used to keep the whole stretch between them. In a cluttered willow_full crop (-4.41,-11.77
/// to 4.35,-5.01, 60 cells) 7.3 m of rows ran within 5 cm of another, now 0.3 m; its rows went
/// from 172.5 to 159.7 m. In 320 random crops (bench/coverage_crops.py, seeds 1-8) 265 reach 95 %
/// by 1.5x the ideal time instead of 262. Dropping bunches of up to 200 or 400 cm² gave 269, but
/// the willow_full crop of doc/performance.md then reached 99 % at 579 or 601 s, for 554.
constexpr double kBunchGap = 0.6;

/// The loop along the walls (wall_loop.h) is driven after the rows when it sweeps at least this
/// much floor per metre of it (m²/m) that the rows do not: where the walls lie at a slant to the
/// rows. The turtlebot3 arena's loop sweeps 0.043 (its hexagon's slanted walls) and takes it from
/// 94.5 to 95.3 % by 1.5× the ideal time (and from all 13 other starts tried, 94.5–94.8 →
/// 95.2–96.0 %). The rooms and crops of doc/performance.md have 0.012–0.027: their rows end square
/// to the walls, and there the drive round the room cost the willow_full crop's 99 % by 2× (549 →
/// 588 s) and the office's 99 % 31 s. Driven in every one of 320 random crops: 270 instead of
/// 267 reach 95 % by 1.5×, but 247 instead of 258 reach 99 % by 2×; above this gain, 271 and 258.
constexpr double kMinWallLoopGain = 0.035;

/// At most this many improvements of the cell order (each moves one cell): enough to settle a
/// room's few dozen cells, and a bound on the work in a large map.
constexpr int kMaxOrderRounds = 200;

/// One lattice row's stretch of a cell: columns a..b of lattice row j.
struct Slice {
  int j = 0;
  int a = 0;
  int b = 0;
};

/// A cell of the decomposition: one slice per lattice row, bottom to top, consecutive rows.
using Cell = std::vector<Slice>;

/// Visits the lattice points connected to `seed` (8-neighbours) for which inside(point) holds,
/// and `seed` itself, by depth-first search; `taken` marks them (and, on entry, the points not
/// to visit again).
template <class Inside, class Visit>
void forComponent(const FreeSpace& space, int seed, Inside inside, Mask& taken, Visit visit) {
  std::vector<int> frontier{seed};
  taken[seed] = 1;
  visit(seed);
  while (!frontier.empty()) {
    const int k = frontier.back();
    frontier.pop_back();
    const int i = space.column(k), j = space.row(k);
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if (!space.inside(i + di, j + dj)) continue;
        const int n = space.index(i + di, j + dj);
        if (!taken[n] && inside(n)) {
          taken[n] = 1;
          visit(n);
          frontier.push_back(n);
        }
      }
    }
  }
}

/// The lattice points of class ≥ `least` connected to `seed` (8-neighbours).
Mask flood(const FreeSpace& space, int seed, FreeSpace::Class least) {
  Mask region(space.size(), 0);
  forComponent(
      space, seed, [&](int n) { return space.at(n) >= least; }, region, [](int) {});
  return region;
}

/// Calls visit(k) for each lattice point k closer than `radius` to the segment a–b (a disc when
/// a = b).
template <class Visit>
void forPointsNear(const FreeSpace& space, const Point2& a, const Point2& b, double radius,
                   Visit visit) {
  const double h = space.resolution();
  const Point2 o = space.point(0, 0);
  const int i0 = std::max(0, static_cast<int>(std::floor((std::min(a.x, b.x) - radius - o.x) / h)));
  const int i1 = std::min(space.width() - 1,
                          static_cast<int>(std::ceil((std::max(a.x, b.x) + radius - o.x) / h)));
  const int j0 = std::max(0, static_cast<int>(std::floor((std::min(a.y, b.y) - radius - o.y) / h)));
  const int j1 = std::min(space.height() - 1,
                          static_cast<int>(std::ceil((std::max(a.y, b.y) + radius - o.y) / h)));
  const geometry::Segment s{a, b};
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const Point2 p = space.point(i, j);
      if (geometry::squaredDistance(geometry::closestPoint(s, p), p) < radius * radius) {
        visit(space.index(i, j));
      }
    }
  }
}

/// Directions floorReachedFrom() tries around a floor point for a centre that reaches it: 256,
/// centres 4 mm apart on the circle of the robot's radius. With 128 it missed some of the steps
/// of a wall a map draws at 45°.
constexpr int kReachDirections = 256;

/// A centre floorReachedFrom() counts lies within this many lattice steps (each way) of the
/// region: in the free space between the region's edge and the blocked points next to it.
constexpr int kNearRegion = 2;

/// The floor within the robot's radius r of a centre it can take in `region`'s part of the free
/// space: the region itself, a disc around each of its boundary points (any floor point near the
/// region is nearest to its boundary), and each floor point beyond those discs that a free centre
/// reaches (world::penetrates, exact) in the free space between the region's edge and its blocked
/// neighbours. That space reaches into a corner or a map's stepped wall where no lattice point's
/// disc does. The centres are tried on the circle of radius r around the point (any free centre
/// nearer to it lies in free space that extends beyond the circle, so crosses it), in
/// kReachDirections directions, first towards the region. The rule this replaces, a disc
/// r + h/2 around the boundary points, also counted floor no centre reaches: 0.3 % of the
/// turtlebot3 arena's.
Mask floorReachedFrom(const FreeSpace& space, const Mask& region) {
  const double h = space.resolution();
  const double r = space.robotRadius();
  const world::World& world = space.world();
  Mask reached = region, tried(space.size(), 0);
  // near: within kNearRegion steps of the region. A free centre that near it is in the same free
  // space: a wall between them, grown by r, would be 2r thick.
  Mask near = region;
  for (int k = 0; k < space.size(); ++k) {
    if (!region[k]) continue;
    const int i = space.column(k), j = space.row(k);
    if (i > 0 && j > 0 && i + 1 < space.width() && j + 1 < space.height() && region[k - 1] &&
        region[k + 1] && region[k - space.width()] && region[k + space.width()]) {
      continue;  // not on the boundary
    }
    const Point2 p = space.point(k);
    forPointsNear(space, p, p, r, [&](int n) { reached[n] = 1; });
    for (int dj = -kNearRegion; dj <= kNearRegion; ++dj) {
      for (int di = -kNearRegion; di <= kNearRegion; ++di) {
        if (space.inside(i + di, j + dj)) near[space.index(i + di, j + dj)] = 1;
      }
    }
  }
  // Whether a free centre near the region lies at r from x (just under: the disc sweeps what
  // lies closer than r), trying the direction of `towards` first, then turning either way.
  const Point2 origin = space.point(0, 0);
  const double reach = r * (1 - 1e-9);
  const double turn_step = 2 * std::acos(-1.0) / kReachDirections;  // 2π / directions
  auto reachedFrom = [&](const Point2& x, const Point2& towards) {
    const double first = std::atan2(towards.y - x.y, towards.x - x.x);
    for (int d = 0; d < kReachDirections; ++d) {
      const int turn = (d + 1) / 2 * (d % 2 ? 1 : -1);  // 0, +1, −1, +2, −2, …
      const double angle = first + turn * turn_step;
      const Point2 c{x.x + reach * std::cos(angle), x.y + reach * std::sin(angle)};
      const int i = static_cast<int>(std::lround((c.x - origin.x) / h));
      const int j = static_cast<int>(std::lround((c.y - origin.y) / h));
      if (space.inside(i, j) && near[space.index(i, j)] && !world::penetrates(world, r, c.x, c.y)) {
        return true;
      }
    }
    return false;
  };
  // Outwards from what the discs reach, one lattice step at a time: each floor point next to a
  // reached one, tried once, looking back towards that one first.
  std::vector<std::pair<int, int>> next;  // (point, its reached neighbour)
  auto push = [&](int k) {
    const int i = space.column(k), j = space.row(k);
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if (!space.inside(i + di, j + dj)) continue;
        const int n = space.index(i + di, j + dj);
        if (reached[n] || tried[n] || !space.isFloor(n)) continue;
        tried[n] = 1;
        next.emplace_back(n, k);
      }
    }
  };
  for (int k = 0; k < space.size(); ++k) {
    if (reached[k] && space.isFloor(k)) push(k);
  }
  while (!next.empty()) {
    const auto [n, from] = next.back();
    next.pop_back();
    if (reachedFrom(space.point(n), space.point(from))) {
      reached[n] = 1;
      push(n);
    }
  }
  for (int k = 0; k < space.size(); ++k) reached[k] = reached[k] && space.isFloor(k);
  return reached;
}

double area(const FreeSpace& space, const Mask& mask) {
  return std::count(mask.begin(), mask.end(), 1) * space.resolution() * space.resolution();
}

/// Boustrophedon decomposition of `region`, swept from the lowest lattice row up. A slice
/// continues the cell of the one slice below it that it overlaps, when that slice overlaps
/// nothing else above; otherwise (an obstacle splits the free space, two parts of it join, or
/// the free space begins) it opens a new cell.
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

/// A cleaning row: a horizontal segment from `left` to `right` (left.x ≤ right.x).
struct Row {
  Point2 left;
  Point2 right;
};

/// The rows of `cell`, bottom to top. Some are fixed: along its lowest and its highest slice (so
/// the disc brushes what bounds the cell below and above), moved out as far as they stay free
/// (the lattice stops up to a step short of the walls), and along the wider slice beside every
/// place where the cell widens or narrows by kMinStepWidth or more from one lattice row to the
/// next (it passes the top or reaches the bottom of something beside it: a sideboard against the
/// wall), so that the floor beside the step's narrow side is swept. Between two fixed rows the
/// others are evenly spaced, at any height, as few as keep neighbours at most `swath` apart. Each
/// row's ends are then moved out as far as they stay free (exactly).
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

/// Removes the rows whose floor other rows sweep as well, and shortens the others to the stretch
/// that sweeps floor no other row does (keptStretch). Cells overlap where they meet (each has its
/// lowest and highest row), and thin cells between nearby events (the tops of two pieces of
/// furniture) are mostly swept by their neighbours' rows; this drops that double work, losing
/// no floor but bunches of less than kMinRowGain that only one row would sweep. Rows with the
/// least floor of their own go first; every row stays inside its original segment, so it stays
/// free.
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

/// One of the four ways to sweep a cell's rows: upwards or downwards, the first row from left to
/// right or from right to left; the rows then alternate.
struct Way {
  bool upwards = true;
  bool first_left_to_right = true;
};
constexpr Way kWays[] = {{true, true}, {true, false}, {false, true}, {false, false}};

/// A cell's rows in the order they are driven, each as (start, end).
using Sweep = std::vector<std::pair<Point2, Point2>>;

/// The rows of a cell as `way` sweeps them: the first row in the way's direction, then the others
/// in the directions that make the straight jumps between rows shortest (dynamic programming over
/// the two directions of each row), and in the order of their heights but where driving two
/// neighbours the other way round makes the jumps shorter. Rows alternate, but a short row (a
/// step's, or one pruneRows() shortened) would flip the alternation of all the rows after it:
/// it is entered from its nearer end, after the row before or the row after it, whichever
/// leaves the robot where the next row starts. Ties keep the alternation.
Sweep sweep(const std::vector<Row>& rows, Way way) {
  const std::size_t n = rows.size();
  if (n == 0) return {};
  std::vector<std::size_t> order(n);  // indices into rows, in the order driven
  for (std::size_t k = 0; k < n; ++k) order[k] = way.upwards ? k : n - 1 - k;
  auto ends = [&](std::size_t k, int d) {  // row order[k], d = 0 in its alternating direction
    const Row& row = rows[order[k]];
    const bool left_to_right = (k % 2 == 0) == way.first_left_to_right;
    return left_to_right == (d == 0) ? std::pair{row.left, row.right}
                                     : std::pair{row.right, row.left};
  };
  // The directions of the rows in `order` with the shortest jumps, and their total.
  std::vector<std::array<double, 2>> cost(n);
  std::vector<std::array<int, 2>> came(n);  // direction of row k − 1 on the best way to (k, d)
  auto directions = [&](std::vector<int>* best) {
    cost[0] = {0, std::numeric_limits<double>::infinity()};  // the first as the way says
    for (std::size_t k = 1; k < n; ++k) {
      for (int d = 0; d < 2; ++d) {
        const Point2 start = ends(k, d).first;
        const double stay = cost[k - 1][0] + geometry::distance(ends(k - 1, 0).second, start);
        const double swap = cost[k - 1][1] + geometry::distance(ends(k - 1, 1).second, start);
        came[k][d] = swap < stay - kMinLegLength ? 1 : 0;
        cost[k][d] = came[k][d] ? swap : stay;
      }
    }
    int d = cost[n - 1][1] < cost[n - 1][0] - kMinLegLength ? 1 : 0;
    const double total = cost[n - 1][d];
    if (best) {
      best->assign(n, 0);
      for (std::size_t k = n; k-- > 0;) {
        (*best)[k] = d;
        d = came[k][d];
      }
    }
    return total;
  };
  double total = directions(nullptr);
  for (bool improved = true; improved;) {
    improved = false;
    for (std::size_t k = 1; k + 1 < n; ++k) {
      std::swap(order[k], order[k + 1]);
      const double swapped = directions(nullptr);
      if (swapped < total - kMinLegLength) {
        total = swapped;
        improved = true;
      } else {
        std::swap(order[k], order[k + 1]);
      }
    }
  }
  std::vector<int> chosen;
  directions(&chosen);
  Sweep out(n);
  for (std::size_t k = 0; k < n; ++k) out[k] = ends(k, chosen[k]);
  return out;
}

/// A cell in the sweep order, and the way it is swept.
struct Visit {
  std::size_t cell = 0;
  std::size_t way = 0;  ///< index in kWays
};

/// sweeps[c][w]: cell c swept the way kWays[w].
using Sweeps = std::vector<std::array<Sweep, std::size(kWays)>>;

/// The order to sweep the cells with rows in: first greedily (from where the robot is, the cell
/// whose first row starts nearest), then improved by moving single cells to another place in the
/// order or sweeping them another way, while that shortens the straight jumps between cells (a
/// lower bound of the transits), at most kMaxOrderRounds times.
std::vector<Visit> orderCells(const Sweeps& sweeps, const Point2& start) {
  auto entry = [&](const Visit& v) { return sweeps[v.cell][v.way].front().first; };
  auto exit = [&](const Visit& v) { return sweeps[v.cell][v.way].back().second; };
  std::vector<Visit> order;
  std::vector<bool> done(sweeps.size(), false);
  Point2 at = start;
  for (;;) {
    std::optional<Visit> best;
    double best_distance = 0;
    for (std::size_t c = 0; c < sweeps.size(); ++c) {
      if (done[c] || sweeps[c][0].empty()) continue;
      for (std::size_t way = 0; way < std::size(kWays); ++way) {
        const double d = geometry::distance(at, entry({c, way}));
        if (!best || d < best_distance) best = Visit{c, way}, best_distance = d;
      }
    }
    if (!best) break;
    done[best->cell] = true;
    order.push_back(*best);
    at = exit(*best);
  }

  // The straight jump into `v` as the k-th visit of `o` (from the start when k = 0).
  auto jump = [&](const std::vector<Visit>& o, std::size_t k, const Visit& v) {
    return geometry::distance(k == 0 ? start : exit(o[k - 1]), entry(v));
  };
  for (int round = 0; round < kMaxOrderRounds; ++round) {
    bool improved = false;
    for (std::size_t i = 0; i < order.size(); ++i) {
      const Visit moved = order[i];
      std::vector<Visit> rest = order;
      rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
      // What taking it out saves, and what putting it back elsewhere costs.
      double saved = jump(order, i, moved);
      if (i + 1 < order.size()) saved += jump(order, i + 1, order[i + 1]) - jump(rest, i, rest[i]);
      for (std::size_t k = 0; k <= rest.size() && !improved; ++k) {
        for (std::size_t way = 0; way < std::size(kWays); ++way) {
          const Visit v{moved.cell, way};
          double cost = jump(rest, k, v);
          if (k < rest.size()) {
            cost += geometry::distance(exit(v), entry(rest[k])) - jump(rest, k, rest[k]);
          }
          if (cost < saved - kMinLegLength) {
            rest.insert(rest.begin() + static_cast<std::ptrdiff_t>(k), v);
            order = std::move(rest);
            improved = true;
            break;
          }
        }
      }
      if (improved) break;
    }
    if (!improved) break;
  }
  return order;
}

/// The widest island (m, across the lattice points around it where the disc lacks the
/// clearance: the obstacle grown by the planning radius) that rows pass around. 1 m: the
/// turtlebot3 arena's pillars (0.66 m), the furnished room's round table (0.96 m) and bin (0.76 m);
/// 0.7 m left those two splitting the room and cost it 27 s to 90 %.
constexpr double kMaxIsland = 1.0;

/// A row's piece ends this far (m) before the island: the way round it then sets off from the
/// row without a step back first (the nearest lattice point of a piece that ends exactly at the
/// planning radius is often behind it), and the robot drives the two as one (FollowCoverage).
constexpr double kIslandBackOff = 0.02;

/// The world without its islands: obstacles whose grown extent (the lattice points where the
/// disc does not have the clearance) touches nothing else and fits in kMaxIsland. nullopt when
/// there are none.
std::optional<world::World> withoutIslands(const FreeSpace& space) {
  const double h = space.resolution();
  const int most = static_cast<int>(std::lround(kMaxIsland / h));
  Mask taken(space.size(), 0), island(space.size(), 0);
  bool any = false;
  for (int k = 0; k < space.size(); ++k) {
    if (taken[k] || space.at(k) == FreeSpace::kFree) continue;
    std::vector<int> points;
    int i0 = space.width(), i1 = -1, j0 = space.height(), j1 = -1;
    forComponent(
        space, k, [&](int n) { return space.at(n) != FreeSpace::kFree; }, taken,
        [&](int n) {
          points.push_back(n);
          i0 = std::min(i0, space.column(n));
          i1 = std::max(i1, space.column(n));
          j0 = std::min(j0, space.row(n));
          j1 = std::max(j1, space.row(n));
        });
    if (i0 == 0 || j0 == 0 || i1 + 1 == space.width() || j1 + 1 == space.height()) continue;
    if (i1 - i0 > most || j1 - j0 > most) continue;
    for (int n : points) island[n] = 1;
    any = true;
  }
  if (!any) return std::nullopt;
  const Point2 o = space.point(0, 0);
  auto onIsland = [&](const Point2& p) {
    const int i = static_cast<int>(std::lround((p.x - o.x) / h));
    const int j = static_cast<int>(std::lround((p.y - o.y) / h));
    return space.inside(i, j) && island[space.index(i, j)];
  };
  world::World open = space.world();
  open.circles.erase(std::remove_if(open.circles.begin(), open.circles.end(),
                                    [&](const world::Circle& c) { return onIsland(c.center); }),
                     open.circles.end());
  open.rectangles.erase(
      std::remove_if(open.rectangles.begin(), open.rectangles.end(),
                     [&](const world::Rectangle& r) {
                       return onIsland({(r.min_x + r.max_x) / 2, (r.min_y + r.max_y) / 2});
                     }),
      open.rectangles.end());
  if (open.map) {
    auto grid = std::make_shared<geometry::OccupancyGrid>(*open.map);
    for (int j = 0; j < grid->height; ++j) {
      for (int i = 0; i < grid->width; ++i) {
        const Point2 c{grid->origin.x + (i + 0.5) * grid->resolution,
                       grid->origin.y + (j + 0.5) * grid->resolution};
        if (grid->blocked(i, j) && onIsland(c)) {
          grid->cells[static_cast<std::size_t>(j) * grid->width + i] =
              geometry::OccupancyGrid::kFree;
        }
      }
    }
    open.map = grid;
  }
  return open;
}

}  // namespace

double CoveragePlan::length() const {
  double total = 0;
  for (const Leg& leg : legs) total += geometry::pathLength(leg.points);
  return total;
}

double CoveragePlan::rowLength() const {
  double total = 0;
  for (const Leg& leg : legs) {
    if (leg.kind == Leg::Kind::kRow) total += geometry::pathLength(leg.points);
  }
  return total;
}

namespace {
const CoverageOptions& validated(const world::World& world, const CoverageOptions& options) {
  util::requirePositive("swath", options.swath, 2 * world.robot_radius, "m");
  util::requireInRange("resolution", options.resolution, 1e-3, world.robot_radius, "m");
  util::require(options.swath >= 2 * options.resolution, "swath", "at least twice the resolution",
                options.swath);
  util::requireInRange("clearance", options.clearance, 0.0, world.robot_radius, "m");
  util::requireInRange("edge_clearance", options.edge_clearance, 0.0, world.robot_radius, "m");
  const double points =
      std::ceil(world.width / options.resolution) * std::ceil(world.height / options.resolution);
  util::require(points <= kMaxLatticePoints, "resolution",
                "coarse enough for at most 2e7 lattice points in this world", options.resolution);
  return options;
}
}  // namespace

CoverageOptions cleaningOptions(const world::World& world) {
  CoverageOptions options;
  options.resolution = world.coverage_cell_size;
  return options;
}

CoveragePlanner::CoveragePlanner(const world::World& world, const CoverageOptions& options)
    : options_(validated(world, options)), space_(world, options_.clearance, options_.resolution) {
  if (std::optional<world::World> open = withoutIslands(space_)) {
    open_.emplace(*open, options_.clearance, options_.resolution);
  }
}

std::optional<Polyline> CoveragePlanner::transit(const Point2& from, const Point2& to) const {
  if (space_.segmentFree(from, to)) return Polyline{from, to};
  const std::optional<int> first = space_.connect(from, FreeSpace::kFree);
  const std::optional<int> last = space_.connect(to, FreeSpace::kFree);
  if (!first || !last) return std::nullopt;
  std::optional<Polyline> path = space_.shortestPath(*first, *last);
  if (!path) return std::nullopt;
  // The robot's own point and the row's point on either end (each one free straight segment
  // away, by connect()); a lattice point that is one of them is not repeated.
  Polyline out{from};
  for (const Point2& p : *path) {
    if (geometry::squaredDistance(p, out.back()) > 0) out.push_back(p);
  }
  if (geometry::squaredDistance(to, out.back()) > 0) out.push_back(to);
  if (out.size() == 1) out.push_back(to);
  return space_.shortcut(out);
}

std::vector<std::uint8_t> CoveragePlanner::reachableFloor(CoveragePlan& plan,
                                                          const Point2& start) const {
  Mask floor(space_.size());
  for (int k = 0; k < space_.size(); ++k) floor[k] = space_.isFloor(k);
  plan.floor_area = area(space_, floor);
  plan.unreachable_area = plan.floor_area;
  const std::optional<int> seed = space_.connect(start, FreeSpace::kTight);
  if (!seed) return Mask(space_.size(), 0);
  Mask reachable = floorReachedFrom(space_, flood(space_, *seed, FreeSpace::kTight));
  plan.reachable_area = area(space_, reachable);
  plan.unreachable_area = plan.floor_area - plan.reachable_area;
  return reachable;
}

void CoveragePlanner::markSwept(std::vector<std::uint8_t>& swept, const Point2& at) const {
  swept.resize(space_.size(), 0);
  forPointsNear(space_, at, at, space_.robotRadius(), [&](int k) { swept[k] = 1; });
}

CoveragePlan CoveragePlanner::touchUp(const std::vector<std::uint8_t>& swept, const Point2& at,
                                      double min_spot_area) const {
  CoveragePlan plan;
  Mask missed = reachableFloor(plan, at);
  for (int k = 0; k < space_.size(); ++k) {
    missed[k] = missed[k] && !(k < static_cast<int>(swept.size()) && swept[k]);
  }
  // Where the robot can drive from here (with the clearance).
  const std::optional<int> seed = space_.connect(at, FreeSpace::kFree);
  if (!seed) return plan;
  const Mask drivable = flood(space_, *seed, FreeSpace::kFree);
  // The spots: 8-connected pieces of missed floor. Those under min_spot_area are not worth going
  // back for (now).
  const double h = space_.resolution();
  const double r = space_.robotRadius();
  std::vector<Leg> visits;  // rows to drive, in either direction
  Mask seen(space_.size(), 0);
  for (int k = 0; k < space_.size(); ++k) {
    if (!missed[k] || seen[k]) continue;
    std::vector<int> spot;
    forComponent(
        space_, k, [&](int n) { return missed[n] != 0; }, seen, [&](int n) { spot.push_back(n); });
    if (spot.size() * h * h < min_spot_area) {
      for (int q : spot) missed[q] = 0;
    }
  }
  // First what is missed along a wall or a piece of furniture, closer to it than any drivable
  // lattice point reaches (the floor U-turns' arcs leave between the rows' ends), in runs of a
  // lattice column or row: a row along each run, as close as stays free (stripRow()), when the
  // disc reaches the run from there. It sweeps the missed floor beside the run too.
  Mask uncovered(space_.size(), 0);
  for (int k = 0; k < space_.size(); ++k) {
    if (!missed[k]) continue;
    bool reached = false;
    const Point2 p = space_.point(k);
    forPointsNear(space_, p, p, r, [&](int c) { reached = reached || drivable[c]; });
    uncovered[k] = !reached;
  }
  // A row along `points` (in order along a line), sweeping what is missed beside it; false when
  // no free row reaches them. Too few points to be worth a row: nothing to do (true).
  auto stripVisit = [&](const std::vector<int>& points, bool vertical, double clearance) {
    if (static_cast<int>(points.size()) <= kStripLength) return true;
    const std::optional<Polyline> row = stripRow(points, vertical, clearance);
    if (!row) return false;
    for (std::size_t k = 0; k + 1 < row->size(); ++k) {
      forPointsNear(space_, (*row)[k], (*row)[k + 1], r,
                    [&](int c) { uncovered[c] = missed[c] = 0; });
    }
    visits.push_back(Leg{Leg::Kind::kRow, *row, clearance < options_.clearance});
    return true;
  };
  // A run that no free row reaches as a whole (something stands near one end: a plant in the
  // corner) is tried in halves.
  std::function<void(const std::vector<int>&, bool, double)> sweepRun =
      [&](const std::vector<int>& points, bool vertical, double clearance) {
        if (stripVisit(points, vertical, clearance)) return;
        const auto middle = points.begin() + static_cast<std::ptrdiff_t>(points.size() / 2);
        sweepRun(std::vector<int>(points.begin(), middle), vertical, clearance);
        sweepRun(std::vector<int>(middle, points.end()), vertical, clearance);
      };
  // Runs a short gap apart are one row: driving over a few swept centimetres costs less than a
  // transit and two turns more. When that row is not free, each run on its own.
  auto sweepStrip = [&](const std::vector<std::vector<int>>& runs, bool vertical,
                        double clearance) {
    std::vector<int> merged;
    for (const auto& run : runs) merged.insert(merged.end(), run.begin(), run.end());
    if (stripVisit(merged, vertical, clearance)) return;
    for (const auto& run : runs) sweepRun(run, vertical, clearance);
  };
  auto sweepStrips = [&](double clearance) {
    for (const bool vertical : {true, false}) {
      const int lines = vertical ? space_.width() : space_.height();
      const int length = vertical ? space_.height() : space_.width();
      for (int line = 0; line < lines; ++line) {
        std::vector<std::vector<int>> runs;  // runs of uncovered points, at most kStripGap apart
        int last = -kStripGap - 2;           // where the last uncovered point was along the line
        for (int along = 0; along < length; ++along) {
          const int q = vertical ? space_.index(line, along) : space_.index(along, line);
          if (!uncovered[q]) continue;
          if (along - last > kStripGap + 1) {
            sweepStrip(runs, vertical, clearance);
            runs.clear();
          }
          if (runs.empty() || along - last > 1) runs.emplace_back();
          runs.back().push_back(q);
          last = along;
        }
        sweepStrip(runs, vertical, clearance);
      }
    }
  };
  sweepStrips(options_.clearance);
  // What no row at the clearance reaches (the floor within the clearance of a wall, which
  // the rows and stops never sweep: a 1 cm band is 1 % of a small room's floor): edge cleaning,
  // rows along the wall at the edge clearance.
  if (options_.edge_clearance < options_.clearance) sweepStrips(options_.edge_clearance);
  // Places to stand for the rest: from the first missed point left (row by row), the drivable
  // lattice point within the robot's radius of it whose disc covers most missed floor, a row of
  // no length there: the robot arrives and drives on to the next spot in any heading (a row of
  // 5 cm along x made it turn twice at each spot; without it the dining room has 99 % 2 s
  // sooner, the turtlebot3 arena 96.1 % instead of 95.5 % by 2× the ideal time). What it covers
  // is no longer missed. A point no drivable lattice point covers (a corner the clearance keeps
  // the robot out of) is dropped.
  for (int k = 0; k < space_.size(); ++k) {
    if (!missed[k]) continue;
    std::optional<int> best;
    int best_count = 0;
    const Point2 p = space_.point(k);
    forPointsNear(space_, p, p, r, [&](int c) {
      if (!drivable[c]) return;
      int count = 0;
      const Point2 centre = space_.point(c);
      forPointsNear(space_, centre, centre, r, [&](int q) { count += missed[q]; });
      if (count > best_count) best = c, best_count = count;
    });
    if (!best) {
      missed[k] = 0;
      continue;
    }
    const Point2 centre = space_.point(*best);
    forPointsNear(space_, centre, centre, r, [&](int q) { missed[q] = 0; });
    visits.push_back(Leg{Leg::Kind::kRow, {centre, centre}});
  }
  // Nearest first (either end), each a transit and its row. (Improving the tour by 2-opt on the
  // straight jumps did not make the touch-up quicker: its cost is the turns as much as the jumps.)
  Point2 here = at;
  std::vector<bool> visited(visits.size(), false);
  for (std::size_t n = 0; n < visits.size(); ++n) {
    std::size_t next = visits.size();
    double next_distance = 0;
    for (std::size_t v = 0; v < visits.size(); ++v) {
      if (visited[v]) continue;
      const double d = std::min(geometry::distance(here, visits[v].points.front()),
                                geometry::distance(here, visits[v].points.back()));
      if (next == visits.size() || d < next_distance) next = v, next_distance = d;
    }
    visited[next] = true;
    Leg row = visits[next];
    Polyline& points = row.points;
    if (geometry::distance(here, points.back()) < geometry::distance(here, points.front())) {
      std::reverse(points.begin(), points.end());
    }
    const std::optional<Polyline> path = transit(here, points.front());
    if (!path) continue;
    if (geometry::pathLength(*path) > kMinLegLength) {
      plan.legs.push_back(Leg{Leg::Kind::kTransit, *path});
    }
    here = points.back();
    plan.legs.push_back(std::move(row));
  }
  return plan;
}

std::optional<Polyline> CoveragePlanner::stripRow(const std::vector<int>& points, bool vertical,
                                                  double clearance) const {
  const double h = space_.resolution();
  const double r = space_.robotRadius();
  const double radius = r + clearance;
  // The row along the line, `offset` from it (across it), from its first point to its last.
  const Point2 low = space_.point(points.front()), high = space_.point(points.back());
  auto along = [&](double offset) {
    return vertical ? std::pair{Point2{low.x + offset, low.y}, Point2{low.x + offset, high.y}}
                    : std::pair{Point2{low.x, low.y + offset}, Point2{high.x, low.y + offset}};
  };
  auto free = [&](double offset) {
    const auto [a, b] = along(offset);
    return space_.segmentFree(a, b, radius);
  };
  // Out from the strip, on the side with room, to the first free row; then back towards it as
  // far as it stays free (exactly). Kept when the disc reaches the strip from there.
  const int most = static_cast<int>(std::ceil(radius / h)) + 3;
  for (const double side : {1.0, -1.0}) {
    for (int m = 1; m <= most; ++m) {
      if (!free(side * m * h)) continue;
      const double offset =
          side * (m * h - farthestFree(h, [&](double t) { return free(side * (m * h - t)); }));
      if (std::fabs(offset) >= r) break;
      const auto [a, b] = along(offset);
      if (clearance >= options_.clearance) return Polyline{a, b};
      // Closer than the clearance (edge cleaning): the robot can neither arrive nor stop there
      // with the clearance. It comes in from the clearance beside the row's start along a ramp of
      // a few degrees (kEdgeRamp long), drives along the wall and ramps out again before the end.
      // (Ramps before and after the row, where there is room, swept its ends too but were slower
      // and bumped more with a late pose: 29 instead of 31 of 40 random crops at 99 % by 2×.)
      const double length = geometry::distance(a, b);
      const double ramp = std::min(kEdgeRamp, length / 4);
      const Point2 in{a.x + (b.x - a.x) * ramp / length, a.y + (b.y - a.y) * ramp / length};
      const Point2 out{b.x + (a.x - b.x) * ramp / length, b.y + (a.y - b.y) * ramp / length};
      const double lift = side * (options_.clearance - clearance);  // away from the wall
      const Point2 up{vertical ? lift : 0, vertical ? 0 : lift};
      const Point2 from{a.x + up.x, a.y + up.y}, to{b.x + up.x, b.y + up.y};
      if (!space_.segmentFree(from, from) || !space_.segmentFree(to, to) ||
          !space_.segmentFree(from, in, radius) || !space_.segmentFree(out, to, radius)) {
        break;
      }
      return Polyline{from, in, out, to};
    }
  }
  return std::nullopt;
}

std::vector<std::pair<Point2, Point2>> CoveragePlanner::freePieces(const Point2& a,
                                                                   const Point2& b) const {
  if (!open_ || space_.segmentFree(a, b)) return {{a, b}};
  // Samples half a lattice step apart; each run of free ones is a piece, its ends moved out to
  // the island as far as they stay free (exactly), then kIslandBackOff back.
  const double length = geometry::distance(a, b);
  const int n = std::max(1, static_cast<int>(std::ceil(2 * length / space_.resolution())));
  auto at = [&](double t) { return Point2{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; };
  auto freeAt = [&](int k) { return space_.segmentFree(at(double(k) / n), at(double(k) / n)); };
  std::vector<std::pair<Point2, Point2>> out;
  for (int k = 0; k <= n; ++k) {
    if (!freeAt(k)) continue;
    const int first = k;
    while (k < n && freeAt(k + 1)) ++k;
    double t0 = double(first) / n, t1 = double(k) / n;
    if (first > 0) {
      t0 -= farthestFree(1.0 / n, [&](double d) { return space_.segmentFree(at(t0 - d), at(t0)); });
    }
    if (k < n) {
      t1 += farthestFree(1.0 / n, [&](double d) { return space_.segmentFree(at(t1), at(t1 + d)); });
    }
    if (first > 0) t0 += kIslandBackOff / length;
    if (k < n) t1 -= kIslandBackOff / length;
    if ((t1 - t0) * length > kMinLegLength && space_.segmentFree(at(t0), at(t1))) {
      out.push_back({at(t0), at(t1)});
    }
  }
  return out;
}

CoveragePlan CoveragePlanner::plan(const Point2& start) const {
  CoveragePlan plan;

  // 1. What the robot can reach from the start: with its own radius (the floor it may touch),
  //    and with the clearance (where the rows and transits run).
  const std::optional<int> plan_seed = space_.connect(start, FreeSpace::kFree);
  const Mask reachable = reachableFloor(plan, start);
  if (!plan_seed || plan.reachable_area == 0) return plan;

  // 2. Islands aside (open_: a point free in space_ is free there too), 3. cells, 4. the rows
  //    that cover each, 5. pruned. A row across an island is cut into its free pieces below.
  const FreeSpace& rows_space = open_ ? *open_ : space_;
  const std::vector<Cell> cells =
      decompose(rows_space, flood(rows_space, *plan_seed, FreeSpace::kFree));
  plan.cells = static_cast<int>(cells.size());
  std::vector<std::vector<Row>> rows;
  for (const Cell& cell : cells) rows.push_back(cellRows(rows_space, cell, options_.swath));
  pruneRows(rows_space, reachable, rows);

  // 6. The order of the cells; 7. their rows, joined by transits (round an island between two
  //    pieces of a row).
  Mask swept(space_.size(), 0);
  Point2 at = start;
  Sweeps sweeps(rows.size());
  for (std::size_t c = 0; c < rows.size(); ++c) {
    for (std::size_t w = 0; w < std::size(kWays); ++w) sweeps[c][w] = sweep(rows[c], kWays[w]);
  }
  for (const Visit& visit : orderCells(sweeps, start)) {
    for (auto [row_start, row_end] : sweeps[visit.cell][visit.way]) {
      for (auto [piece_start, piece_end] : freePieces(row_start, row_end)) {
        const std::optional<Polyline> path = transit(at, piece_start);
        if (!path) continue;  // cannot happen in one connected region; never assumed
        if (geometry::pathLength(*path) > kMinLegLength) {
          plan.legs.push_back(Leg{Leg::Kind::kTransit, *path});
        }
        plan.legs.push_back(Leg{Leg::Kind::kRow, {piece_start, piece_end}});
        forPointsNear(space_, piece_start, piece_end, space_.robotRadius(),
                      [&](int p) { swept[p] = reachable[p]; });
        at = piece_end;
      }
    }
  }

  // 8. Once round the walls (wall_loop.h), when that sweeps enough floor the rows do not:
  //    its segments are rows, from its corner nearest the last row's end round to it again. The
  //    robot drives them as one path (FollowCoverage).
  Polyline loop = wallLoop(space_, *plan_seed);
  if (!loop.empty()) {
    loop.pop_back();
    std::rotate(loop.begin(),
                std::min_element(loop.begin(), loop.end(),
                                 [&](const Point2& a, const Point2& b) {
                                   return geometry::distance(a, at) < geometry::distance(b, at);
                                 }),
                loop.end());
    loop.push_back(loop.front());
    Mask gained(space_.size(), 0);
    for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
      forPointsNear(space_, loop[k], loop[k + 1], space_.robotRadius(),
                    [&](int p) { gained[p] = reachable[p] && !swept[p]; });
    }
    const std::optional<Polyline> path =
        area(space_, gained) >= kMinWallLoopGain * geometry::pathLength(loop)
            ? transit(at, loop.front())
            : std::nullopt;
    if (path) {
      if (geometry::pathLength(*path) > kMinLegLength) {
        plan.legs.push_back(Leg{Leg::Kind::kTransit, *path});
      }
      for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
        plan.legs.push_back(Leg{Leg::Kind::kRow, {loop[k], loop[k + 1]}});
      }
      for (int p = 0; p < space_.size(); ++p) swept[p] = swept[p] || gained[p];
    }
  }
  plan.swept_area = area(space_, swept);
  return plan;
}

CoveragePlan CoveragePlanner::resume(const CoveragePlan& plan, std::size_t leg,
                                     const Point2& at) const {
  CoveragePlan rest = plan;
  rest.legs.clear();
  std::vector<Leg> todo;  // the work left, before the transit to it
  if (leg < plan.legs.size() && plan.legs[leg].kind == Leg::Kind::kRow) {
    const Polyline& row = plan.legs[leg].points;
    const Point2 from = geometry::closestPoint({row.front(), row.back()}, at);
    if (geometry::distance(from, row.back()) > kMinLegLength) {
      todo.push_back(Leg{Leg::Kind::kRow, {from, row.back()}, plan.legs[leg].along_wall});
    }
  }
  for (std::size_t k = leg + 1; k < plan.legs.size(); ++k) todo.push_back(plan.legs[k]);

  std::size_t next = 0;
  while (next < todo.size()) {
    // The transits that led to a row are replaced by the one from `at`.
    while (next < todo.size() && todo[next].kind == Leg::Kind::kTransit) ++next;
    if (next == todo.size()) break;
    const std::optional<Polyline> path = transit(at, todo[next].points.front());
    if (!path) {
      ++next;  // this row cannot be reached from here: skip it
      continue;
    }
    if (geometry::pathLength(*path) > kMinLegLength) {
      rest.legs.push_back(Leg{Leg::Kind::kTransit, *path});
    }
    rest.legs.insert(rest.legs.end(), todo.begin() + static_cast<std::ptrdiff_t>(next), todo.end());
    break;
  }
  return rest;
}

}  // namespace roomba_rrt::coverage
