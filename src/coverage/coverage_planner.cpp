#include "roomba_rrt/coverage/coverage_planner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

#include "roomba_rrt/coverage/boustrophedon.h"
#include "roomba_rrt/coverage/cell_order.h"
#include "roomba_rrt/coverage/reachable_floor.h"
#include "roomba_rrt/coverage/wall_loop.h"
#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/util/require.h"

namespace roomba_rrt::coverage {
namespace {

/// The most lattice points a planner samples (about 20 MB of working memory): a 100 m × 100 m
/// map at 0.025 m; a larger world needs a coarser resolution.
constexpr double kMaxLatticePoints = 2e7;

/// The loop along the walls (wall_loop.h) is driven after the rows when it sweeps at least this
/// much floor per metre of it (m²/m) that the rows do not: where the walls lie at a slant to the
/// rows. The turtlebot3 arena's loop sweeps 0.043 (its hexagon's slanted walls); the rooms and
/// crops of doc/coverage.md have 0.012–0.027: their rows end square to the walls, where a drive
/// round the room costs more time than the floor it sweeps is worth.
constexpr double kMinWallLoopGain = 0.035;

/// The widest island (m, across the lattice points around it where the disc lacks the
/// clearance: the obstacle grown by the planning radius) that rows pass around. 1 m: the
/// turtlebot3 arena's pillars (0.66 m), the furnished room's round table (0.96 m) and bin (0.76 m).
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
  open.room.circles.erase(
      std::remove_if(open.room.circles.begin(), open.room.circles.end(),
                     [&](const world::Circle& c) { return onIsland(c.center); }),
      open.room.circles.end());
  open.room.rectangles.erase(
      std::remove_if(open.room.rectangles.begin(), open.room.rectangles.end(),
                     [&](const world::Rectangle& r) {
                       return onIsland({(r.min_x + r.max_x) / 2, (r.min_y + r.max_y) / 2});
                     }),
      open.room.rectangles.end());
  if (open.room.map) {
    auto grid = std::make_shared<geometry::OccupancyGrid>(*open.room.map);
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
    open.room.map = grid;
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
  util::requirePositive("swath", options.swath, 2 * world.robot().radius, "m");
  util::requireInRange("resolution", options.resolution, 1e-3, world.robot().radius, "m");
  util::require(options.swath >= 2 * options.resolution, "swath", "at least twice the resolution",
                options.swath);
  util::requireInRange("clearance", options.clearance, 0.0, world.robot().radius, "m");
  util::requireInRange("edge_clearance", options.edge_clearance, 0.0, world.robot().radius, "m");
  const double points = std::ceil(world.room.width / options.resolution) *
                        std::ceil(world.room.height / options.resolution);
  util::require(points <= kMaxLatticePoints, "resolution",
                "coarse enough for at most 2e7 lattice points in this world", options.resolution);
  return options;
}
}  // namespace

CoverageOptions cleaningOptions(const world::World& world) {
  CoverageOptions options;
  options.resolution = world.coverage_cell_size;
  // The strips of neighbouring rows overlap: the Roomba's 0.335 m for its 0.17 m radius.
  options.swath =
      std::max(2 * world.robot().radius - CoverageOptions::kMinOverlap, 2 * options.resolution);
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

double CoveragePlanner::sweptFraction(const std::vector<std::uint8_t>& swept) const {
  long floor = 0, marked = 0;
  for (int k = 0; k < space_.size(); ++k) {
    if (!space_.isFloor(k)) continue;
    ++floor;
    marked += static_cast<std::size_t>(k) < swept.size() && swept[k] != 0;
  }
  return floor > 0 ? static_cast<double>(marked) / static_cast<double>(floor) : 0.0;
}

std::vector<std::pair<Point2, Point2>> CoveragePlanner::freePieces(const Point2& a, const Point2& b,
                                                                   double radius) const {
  if (space_.segmentFree(a, b, radius)) return {{a, b}};
  // Samples half a lattice step apart; each run of free ones is a piece, its ends moved out to
  // the island as far as they stay free (exactly), then kIslandBackOff back.
  const double length = geometry::distance(a, b);
  const int n = std::max(1, static_cast<int>(std::ceil(2 * length / space_.resolution())));
  auto at = [&](double t) { return Point2{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; };
  auto free = [&](const Point2& p, const Point2& q) { return space_.segmentFree(p, q, radius); };
  auto freeAt = [&](int k) { return free(at(double(k) / n), at(double(k) / n)); };
  std::vector<std::pair<Point2, Point2>> out;
  for (int k = 0; k <= n; ++k) {
    if (!freeAt(k)) continue;
    const int first = k;
    while (k < n && freeAt(k + 1)) ++k;
    double t0 = double(first) / n, t1 = double(k) / n;
    if (first > 0) t0 -= farthestFree(1.0 / n, [&](double d) { return free(at(t0 - d), at(t0)); });
    if (k < n) t1 += farthestFree(1.0 / n, [&](double d) { return free(at(t1), at(t1 + d)); });
    if (first > 0) t0 += kIslandBackOff / length;
    if (k < n) t1 -= kIslandBackOff / length;
    if ((t1 - t0) * length > kMinLegLength && free(at(t0), at(t1))) {
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
    for (std::size_t w = 0; w < std::size(kWays); ++w) sweeps[c][w] = sweepRows(rows[c], kWays[w]);
  }
  for (const CellVisit& visit : orderCells(sweeps, start)) {
    for (auto [row_start, row_end] : sweeps[visit.cell][visit.way]) {
      const std::vector<std::pair<Point2, Point2>> pieces =
          open_ ? freePieces(row_start, row_end, space_.planningRadius())
                : std::vector<std::pair<Point2, Point2>>{{row_start, row_end}};
      for (auto [piece_start, piece_end] : pieces) {
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

CoveragePlan CoveragePlanner::repair(const CoveragePlan& plan, std::size_t leg,
                                     const Point2& at) const {
  CoveragePlan rest = plan;
  rest.legs.clear();
  Point2 from = at;
  // Appends `row` (cut to its free pieces) after a transit from where the last one ended.
  auto add = [&](const Leg& row) {
    const double radius =
        space_.robotRadius() + (row.along_wall ? options_.edge_clearance : options_.clearance);
    std::vector<Polyline> pieces;
    if (row.points.size() == 2) {
      for (auto [a, b] : freePieces(row.points.front(), row.points.back(), radius)) {
        pieces.push_back({a, b});
      }
    } else {  // a polyline (a row along a wall, ramping in and out): whole or not at all
      bool free = !row.points.empty();
      for (std::size_t k = 0; free && k + 1 < row.points.size(); ++k) {
        free = space_.segmentFree(row.points[k], row.points[k + 1], radius);
      }
      if (free) pieces.push_back(row.points);
    }
    for (Polyline& piece : pieces) {
      const std::optional<Polyline> path = transit(from, piece.front());
      if (!path) continue;  // cannot be reached from here any more
      if (geometry::pathLength(*path) > kMinLegLength) {
        rest.legs.push_back(Leg{Leg::Kind::kTransit, *path});
      }
      from = piece.back();
      rest.legs.push_back(Leg{Leg::Kind::kRow, std::move(piece), row.along_wall});
    }
  };
  for (std::size_t k = leg; k < plan.legs.size(); ++k) {
    const Leg& row = plan.legs[k];
    if (row.kind != Leg::Kind::kRow || row.points.empty()) continue;
    if (k == leg && row.points.size() == 2) {  // the rest of the row the robot is in
      const Point2 closest = geometry::closestPoint({row.points.front(), row.points.back()}, at);
      if (geometry::distance(closest, row.points.back()) <= kMinLegLength) continue;
      add(Leg{Leg::Kind::kRow, {closest, row.points.back()}, row.along_wall});
      continue;
    }
    add(row);
  }
  return rest;
}

}  // namespace roomba_rrt::coverage
