#include "roomba_rrt/coverage/coverage_planner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

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
/// beside the step (cellRows): the strip a swath wide beside a narrower step is not worth the
/// U-turn and the transit to it.
constexpr double kMinStepWidth = 1.0;

/// A row that would sweep less floor than this (m²) that no other row sweeps is not planned: a
/// spot of a few square centimetres is not worth a transit and two turns.
constexpr double kMinRowGain = 0.01;

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

/// The lattice points of class ≥ `least` connected to `seed` (8-neighbours), by breadth-first
/// search.
Mask flood(const FreeSpace& space, int seed, FreeSpace::Class least) {
  Mask region(space.size(), 0);
  std::vector<int> frontier{seed};
  region[seed] = 1;
  while (!frontier.empty()) {
    const int k = frontier.back();
    frontier.pop_back();
    const int i = space.column(k), j = space.row(k);
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if (!space.inside(i + di, j + dj)) continue;
        const int n = space.index(i + di, j + dj);
        if (!region[n] && space.at(n) >= least) {
          region[n] = 1;
          frontier.push_back(n);
        }
      }
    }
  }
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

/// The floor within the robot's radius of a centre in `region`: the region itself, and a disc
/// around each of its boundary points (any floor point near the region is nearest to its
/// boundary). The true boundary of the centre's free space lies between a boundary point and its
/// blocked neighbour, on average half a step beyond: the discs have radius r + h/2.
Mask floorReachedFrom(const FreeSpace& space, const Mask& region) {
  Mask reached = region;
  for (int k = 0; k < space.size(); ++k) {
    if (!region[k]) continue;
    const int i = space.column(k), j = space.row(k);
    const bool boundary = i == 0 || j == 0 || i + 1 == space.width() || j + 1 == space.height() ||
                          !region[k - 1] || !region[k + 1] || !region[k - space.width()] ||
                          !region[k + space.width()];
    if (!boundary) continue;
    const Point2 p = space.point(k);
    const double reach = space.robotRadius() + space.resolution() / 2;
    forPointsNear(space, p, p, reach, [&](int n) { reached[n] = 1; });
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
        const auto& [parent_slice, parent_cell] = below[parent];
        const auto above = std::count_if(here.begin(), here.end(), [&](const auto& other) {
          return overlap(parent_slice, other.first);
        });
        if (above == 1) cell = parent_cell;
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

/// The largest t in [0, max] with free(t), to max/2^16, given free(0): how far a row can be moved
/// towards a wall the lattice stopped short of (by up to a step).
template <class Free>
double farthestFree(double max, Free free) {
  if (free(max)) return max;
  double lo = 0, hi = max;
  for (int k = 0; k < 16; ++k) {
    const double mid = (lo + hi) / 2;
    (free(mid) ? lo : hi) = mid;
  }
  return lo;
}

/// The rows of `cell`, bottom to top: along its lowest and its highest slice (so the disc brushes
/// what bounds the cell below and above) and evenly between them, as few as keep neighbours at
/// most `swath` apart. Where the cell widens going up by kMinStepWidth or more (it passes
/// the top of something beside it: a sideboard against the wall) or narrows going up (it reaches
/// the bottom of something), also along the wider slice next to the step: the even rows may pass
/// it by up to a swath, and leave the floor beside the step's narrow side; pruneRows() keeps of
/// such a row only the stretch that sweeps floor of its own. The lattice stops up to a step short
/// of the walls; each row's ends, and the lowest and highest row, are then moved out as far as
/// they stay free (exactly).
std::vector<Row> cellRows(const FreeSpace& space, const Cell& cell, double swath) {
  const int rows = static_cast<int>(cell.size()) - 1;  // lattice rows spanned
  const double h = space.resolution();
  // Spaced by at most swath − h, so that moving the outer rows out by up to h keeps every gap
  // within the swath.
  const int count = rows == 0 ? 1 : static_cast<int>(std::ceil(rows * h / (swath - h) - 1e-9)) + 1;
  auto shifted = [](const Row& row, double dy) {
    return Row{{row.left.x, row.left.y + dy}, {row.right.x, row.right.y + dy}};
  };
  auto free = [&](const Row& row) { return space.segmentFree(row.left, row.right); };
  // The slices the rows run along: evenly spaced, and beside the steps.
  std::vector<std::pair<long, bool>> along;  // (slice index, an outer row)
  for (int k = 0; k < count; ++k) {
    along.emplace_back(count == 1 ? 0 : std::lround(double(k) * rows / (count - 1)),
                       count > 1 && (k == 0 || k == count - 1));
  }
  const int step = std::max(1, static_cast<int>(std::lround(kMinStepWidth / h)));
  for (int j = 1; j <= rows; ++j) {
    const Slice& lower = cell[j - 1];
    const Slice& upper = cell[j];
    if (upper.a + step <= lower.a || upper.b >= lower.b + step) along.emplace_back(j, false);
    if (lower.a + step <= upper.a || lower.b >= upper.b + step) along.emplace_back(j - 1, false);
  }
  std::sort(along.begin(), along.end(), [](const auto& x, const auto& y) {
    return x.first != y.first ? x.first < y.first : x.second > y.second;  // outer first
  });
  along.erase(std::unique(along.begin(), along.end(),
                          [](const auto& x, const auto& y) { return x.first == y.first; }),
              along.end());
  std::vector<Row> out;
  for (const auto& [index, outer] : along) {
    const Slice& s = cell[index];
    Row row{space.point(s.a, s.j), space.point(s.b, s.j)};
    if (outer) {
      const double out_dir = index == 0 ? -1 : 1;
      row = shifted(row, out_dir * farthestFree(h, [&](double t) {
                           return free(shifted(row, out_dir * t));
                         }));
    }
    row.left.x -= farthestFree(h, [&](double t) {
      return space.segmentFree({row.left.x - t, row.left.y}, row.left);
    });
    row.right.x += farthestFree(h, [&](double t) {
      return space.segmentFree(row.right, {row.right.x + t, row.right.y});
    });
    out.push_back(row);
  }
  return out;
}

/// Removes the rows whose floor other rows sweep as well, and shortens the others to the stretch
/// that sweeps floor no other row does. Cells overlap where they meet (each has its lowest and
/// highest row), and thin cells between nearby events (the tops of two pieces of furniture) are
/// mostly swept by their neighbours' rows; this drops that double work, losing no floor but
/// what rows of less than kMinRowGain of their own would sweep. Rows with the least floor of
/// their own go first; every row stays inside its original segment, so it stays free.
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
  for (auto& [own, row] : order) {
    // The shortest stretch [lo, hi] of the row within r of each point only it sweeps.
    double lo = row->right.x, hi = row->left.x;
    int own_now = 0;
    forPointsNear(space, row->left, row->right, r, [&](int k) {
      if (!floor[k] || sweeps[k] != 1) return;
      ++own_now;
      const Point2 p = space.point(k);
      const double reach = std::sqrt(r * r - (p.y - row->left.y) * (p.y - row->left.y));
      lo = std::min(lo, p.x + reach - kMinLegLength);
      hi = std::max(hi, p.x - reach + kMinLegLength);
    });
    stamp(*row, -1);
    if (own_now * space.resolution() * space.resolution() < kMinRowGain) {  // dropped
      *row = Row{{0, 0}, {-1, 0}};
      continue;
    }
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

/// Row `k` of the sweep as (start, end).
std::pair<Point2, Point2> rowOf(const std::vector<Row>& rows, Way way, std::size_t k) {
  const Row& row = rows[way.upwards ? k : rows.size() - 1 - k];
  const bool left_to_right = (k % 2 == 0) == way.first_left_to_right;
  return left_to_right ? std::pair{row.left, row.right} : std::pair{row.right, row.left};
}

/// A cell in the sweep order, and the way it is swept.
struct Visit {
  std::size_t cell = 0;
  Way way;
};

/// The order to sweep the cells with rows in: first greedily (from where the robot is, the cell
/// whose first row starts nearest), then improved by moving single cells to another place in the
/// order or sweeping them another way, while that shortens the straight jumps between cells (a
/// lower bound of the transits), at most kMaxOrderRounds times.
std::vector<Visit> orderCells(const std::vector<std::vector<Row>>& rows, const Point2& start) {
  auto entry = [&](const Visit& v) { return rowOf(rows[v.cell], v.way, 0).first; };
  auto exit = [&](const Visit& v) {
    return rowOf(rows[v.cell], v.way, rows[v.cell].size() - 1).second;
  };
  std::vector<Visit> order;
  std::vector<bool> done(rows.size(), false);
  Point2 at = start;
  for (;;) {
    std::optional<Visit> best;
    double best_distance = 0;
    for (std::size_t c = 0; c < rows.size(); ++c) {
      if (done[c] || rows[c].empty()) continue;
      for (const Way& way : kWays) {
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
        for (const Way& way : kWays) {
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
  const double points =
      std::ceil(world.width / options.resolution) * std::ceil(world.height / options.resolution);
  util::require(points <= kMaxLatticePoints, "resolution",
                "coarse enough for at most 2e7 lattice points in this world", options.resolution);
  return options;
}
}  // namespace

CoveragePlanner::CoveragePlanner(const world::World& world, const CoverageOptions& options)
    : options_(validated(world, options)), space_(world, options_.clearance, options_.resolution) {}

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

CoveragePlan CoveragePlanner::plan(const Point2& start) const {
  CoveragePlan plan;
  Mask floor(space_.size());
  for (int k = 0; k < space_.size(); ++k) floor[k] = space_.isFloor(k);
  plan.floor_area = area(space_, floor);
  plan.unreachable_area = plan.floor_area;

  // 1. What the robot can reach from the start: with its own radius (the floor it may touch),
  //    and with the clearance (where the rows and transits run).
  const std::optional<int> reach_seed = space_.connect(start, FreeSpace::kTight);
  const std::optional<int> plan_seed = space_.connect(start, FreeSpace::kFree);
  if (!reach_seed) return plan;
  const Mask reachable = floorReachedFrom(space_, flood(space_, *reach_seed, FreeSpace::kTight));
  plan.reachable_area = area(space_, reachable);
  plan.unreachable_area = plan.floor_area - plan.reachable_area;
  if (!plan_seed) return plan;

  // 2. Cells, and 3. the rows that cover each.
  const std::vector<Cell> cells = decompose(space_, flood(space_, *plan_seed, FreeSpace::kFree));
  plan.cells = static_cast<int>(cells.size());
  std::vector<std::vector<Row>> rows;
  for (const Cell& cell : cells) rows.push_back(cellRows(space_, cell, options_.swath));
  pruneRows(space_, reachable, rows);

  // 4. The order of the cells; 5. their rows, joined by transits.
  Mask swept(space_.size(), 0);
  Point2 at = start;
  for (const Visit& visit : orderCells(rows, start)) {
    for (std::size_t k = 0; k < rows[visit.cell].size(); ++k) {
      auto [row_start, row_end] = rowOf(rows[visit.cell], visit.way, k);
      // A row shortened to one side (pruneRows) may start nearer its other end.
      if (geometry::distance(at, row_end) < geometry::distance(at, row_start)) {
        std::swap(row_start, row_end);
      }
      const std::optional<Polyline> path = transit(at, row_start);
      if (!path) continue;  // cannot happen in one connected region; never assumed
      if (geometry::pathLength(*path) > kMinLegLength) {
        plan.legs.push_back(Leg{Leg::Kind::kTransit, *path});
      }
      plan.legs.push_back(Leg{Leg::Kind::kRow, {row_start, row_end}});
      forPointsNear(space_, row_start, row_end, space_.robotRadius(),
                    [&](int p) { swept[p] = reachable[p]; });
      at = row_end;
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
      todo.push_back(Leg{Leg::Kind::kRow, {from, row.back()}});
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
