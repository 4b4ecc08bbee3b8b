// Ray casting (ray_cast.h) against two oracles: for furniture worlds, fine sampling of the ray
// with point tests (penetrates' shapes, a disc of radius ~0) refined by bisection; for maps,
// every blocked cell's square near the ray intersected on its own (no walk, no jumps). Random
// rooms, random maps, the real willow_full map, and the hard rays: along grid lines and through
// cell corners.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "../common/shared_maps.h"
#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/sensors/ray_cast.h"

namespace roomba_rrt::sensors {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kExact = 1e-9;  // m

using geometry::Circle;
using geometry::OccupancyGrid;
using geometry::Point2;
using geometry::Rectangle;

Point2 at(const Ray& ray, double t) {
  return {ray.origin.x + t * ray.dx, ray.origin.y + t * ray.dy};
}

/// Whether `p` is in a wall (outside the room or on its border) or a closed piece of furniture.
bool solid(const world::Room& room, const Point2& p) {
  if (!(p.x > room.origin.x && p.x < room.origin.x + room.width && p.y > room.origin.y &&
        p.y < room.origin.y + room.height)) {
    return true;
  }
  for (const Circle& c : room.circles) {
    if (geometry::contains(c, p)) return true;
  }
  for (const Rectangle& b : room.rectangles) {
    if (geometry::contains(b, p)) return true;
  }
  return false;
}

/// The first solid point along the ray within max_range: samples every `step`, then bisects
/// between the last free sample and the first solid one. A crossing shorter than `step` (a
/// graze) can be missed: the callers allow the cast to be nearer, never farther.
double sampledHit(const world::Room& room, const Ray& ray, double max_range, double step) {
  if (solid(room, ray.origin)) return 0;
  double free_t = 0;
  for (double t = step;; t += step) {
    const double probe = std::min(t, max_range + step);
    if (solid(room, at(ray, probe))) {
      double lo = free_t, hi = probe;
      for (int k = 0; k < 80; ++k) {
        const double mid = 0.5 * (lo + hi);
        (solid(room, at(ray, mid)) ? hi : lo) = mid;
      }
      return hi <= max_range ? hi : kInf;
    }
    free_t = probe;
    if (probe > max_range) return kInf;
  }
}

/// Every blocked square of the map within max_range of the origin, intersected on its own, and
/// the room's walls.
double bruteMapHit(const world::Room& room, const Ray& ray, double max_range) {
  const OccupancyGrid& g = *room.map;
  double best = leaveRectangle(
      ray, {room.origin.x, room.origin.y, room.origin.x + room.width, room.origin.y + room.height});
  const Point2 end = at(ray, max_range);
  const int i0 = g.column(std::min(ray.origin.x, end.x)) - 1;
  const int i1 = g.column(std::max(ray.origin.x, end.x)) + 1;
  const int j0 = g.row(std::min(ray.origin.y, end.y)) - 1;
  const int j1 = g.row(std::max(ray.origin.y, end.y)) + 1;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      if (g.blocked(i, j)) best = std::min(best, hitRectangle(ray, g.square(i, j)));
    }
  }
  return best <= max_range ? best : kInf;
}

Ray rayAt(const Point2& origin, double angle) { return {origin, std::cos(angle), std::sin(angle)}; }

TEST(RayCast, shapes_are_closed_and_hit_at_their_near_side) {
  const Ray ray = rayAt({0, 0}, 0);
  EXPECT_DOUBLE_EQ(hitCircle(ray, {{3, 0}, 1}), 2);
  EXPECT_DOUBLE_EQ(hitCircle(ray, {{3, 1}, 1}), 3);  // tangent: touching counts
  EXPECT_EQ(hitCircle(ray, {{3, 1.5}, 1}), kInf);
  EXPECT_EQ(hitCircle(ray, {{-3, 0}, 1}), kInf);  // behind
  EXPECT_EQ(hitCircle(ray, {{0.5, 0}, 1}), 0);    // the origin is inside
  EXPECT_DOUBLE_EQ(hitRectangle(ray, {2, -1, 3, 1}), 2);
  EXPECT_DOUBLE_EQ(hitRectangle(ray, {2, 0, 3, 1}), 2);  // along its lower side
  EXPECT_EQ(hitRectangle(ray, {2, 0.1, 3, 1}), kInf);
  EXPECT_DOUBLE_EQ(leaveRectangle(ray, {-1, -1, 4, 1}), 4);
  EXPECT_EQ(leaveRectangle(ray, {0, -1, 4, 1}), 0);  // on the wall
}

