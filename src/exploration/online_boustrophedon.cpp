#include "roomba_rrt/exploration/online_boustrophedon.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <utility>

#include "roomba_rrt/geometry/distance_transform.h"

namespace roomba_rrt::exploration {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr Heading kHeadings[] = {Heading::kEast, Heading::kWest, Heading::kNorth, Heading::kSouth};
/// m: a shift that cannot go this far is no shift.
constexpr double kLeastShift = 0.01;
/// The centres a transit passes: safe ones, and (kBeenCost times as long, only where there is no
/// other way) those the robot has been on but that lie within reach of what it found since.
constexpr char kSafe = 1, kBeen = 2;
constexpr double kBeenCost = 20;
/// m: a transit may begin at a safe centre this near the robot (straight from where it stands).
constexpr double kLeaveRadius = 0.1;
/// m: two points found this near the same distance ahead, one on each side of the way, are
/// taken for one straight wall across it.
constexpr double kInLine = 0.03;

bool alongRows(Heading h) { return h == Heading::kEast || h == Heading::kWest; }

}  // namespace

geometry::Point2 unit(Heading heading) {
  switch (heading) {
    case Heading::kEast:
      return {1, 0};
    case Heading::kWest:
      return {-1, 0};
    case Heading::kNorth:
      return {0, 1};
    case Heading::kSouth:
      return {0, -1};
  }
  return {1, 0};
}

double yaw(Heading heading) {
  switch (heading) {
    case Heading::kEast:
      return 0;
    case Heading::kWest:
      return kPi;
    case Heading::kNorth:
      return kPi / 2;
    case Heading::kSouth:
      return -kPi / 2;
  }
  return 0;
}

Heading opposite(Heading heading) {
  switch (heading) {
    case Heading::kEast:
      return Heading::kWest;
    case Heading::kWest:
      return Heading::kEast;
    case Heading::kNorth:
      return Heading::kSouth;
    case Heading::kSouth:
      return Heading::kNorth;
  }
  return heading;
}

const char* toString(Heading heading) {
  switch (heading) {
    case Heading::kEast:
      return "east";
    case Heading::kWest:
      return "west";
    case Heading::kNorth:
      return "north";
    case Heading::kSouth:
      return "south";
  }
  return "?";
}

OnlineBoustrophedon::OnlineBoustrophedon(const geometry::Point2& start, double start_yaw,
                                         const BoustrophedonOptions& options)
    : options_(options),
      line_y_(start.y),
      // next() drives the row opposite to the last one first: the first row goes the way the
      // robot faces.
      row_heading_(std::cos(start_yaw) >= 0 ? Heading::kWest : Heading::kEast) {}

double OnlineBoustrophedon::newFloor(const SweptMap& map, const geometry::Point2& from,
                                     Heading heading, double length) {
  const geometry::Point2 u = unit(heading);
  const double l = map.freeLength(from, u, length);
  if (l <= 0) return 0;
  const geometry::Point2 to{from.x + l * u.x, from.y + l * u.y};
  const double r = map.radius(), r2 = r * r;
  const Cell lo = map.cellOf({std::min(from.x, to.x) - r, std::min(from.y, to.y) - r});
  const Cell hi = map.cellOf({std::max(from.x, to.x) + r, std::max(from.y, to.y) + r});
  long count = 0;
  for (int j = lo.j; j <= hi.j; ++j) {
    for (int i = lo.i; i <= hi.i; ++i) {
      const Cell c{i, j};
      if (!map.unknown(c)) continue;
      const geometry::Point2 p = map.centre(c);
      if (geometry::squaredDistance(p, from) <= r2) continue;  // under the disc already
      const double along = std::clamp((p.x - from.x) * u.x + (p.y - from.y) * u.y, 0.0, l);
      if (geometry::squaredDistance(p, {from.x + along * u.x, from.y + along * u.y}) <= r2) {
        ++count;
      }
    }
  }
  return static_cast<double>(count) * map.resolution() * map.resolution();
}

double OnlineBoustrophedon::nextRowLine(double y, Heading side) const {
  const double s = options_.swath;
  const double line = side == Heading::kNorth
                          ? line_y_ + std::ceil((y + options_.min_shift - line_y_) / s - 1e-9) * s
                          : line_y_ + std::floor((y - options_.min_shift - line_y_) / s + 1e-9) * s;
  // A row line nearer than half a swath (the robot is on a row along a wall, off the lines): a
  // swath on, not a sliver.
  if (std::abs(line - y) < s / 2) return side == Heading::kNorth ? y + s : y - s;
  return line;
}

