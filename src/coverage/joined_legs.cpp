#include "roomba_rrt/coverage/joined_legs.h"

#include <cmath>
#include <optional>

#include "roomba_rrt/geometry/geometry.h"

namespace roomba_rrt::coverage {

namespace {

/// The way the first (`last`: the last) stretch of `points` that has a length goes; nullopt when
/// none has (a touch-up stop: a row of no length).
std::optional<Point2> stretch(const Polyline& points, bool last) {
  for (std::size_t s = 0; s + 1 < points.size(); ++s) {
    const std::size_t i = last ? points.size() - 2 - s : s;
    const Point2 d{points[i + 1].x - points[i].x, points[i + 1].y - points[i].y};
    if (d.x != 0 || d.y != 0) return d;
  }
  return std::nullopt;
}

/// The rules of joinLegs, over one plan's legs.
class Joiner {
 public:
  Joiner(const std::vector<Leg>& legs, std::size_t first, bool touching_up)
      : legs_(legs), first_(first), touching_up_(touching_up) {}

  /// True when the turn where leg k starts, from the last stretch driven before it to the first
  /// one from there on, is no sharper than JoinRules::kMaxTurn. A touch-up stop (a row of no
  /// length) does not hide the turn through it.
  bool gentle(std::size_t k) const {
    std::optional<Point2> in, out;
    for (std::size_t m = k; m-- > 0 && !in;) in = stretch(legs_[m].points, true);
    for (std::size_t m = k; m < legs_.size() && !out; ++m) out = stretch(legs_[m].points, false);
    if (!in || !out) return true;
    const double norms = std::hypot(in->x, in->y) * std::hypot(out->x, out->y);
    return (in->x * out->x + in->y * out->y) / norms >= std::cos(JoinRules::kMaxTurn);
  }

  /// True when transit k is the way round an island from one piece of a row to the next, which
  /// goes on along the same line, the same way (CoveragePlanner cuts rows at islands).
  bool roundsIsland(std::size_t k) const {
    if (k == 0 || legs_[k - 1].kind != Leg::Kind::kRow ||
        geometry::pathLength(legs_[k].points) > JoinRules::kDetour) {
      return false;
    }
    const Point2 a = legs_[k - 1].points.front(), b = legs_[k - 1].points.back();
    const Point2 c = legs_[k + 1].points.front(), d = legs_[k + 1].points.back();
    const double ux = b.x - a.x, uy = b.y - a.y, length = std::hypot(ux, uy);
    auto onLine = [&](const Point2& p) {
      return std::fabs(ux * (p.y - a.y) - uy * (p.x - a.x)) <= 1e-9 * length;
    };
    return length > 0 && onLine(c) && onLine(d) && ux * (c.x - b.x) + uy * (c.y - b.y) > 0 &&
           ux * (d.x - c.x) + uy * (d.y - c.y) > 0 && gentle(k) && gentle(k + 1);
  }

  /// True when leg k is a transit driven with the row after it: a U-turn's short step (in the
  /// touch-up only where it turns gently), or the way round an island.
  bool joinable(std::size_t k) const {
    if (k + 1 >= legs_.size() || legs_[k].kind != Leg::Kind::kTransit ||
        legs_[k + 1].kind != Leg::Kind::kRow || legs_[k + 1].along_wall) {
      return false;
    }
    const bool u_turn = geometry::pathLength(legs_[k].points) <= JoinRules::kTransit &&
                        (!touching_up_ || (gentle(k + 1) && (k == first_ || gentle(k))));
    return u_turn || roundsIsland(k);
  }

  /// True when row k goes on from where the row before it ended, without turning back (the loop
  /// along the walls: its segments are rows, wall_loop.h).
  bool continues(std::size_t k) const {
    auto row = [&](std::size_t m) {
      return legs_[m].kind == Leg::Kind::kRow && !legs_[m].along_wall &&
             stretch(legs_[m].points, false).has_value();
    };
    if (k == 0 || k >= legs_.size() || !row(k) || !row(k - 1)) return false;
    const Point2 &from = legs_[k - 1].points.back(), &to = legs_[k].points.front();
    return from.x == to.x && from.y == to.y && gentle(k);
  }

 private:
  const std::vector<Leg>& legs_;
  std::size_t first_;
  bool touching_up_;
};

}  // namespace

JoinedLegs joinLegs(const std::vector<Leg>& legs, std::size_t first, bool touching_up,
                    const FreeSpace& free_space) {
  const Joiner joiner(legs, first, touching_up);
  JoinedLegs joined;
  joined.path = legs[first].points;
  joined.cleaning = legs[first].kind == Leg::Kind::kRow || joiner.joinable(first);
  if (!joined.cleaning) return joined;
  std::vector<std::size_t> starts;  // the points of the path where the joined legs start
  const auto join = [&](std::size_t m) {
    starts.push_back(joined.path.size() - 1);
    joined.path.insert(joined.path.end(), legs[m].points.begin() + 1, legs[m].points.end());
  };
  std::size_t k = first;
  if (legs[first].kind == Leg::Kind::kTransit) join(++k);  // the row it leads to
  for (;;) {
    if (joiner.continues(k + 1)) {
      join(++k);
    } else if (joiner.joinable(k + 1)) {
      join(k + 1);
      join(k + 2);
      k += 2;
    } else {
      break;
    }
  }
  if (!starts.empty()) {
    std::vector<double> passes;
    joined.path = free_space.rounded(joined.path, JoinRules::kTurnRadius, &passes);
    for (const std::size_t point : starts) joined.ends.push_back(passes[point]);
  }
  return joined;
}

}  // namespace roomba_rrt::coverage