TEST(RayCast, a_ray_reads_the_nearest_surface_or_infinity_beyond_range) {
  world::Room room;  // 6.4 x 4.8
  room.circles.push_back({{3.2, 3.4}, 0.5});
  const RayCaster caster(room);
  EXPECT_DOUBLE_EQ(caster.cast(rayAt({3.2, 2.4}, 0), 10), 3.2);
  EXPECT_DOUBLE_EQ(caster.cast(rayAt({3.2, 2.4}, M_PI / 2), 10), 0.5);
  EXPECT_EQ(caster.cast(rayAt({3.2, 2.4}, 0), 3.1), kInf);
  EXPECT_DOUBLE_EQ(caster.cast(rayAt({3.2, 2.4}, 0), 3.2), 3.2);  // at range_max: a return
  // Another robot's disc.
  EXPECT_DOUBLE_EQ(caster.cast(rayAt({3.2, 2.4}, 0), 10, {{{4.2, 2.4}, 0.17}}), 0.83);
}

TEST(RayCast, random_furnished_rooms_match_sampling_and_bisection) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> u(0, 1);
  int hits = 0;
  for (int w = 0; w < 60; ++w) {
    world::Room room;
    room.width = 2 + 6 * u(rng);
    room.height = 2 + 6 * u(rng);
    room.origin = {-5 + 10 * u(rng), -5 + 10 * u(rng)};
    const auto rx = [&] { return room.origin.x + room.width * u(rng); };
    const auto ry = [&] { return room.origin.y + room.height * u(rng); };
    for (int k = 0; k < 8; ++k) room.circles.push_back({{rx(), ry()}, 0.05 + 0.4 * u(rng)});
    for (int k = 0; k < 8; ++k) {
      const double x = rx(), y = ry();
      room.rectangles.push_back({x, y, x + 0.05 + 0.8 * u(rng), y + 0.05 + 0.8 * u(rng)});
    }
    const RayCaster caster(room);
    for (int r = 0; r < 200; ++r) {
      const Point2 o{rx(), ry()};
      if (solid(room, o)) continue;
      const Ray ray = rayAt(o, 2 * M_PI * u(rng));
      const double max_range = 0.5 + 5 * u(rng);
      const double t = caster.cast(ray, max_range);
      const double oracle = sampledHit(room, ray, max_range, 1e-3);
      SCOPED_TRACE(::testing::Message() << "world " << w << " ray " << r);
      if (oracle == kInf) {
        // No crossing thicker than the sampling step: at most a graze, on a surface.
        if (t != kInf) {
          EXPECT_TRUE(solid(room, at(ray, t)));
        }
        continue;
      }
      ASSERT_LE(t, oracle + kExact);
      // Nearer than the oracle only by a graze it could not sample: the point is on a surface.
      if (t < oracle - kExact) {
        EXPECT_TRUE(solid(room, at(ray, t))) << t << " vs " << oracle;
      }
      hits += std::abs(t - oracle) <= kExact;
    }
  }
  EXPECT_GT(hits, 5000);  // most rays compared exactly
}

/// A random map: `blocked` of its cells occupied, a few unknown, at a random origin.
std::shared_ptr<const OccupancyGrid> randomMap(std::mt19937& rng, double blocked) {
  std::uniform_real_distribution<double> u(0, 1);
  auto g = std::make_shared<OccupancyGrid>();
  g->width = 20 + static_cast<int>(40 * u(rng));
  g->height = 20 + static_cast<int>(40 * u(rng));
  g->resolution = 0.025 + 0.1 * u(rng);
  g->origin = {-3 + 6 * u(rng), -3 + 6 * u(rng)};
  g->cells.resize(static_cast<std::size_t>(g->width) * g->height);
  for (auto& c : g->cells) {
    const double v = u(rng);
    c = v < blocked ? OccupancyGrid::kOccupied
                    : (v < blocked * 1.1 ? OccupancyGrid::kUnknown : OccupancyGrid::kFree);
  }
  g->cells[0] = OccupancyGrid::kOccupied;  // known corners: the room is the whole grid
  g->cells.back() = OccupancyGrid::kOccupied;
  return g;
}