std::int64_t OnlineBoustrophedon::tryKey(const SweptMap& map, const geometry::Point2& from,
                                         Heading heading) {
  const Cell c = map.cellOf(from);
  return (static_cast<std::int64_t>(c.i) * 1000003 + c.j) * 4 + static_cast<int>(heading);
}

bool OnlineBoustrophedon::triedOut(const SweptMap& map, const geometry::Point2& from,
                                   Heading heading) const {
  const auto it = tries_.find(tryKey(map, from, heading));
  return it != tries_.end() && it->second >= options_.max_tries;
}

void OnlineBoustrophedon::sweptNothing(const SweptMap& map, const Move& move) {
  tries_[tryKey(map, move.start, move.heading)] = options_.max_tries;
}

Move OnlineBoustrophedon::chosen(const SweptMap& map, Move move, double gain) {
  move.gain = gain;
  ++tries_[tryKey(map, move.start, move.heading)];
  last_ = move.kind;
  (move.kind == Move::Kind::kRow ? row_heading_ : side_) = move.heading;
  return move;
}

double OnlineBoustrophedon::guessedWall(const SweptMap& map, const geometry::Point2& from,
                                        Heading heading, double max) const {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const geometry::Point2 u = unit(heading), v{-u.y, u.x};
  const double w = options_.wall_gap;
  // On each side of the way ahead, the point found nearest to it.
  struct Nearest {
    double across = kNone, along = 0;
    geometry::Point2 point;
  } left, right;
  const geometry::Point2 a{from.x + max * u.x - w * v.x, from.y + max * u.y - w * v.y};
  const geometry::Point2 b{from.x + w * v.x, from.y + w * v.y};
  map.forPointsNear({std::min(a.x, b.x), std::min(a.y, b.y)},
                    {std::max(a.x, b.x), std::max(a.y, b.y)}, [&](const geometry::Point2& q) {
                      const double along = (q.x - from.x) * u.x + (q.y - from.y) * u.y;
                      const double across = (q.x - from.x) * v.x + (q.y - from.y) * v.y;
                      if (along <= 0 || along > max || std::abs(across) > w) return;
                      Nearest& side = across >= 0 ? left : right;
                      if (std::abs(across) < side.across) side = {std::abs(across), along, q};
                    });
  if (std::isinf(left.across) || std::isinf(right.across) ||
      std::abs(left.along - right.along) > kInLine) {
    return kNone;
  }
  // No wall where the robot has been: the line between them crosses no swept floor.
  const double h = map.resolution();
  const int n = static_cast<int>(std::ceil(geometry::distance(left.point, right.point) / (h / 2)));
  for (int k = 1; k < n; ++k) {
    const double t = static_cast<double>(k) / n;
    const geometry::Point2 p{left.point.x + t * (right.point.x - left.point.x),
                             left.point.y + t * (right.point.y - left.point.y)};
    if (map.swept(map.cellOf(p))) return kNone;
  }
  return std::min(left.along, right.along);
}

std::optional<OnlineBoustrophedon::Candidate> OnlineBoustrophedon::candidate(
    const SweptMap& map, const geometry::Point2& from, Heading heading) const {
  if (triedOut(map, from, heading)) return std::nullopt;
  const geometry::Point2 u = unit(heading);
  Candidate c;
  c.move.start = from;
  c.move.heading = heading;
  if (alongRows(heading)) {
    c.move.kind = Move::Kind::kRow;
    c.unguessed = c.guessed = newFloor(map, from, heading, options_.lookahead);
    if (c.unguessed < options_.min_gain) return c;  // worth nothing, guess or not
    const double wall =
        guessedWall(map, from, heading, options_.lookahead + map.reach() + kInLine) - map.reach();
    if (wall < options_.lookahead) c.guessed = newFloor(map, from, heading, wall);
    return c;
  }
  c.move.kind = Move::Kind::kShift;
  const double wanted = std::abs(nextRowLine(from.y, heading) - from.y);
  c.move.length = wanted;  // the robot goes as far as it can: what it finds on the way may stop it
  // To the line, or on to what it found just beyond it (kSnapToWall); the row after it counts.
  auto promised = [&](double limit) {
    double length = std::min(map.freeLength(from, u, wanted + kSnapToWall), limit);
    // Stopped short of what it found, as the robot stops (a row along it is then not blocked
    // by it, a hair nearer than reach).
    length = length >= wanted + kSnapToWall ? wanted : length - kStopShort;
    if (length < kLeastShift) return 0.0;
    const geometry::Point2 end{from.x + length * u.x, from.y + length * u.y};
    return newFloor(map, from, heading, length) +
           std::max(newFloor(map, end, Heading::kEast, options_.lookahead),
                    newFloor(map, end, Heading::kWest, options_.lookahead));
  };
  c.unguessed = c.guessed = promised(std::numeric_limits<double>::infinity());
  if (c.unguessed < options_.min_gain) return c;  // worth nothing, guess or not
  const double wall = guessedWall(map, from, heading, wanted + map.reach() + kInLine) - map.reach();
  if (wall < wanted + kSnapToWall) c.guessed = promised(wall);
  return c;
}

