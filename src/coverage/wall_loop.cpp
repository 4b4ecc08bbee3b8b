#include "roomba_rrt/coverage/wall_loop.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace roomba_rrt::coverage {
namespace {

/// The eight neighbours of a lattice point, counter-clockwise from east.
constexpr int kDi[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kDj[8] = {0, 1, 1, 1, 0, -1, -1, -1};

/// Two segments whose directions' cross product is below this (the sine of the angle between
/// them) are taken as parallel where their moved copies meet.
constexpr double kParallel = 0.2;

/// The boundary points of the piece of kFree points numbered `piece` in order, clockwise, from
/// its lowest (then leftmost) point: Moore-neighbour tracing, which stops when it leaves the first
/// point the way it first did (Jacob's criterion: a point where the piece is one point wide is
/// passed twice).
std::vector<Point2> traceBoundary(const FreeSpace& space, std::uint32_t piece) {
  int start = 0;
  while (start < space.size() && space.piece(start) != piece) ++start;
  auto inside = [&](int i, int j) {
    return space.inside(i, j) && space.piece(space.index(i, j)) == piece;
  };
  std::vector<Point2> traced{space.point(start)};
  int at = start;
  int back = 4;  // the neighbour we came from (outside the region): the lowest point's west
  int first_move = -1;
  const int most = 4 * space.size();
  for (int step = 0; step < most; ++step) {
    const int i = space.column(at), j = space.row(at);
    // Clockwise round `at` from the neighbour we came from: the first one inside is next, and
    // the one before it (outside) is where we come from when we look round the next point.
    int move = -1, outside = back;
    for (int turn = 1; turn <= 8 && move < 0; ++turn) {
      const int d = (back - turn + 8) % 8;
      if (inside(i + kDi[d], j + kDj[d])) {
        move = d;
      } else {
        outside = d;
      }
    }
    if (move < 0) return traced;  // a single point
    if (at == start) {
      if (step > 0 && move == first_move) break;
      if (step == 0) first_move = move;
    }
    const int ni = i + kDi[move], nj = j + kDj[move];
    const int bi = i + kDi[outside] - ni, bj = j + kDj[outside] - nj;
    for (int d = 0; d < 8; ++d) {
      if (kDi[d] == bi && kDj[d] == bj) back = d;
    }
    at = space.index(ni, nj);
    traced.push_back(space.point(at));
  }
  if (traced.size() > 1 && at == start) traced.pop_back();  // the loop closes on its first point
  return traced;
}

/// `traced` (closed: the first point follows the last) as the longest free segments from one of
/// its points to another that pass within kLoopTolerance of every point they skip. Closed: the
/// first point is repeated at the end.
Polyline simplified(const FreeSpace& space, std::vector<Point2> traced) {
  traced.push_back(traced.front());
  Polyline loop{traced.front()};
  for (std::size_t i = 0; i + 1 < traced.size();) {
    std::size_t j = i + 1;
    for (; j + 1 < traced.size(); ++j) {
      const geometry::Segment longer{traced[i], traced[j + 1]};
      bool keeps = space.segmentFree(longer.a, longer.b);
      for (std::size_t m = i + 1; keeps && m <= j; ++m) {
        keeps = geometry::distance(geometry::closestPoint(longer, traced[m]), traced[m]) <=
                kLoopTolerance;
      }
      if (!keeps) break;
    }
    loop.push_back(traced[j]);
    i = j;
  }
  return loop;
}

/// Each segment of the closed `loop` moved out (away from the region, which lies on its right
/// for a clockwise loop) as far as it stays free, up to kLoopPushOut lattice steps, and each
/// corner where the moved segments meet. A corner that is not free, or whose segments are not,
/// stays where it was; the loop itself when the result is not free throughout.
Polyline pushedOut(const FreeSpace& space, const Polyline& loop) {
  const std::size_t n = loop.size() - 1;  // loop[n] == loop[0]
  double twice_area = 0;                  // > 0: counter-clockwise
  for (std::size_t k = 0; k < n; ++k) {
    twice_area += loop[k].x * loop[k + 1].y - loop[k + 1].x * loop[k].y;
  }
  std::vector<Point2> along(n), out(n);
  std::vector<double> moved(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Point2 a = loop[k], b = loop[k + 1];
    const double length = geometry::distance(a, b);
    along[k] = {(b.x - a.x) / length, (b.y - a.y) / length};
    out[k] = twice_area > 0 ? Point2{along[k].y, -along[k].x} : Point2{-along[k].y, along[k].x};
    moved[k] = farthestFree(kLoopPushOut * space.resolution(), [&](double t) {
      return space.segmentFree({a.x + t * out[k].x, a.y + t * out[k].y},
                               {b.x + t * out[k].x, b.y + t * out[k].y});
    });
  }
  Polyline pushed(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t before = (k + n - 1) % n;
    const Point2 corner = loop[k];
    const Point2 p{corner.x + moved[before] * out[before].x,
                   corner.y + moved[before] * out[before].y};
    const Point2 q{corner.x + moved[k] * out[k].x, corner.y + moved[k] * out[k].y};
    const double cross = along[before].x * along[k].y - along[before].y * along[k].x;
    Point2 meet = corner;
    if (std::fabs(cross) < kParallel) {  // nearly straight on: out by the lesser move
      const double m = std::min(moved[before], moved[k]);
      meet = {corner.x + m * (out[before].x + out[k].x) / 2,
              corner.y + m * (out[before].y + out[k].y) / 2};
    } else {  // where the line through p along `before` meets the one through q along k
      const double s = ((q.x - p.x) * along[k].y - (q.y - p.y) * along[k].x) / cross;
      meet = {p.x + s * along[before].x, p.y + s * along[before].y};
      if (geometry::distance(meet, corner) > 2 * kLoopPushOut * space.resolution()) meet = corner;
    }
    pushed[k] = space.segmentFree(meet, meet) ? meet : corner;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t next = (k + 1) % n;
    if (!space.segmentFree(pushed[k], pushed[next])) {
      pushed[k] = loop[k];
      pushed[next] = loop[next];
    }
  }
  pushed.push_back(pushed.front());
  for (std::size_t k = 0; k < n; ++k) {
    if (!space.segmentFree(pushed[k], pushed[k + 1])) return loop;
  }
  return pushed;
}

}  // namespace

Polyline wallLoop(const FreeSpace& space, int seed) {
  if (seed < 0 || seed >= space.size() || space.piece(seed) == 0) return {};
  std::vector<Point2> traced = traceBoundary(space, space.piece(seed));
  if (traced.size() < 3) return {};
  const Polyline loop = simplified(space, std::move(traced));
  if (loop.size() < 4) return {};
  return pushedOut(space, loop);
}

}  // namespace roomba_rrt::coverage