world::Room mapRoom(std::shared_ptr<const OccupancyGrid> grid) {
  world::World world;
  world::useMap(world, std::move(grid), "");
  return world.room;
}

/// Casts `rays` random rays from free points of the room's map and compares with bruteMapHit.
void compareOnMap(const world::Room& room, std::mt19937& rng, int rays, double max_range) {
  const OccupancyGrid& g = *room.map;
  const RayCaster caster(room);
  std::uniform_real_distribution<double> u(0, 1);
  int cast = 0;
  for (int tries = 0; cast < rays && tries < 100 * rays; ++tries) {
    const Point2 o{room.origin.x + room.width * u(rng), room.origin.y + room.height * u(rng)};
    if (geometry::distanceToBlocked(g, o, g.resolution) == 0) continue;
    ++cast;
    const Ray ray = rayAt(o, 2 * M_PI * u(rng));
    const double t = caster.cast(ray, max_range);
    const double oracle = bruteMapHit(room, ray, max_range);
    if (oracle == kInf) {
      ASSERT_EQ(t, kInf) << "ray " << cast;
    } else {
      ASSERT_NEAR(t, oracle, kExact) << "ray " << cast << " from " << o.x << ", " << o.y;
    }
  }
  EXPECT_EQ(cast, rays);
}

TEST(RayCast, random_maps_match_every_blocked_square) {
  std::mt19937 rng(7);
  for (int m = 0; m < 40; ++m) {
    SCOPED_TRACE(::testing::Message() << "map " << m);
    // Sparse maps make long free runs: the walk jumps over them.
    compareOnMap(mapRoom(randomMap(rng, m % 2 ? 0.3 : 0.02)), rng, 300, 8);
  }
}

TEST(RayCast, rays_along_grid_lines_and_through_corners_touch_the_squares_beside_them) {
  auto g = std::make_shared<OccupancyGrid>();
  g->width = g->height = 10;
  g->resolution = 0.5;
  g->cells.assign(100, OccupancyGrid::kFree);
  const auto block = [&](int i, int j) { g->cells[j * 10 + i] = OccupancyGrid::kOccupied; };
  block(6, 4);  // [3, 3.5] x [2, 2.5]: below the line y = 2.5
  block(4, 7);  // [2, 2.5] x [3.5, 4]: right of the line x = 2
  const world::Room room = mapRoom(g);
  const RayCaster caster(room);
  // Along y = 2.5 (the top side of row 4): cell (6, 4)'s square touches it at x = 3.
  EXPECT_NEAR(caster.cast(rayAt({0.75, 2.5}, 0), 10), 2.25, kExact);
  // Along x = 2.0 upwards: cell (4, 7) spans x 2.0..2.5, its side at y = 3.5.
  EXPECT_NEAR(caster.cast({{2.0, 0.75}, 0, 1}, 10), 2.75, kExact);
  // Every lattice point, eight directions: the walk agrees with the squares.
  std::mt19937 rng(1);
  for (int m = 0; m < 8; ++m) {
    const world::Room r = mapRoom(randomMap(rng, 0.15));
    const OccupancyGrid& grid = *r.map;
    const RayCaster c(r);
    for (int j = 1; j < grid.height; ++j) {
      for (int i = 1; i < grid.width; ++i) {
        const Point2 o{grid.origin.x + i * grid.resolution, grid.origin.y + j * grid.resolution};
        if (geometry::distanceToBlocked(grid, o, grid.resolution) == 0) continue;
        for (int d = 0; d < 8; ++d) {
          Ray ray = rayAt(o, d * M_PI / 4);
          if (d % 2 == 0) {  // exactly axis-parallel
            ray.dx = std::round(ray.dx);
            ray.dy = std::round(ray.dy);
          } else {
            ray.dx = (d == 1 || d == 7 ? 1 : -1) * M_SQRT1_2;
            ray.dy = (d == 1 || d == 3 ? 1 : -1) * M_SQRT1_2;
          }
          const double oracle = bruteMapHit(r, ray, 1.5), t = c.cast(ray, 1.5);
          if (oracle == kInf) {
            ASSERT_EQ(t, kInf) << i << ", " << j << " dir " << d;
          } else {
            ASSERT_NEAR(t, oracle, kExact) << i << ", " << j << " dir " << d;
          }
        }
      }
    }
  }
}