int OnlineBoustrophedon::tier(const Candidate& c) const {
  if (c.guessed >= options_.first_gain) return 0;
  if (c.guessed >= options_.min_gain) return 1;
  if (c.unguessed >= options_.min_gain) return 2;
  return kTiers;
}

std::optional<Move> OnlineBoustrophedon::next(const SweptMap& map, const geometry::Point2& at) {
  // The boustrophedon from where the robot stands. After a shift (or at the start) the row back
  // the way the last one came, or the other way: the shift was chosen for it, so it need only
  // promise half as much.
  if (!last_ || *last_ == Move::Kind::kShift) {
    const double least = last_ ? options_.min_gain / 2 : options_.min_gain;
    for (const Heading h : {opposite(row_heading_), row_heading_}) {
      std::optional<Candidate> c = candidate(map, at, h);
      if (c && c->guessed >= least) return chosen(map, std::move(c->move), c->guessed);
    }
  }
  // After a row, the shift towards the side the rows go (or the other), and else backtracking,
  // tier by tier: the moves that promise most first (walls guessed straight), then the rest, then
  // (nothing left but the gaps between points found) without guessing.
  std::optional<Candidate> shifts[2];
  if (last_ && *last_ == Move::Kind::kRow) {
    shifts[0] = candidate(map, at, side_);
    shifts[1] = candidate(map, at, opposite(side_));
  }
  std::optional<Candidate> found[kTiers];
  bool searched = false;
  for (int t = 0; t < kTiers; ++t) {
    for (std::optional<Candidate>& c : shifts) {
      if (c && tier(*c) <= t) return chosen(map, std::move(c->move), gainOf(*c, t));
    }
    if (!searched) {
      backtrack(map, at, found);
      searched = true;
    }
    if (found[t]) {
      ++backtracks_;
      return chosen(map, std::move(found[t]->move), gainOf(*found[t], t));
    }
  }
  return std::nullopt;
}