TEST(RayCast, willow_full_matches_every_blocked_square) {
  ROOMBA_RRT_REQUIRE_SHARED_MAP("willow_full");
  geometry::MapFile map = geometry::loadMap(test::sharedMapPath("willow_full"));
  const world::Room room = mapRoom(std::make_shared<const OccupancyGrid>(std::move(map.grid)));
  std::mt19937 rng(11);
  compareOnMap(room, rng, 3000, 3.5);
  compareOnMap(room, rng, 300, 30);
}

TEST(RayCast, rays_through_lattice_points_at_other_slopes_touch_the_corners_they_pass) {
  // From every lattice point along (p, q) for small whole p, q: the ray passes exactly through
  // further lattice points (cell corners), where rounding may put it on either side.
  std::mt19937 rng(5);
  for (int m = 0; m < 6; ++m) {
    const world::Room r = mapRoom(randomMap(rng, 0.2));
    const OccupancyGrid& grid = *r.map;
    const RayCaster c(r);
    for (int j = 1; j < grid.height; j += 2) {
      for (int i = 1; i < grid.width; i += 2) {
        const Point2 o{grid.origin.x + i * grid.resolution, grid.origin.y + j * grid.resolution};
        if (geometry::distanceToBlocked(grid, o, grid.resolution) == 0) continue;
        for (int p = -3; p <= 3; ++p) {
          for (int q = -3; q <= 3; ++q) {
            if (std::abs(p) + std::abs(q) < 3 || std::abs(p) == std::abs(q)) continue;
            const double n = std::hypot(p, q);
            const Ray ray{o, p / n, q / n};
            const double oracle = bruteMapHit(r, ray, 2.5), t = c.cast(ray, 2.5);
            if (oracle == kInf) {
              ASSERT_EQ(t, kInf) << i << ", " << j << " along " << p << ", " << q;
            } else {
              ASSERT_NEAR(t, oracle, kExact) << i << ", " << j << " along " << p << ", " << q;
            }
          }
        }
      }
    }
  }
}

TEST(RayCast, beyond_the_maps_edge_is_a_wall_even_in_a_larger_room) {
  // A room reaching past its map (a hand-made Room): the squares beyond the grid are blocked, as
  // for contact; an origin beyond the grid is in one.
  std::mt19937 rng(9);
  for (int m = 0; m < 6; ++m) {
    world::Room room = mapRoom(randomMap(rng, 0.01));
    const OccupancyGrid& g = *room.map;
    room.origin = {g.origin.x - 1, g.origin.y - 1};
    room.width = g.width * g.resolution + 2;
    room.height = g.height * g.resolution + 2;
    const RayCaster caster(room);
    std::uniform_real_distribution<double> u(0, 1);
    const double reach = std::hypot(room.width, room.height);  // every ray ends in the room
    for (int r = 0; r < 100; ++r) {
      const Point2 o{g.origin.x + g.width * g.resolution * u(rng),
                     g.origin.y + g.height * g.resolution * u(rng)};
      const Ray ray = rayAt(o, 2 * M_PI * u(rng));
      const double oracle = bruteMapHit(room, ray, reach), t = caster.cast(ray, reach);
      ASSERT_LT(oracle, kInf);
      ASSERT_NEAR(t, oracle, kExact) << "map " << m << " ray " << r;
    }
    EXPECT_EQ(caster.cast(rayAt({g.origin.x - 0.5, g.origin.y + 0.5}, 0), 10), 0);
  }
}

}  // namespace
}  // namespace roomba_rrt::sensors