void OnlineBoustrophedon::backtrack(const SweptMap& map, const geometry::Point2& at,
                                    std::optional<Candidate> (&found)[kTiers]) const {
  const int width = map.columns(), height = map.rows();
  const int i0 = map.minColumn(), j0 = map.minRow();
  const double h = map.resolution();
  auto index = [&](const Cell& c) { return (c.j - j0) * width + (c.i - i0); };
  auto cellAt = [&](int k) { return Cell{i0 + k % width, j0 + k / width}; };
  auto held = [&](const Cell& c) {
    return c.i >= i0 && c.j >= j0 && c.i < i0 + width && c.j < j0 + height;
  };
  const Cell source_cell = map.cellOf(at);
  if (!held(source_cell)) return;
  const int source = index(source_cell);

  // Safe centres: swept, not blocked, and no centre that is not swept within radius − rim; and
  // (kBeen) every centre the robot has been on.
  geometry::OccupancyGrid unswept;
  unswept.width = width;
  unswept.height = height;
  unswept.resolution = h;
  unswept.cells.resize(static_cast<std::size_t>(width) * height);
  for (int k = 0; k < width * height; ++k) {
    unswept.cells[k] =
        map.swept(cellAt(k)) ? geometry::OccupancyGrid::kFree : geometry::OccupancyGrid::kOccupied;
  }
  const std::vector<std::int32_t> distance = geometry::squaredDistanceTransform(unswept);
  const double inner = std::max(0.0, map.radius() - options_.safe_rim) / h;
  std::vector<char> safe(static_cast<std::size_t>(width) * height, 0);
  for (int k = 0; k < width * height; ++k) {
    safe[k] = distance[k] > inner * inner && !map.blocked(cellAt(k)) ? kSafe
              : map.visited(cellAt(k))                               ? kBeen
                                                                     : 0;
  }

  // Five points just beyond the disc's leading edge in each heading, ±60° round it.
  geometry::Point2 edge[4][5];
  for (int e = 0; e < 4; ++e) {
    const geometry::Point2 u = unit(kHeadings[e]);
    const double angles[] = {0.0, kPi / 6, -kPi / 6, kPi / 3, -kPi / 3};
    for (int a = 0; a < 5; ++a) {
      const double reach = map.radius() + h, c = std::cos(angles[a]), s = std::sin(angles[a]);
      edge[e][a] = {reach * (u.x * c - u.y * s), reach * (u.x * s + u.y * c)};
    }
  }
  // The moves from centre `from` worth starting, each kept in its tier when none nearer is.
  auto consider = [&](const geometry::Point2& from, int k) {
    for (int e = 0; e < 4; ++e) {
      const Heading heading = kHeadings[e];
      // Only where the disc's leading edge touches floor it has not swept.
      bool unswept_ahead = false;
      for (const geometry::Point2& d : edge[e]) {
        unswept_ahead = unswept_ahead || map.unknown(map.cellOf({from.x + d.x, from.y + d.y}));
      }
      if (!unswept_ahead) continue;
      std::optional<Candidate> c = candidate(map, from, heading);
      if (!c) continue;
      const int t = tier(*c);
      if (t == kTiers) continue;
      // Nearer wins; at one centre, the one that promises most.
      if (!found[t] || (found[t]->cell == k && gainOf(*c, t) > gainOf(*found[t], t))) {
        c->cell = k;
        found[t] = std::move(c);
      }
    }
  };

  std::vector<double> cost(static_cast<std::size_t>(width) * height,
                           std::numeric_limits<double>::infinity());
  std::vector<int> parent(static_cast<std::size_t>(width) * height, -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  cost[source] = 0;
  open.push({0, source});
  // The robot may stand where no centre is safe (pressed against what it bumped into, or nearer
  // a wall than reach where it had found no point): the safe centres under its disc's middle are
  // where its paths begin, straight from where it stands.
  const int near = static_cast<int>(std::ceil(kLeaveRadius / h));
  for (int dj = -near; dj <= near; ++dj) {
    for (int di = -near; di <= near; ++di) {
      const Cell c{source_cell.i + di, source_cell.j + dj};
      if (!held(c) || safe[index(c)] != kSafe) continue;
      const double d = geometry::distance(at, map.centre(c));
      if (d > kLeaveRadius || d >= cost[index(c)]) continue;
      cost[index(c)] = d;
      parent[index(c)] = source;
      open.push({d, index(c)});
    }
  }
  while (!open.empty() && !found[0]) {
    const auto [d, k] = open.top();
    open.pop();
    if (d > cost[k]) continue;
    const Cell c = cellAt(k);
    // A move starts on a safe centre, or where the robot stands.
    if (k == source) {
      consider(at, k);
    } else if (safe[k] == kSafe) {
      consider(map.centre(c), k);
    }
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if (di == 0 && dj == 0) continue;
        const Cell n{c.i + di, c.j + dj};
        if (!held(n)) continue;
        const int nk = index(n);
        if (!safe[nk]) continue;
        // No corner cut past a centre that is not safe.
        if (di != 0 && dj != 0 && (!safe[index({c.i + di, c.j})] || !safe[index({c.i, c.j + dj})]))
          continue;
        const double nd = d + h * (di != 0 && dj != 0 ? std::sqrt(2.0) : 1.0) *
                                  (safe[nk] == kBeen ? kBeenCost : 1.0);
        if (nd < cost[nk]) {
          cost[nk] = nd;
          parent[nk] = k;
          open.push({nd, nk});
        }
      }
    }
  }

  // The transit to each: the cells' centres back to the robot, shortcut where a straight line
  // crosses safe centres only.
  auto visible = [&](const geometry::Point2& a, const geometry::Point2& b) {
    const int n = static_cast<int>(std::ceil(geometry::distance(a, b) / (h / 2)));
    for (int s = 1; s < n; ++s) {
      const double t = static_cast<double>(s) / n;
      const int x = index(map.cellOf({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}));
      if (x != source && safe[x] != kSafe) return false;
    }
    return true;
  };
  for (std::optional<Candidate>& c : found) {
    if (!c || c->cell == source) continue;
    std::vector<geometry::Point2> cells;
    for (int p = c->cell; p != source; p = parent[p]) cells.push_back(map.centre(cellAt(p)));
    cells.push_back(at);
    std::reverse(cells.begin(), cells.end());
    std::vector<geometry::Point2>& transit = c->move.transit;
    transit.push_back(cells.front());
    for (std::size_t p = 2; p < cells.size(); ++p) {
      if (!visible(transit.back(), cells[p])) transit.push_back(cells[p - 1]);
    }
    transit.push_back(cells.back());
  }
}

}  // namespace roomba_rrt::exploration
