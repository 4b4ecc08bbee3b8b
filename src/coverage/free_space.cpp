#include "roomba_rrt/coverage/free_space.h"

#include "roomba_rrt/geometry/occupancy_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace roomba_rrt::coverage {
namespace {

/// The radius of the "disc" whose penetration means a point is inside a wall or obstacle (not
/// floor): small enough to be a point, large enough to stay above world::kPenetrationTolerance.
constexpr double kPointRadius = 1e-6;

/// How far connect() looks for a lattice point to drive to (m): a robot backed off after a bump,
/// or within the clearance of furniture, is at most a few centimetres from the kFree lattice.
constexpr double kConnectReach = 0.25;

/// Added to the lattice slack δ (m), far above world::kPenetrationTolerance and the rounding of
/// coordinates, so that the slack's bound holds with strict inequalities.
constexpr double kSlackTolerance = 1e-7;

/// A*'s bookkeeping, kept between searches (one per thread): a lattice point's cost and parent
/// count only when its stamp is the present search's. So a search costs what it visits, not the
/// lattice's size: on willow_full (5 M points) clearing fresh arrays for each transit made
/// planning the whole floor take 47 s. The price: 16 bytes per lattice point of the largest
/// lattice searched, kept for the thread's life (84 MB for all of willow_full).
class SearchRecords {
 public:
  /// Starts a search over a lattice of `size` points: every point unreached.
  void begin(int size) {
    if (records_.size() != static_cast<std::size_t>(size)) {
      records_.assign(static_cast<std::size_t>(size), Record{});
      search_ = 0;
    }
    if (++search_ == 0) {  // the stamps wrapped round: forget them all
      for (Record& record : records_) record.stamp = 0;
      search_ = 1;
    }
  }
  double cost(int k) const {
    const Record& record = records_[static_cast<std::size_t>(k)];
    return record.stamp == search_ ? record.cost : std::numeric_limits<double>::infinity();
  }
  int parent(int k) const {
    const Record& record = records_[static_cast<std::size_t>(k)];
    return record.stamp == search_ ? record.parent : -1;
  }
  void reach(int k, double cost, int parent) {
    records_[static_cast<std::size_t>(k)] = Record{cost, parent, search_};
  }

 private:
  struct Record {
    double cost = 0;
    int parent = -1;
    std::uint32_t stamp = 0;  ///< the search that wrote it; 0: none
  };
  std::vector<Record> records_;
  std::uint32_t search_ = 0;
};

}  // namespace

FreeSpace::FreeSpace(const world::World& world, double clearance, double resolution)
    : world_(world),
      robot_radius_(world.robot().radius),
      radius_(world.robot().radius + clearance),
      h_(resolution),
      origin_(world.room.origin) {
  width_ = std::max(1, static_cast<int>(std::ceil(world.room.width / h_ - 1e-9)));
  height_ = std::max(1, static_cast<int>(std::ceil(world.room.height / h_ - 1e-9)));
  const double half_diagonal_sq = h_ * h_ / 2;
  const double slack = half_diagonal_sq / radius_ + kSlackTolerance;  // δ (see the header)
  classes_.assign(size(), kBlocked);
  floor_.assign(size(), 0);
  for (int k = 0; k < size(); ++k) {
    const Point2 p = point(k);
    if (!world::penetrates(world_, radius_ + slack, p.x, p.y)) {
      classes_[k] = kFree;
    } else if (!world::penetrates(world_, robot_radius_, p.x, p.y)) {
      classes_[k] = kTight;
    }
    floor_[k] = classes_[k] != kBlocked || !world::penetrates(world_, kPointRadius, p.x, p.y);
  }
  // The pieces: the runs of kFree points along each lattice row, joined (union-find) to the
  // runs of the row below that touch them, diagonally included; each point then gets its run's
  // root's number. Runs, not points, keep this a few per cent of the sampling.
  struct Run {
    int row, first, last;  // lattice row and columns
    int parent;            // index of a run of the same piece; itself at the root
  };
  std::vector<Run> runs;
  auto root = [&](int r) {
    while (runs[r].parent != r) r = runs[r].parent = runs[runs[r].parent].parent;
    return r;
  };
  std::size_t below = 0, above = 0;  // the row below's runs: [below, above)
  for (int j = 0; j < height_; ++j) {
    const std::size_t here = runs.size();
    std::size_t q = below;  // the row below's first run that may touch the next run here
    for (int i = 0; i < width_; ++i) {
      if (classes_[index(i, j)] != kFree) continue;
      const int first = i;
      while (i + 1 < width_ && classes_[index(i + 1, j)] == kFree) ++i;
      const int r = static_cast<int>(runs.size());
      runs.push_back({j, first, i, r});
      while (q < above && runs[q].last < first - 1) ++q;
      for (std::size_t t = q; t < above && runs[t].first <= i + 1; ++t) {
        const int a = root(r), b = root(static_cast<int>(t));
        if (a != b) runs[std::max(a, b)].parent = std::min(a, b);
      }
    }
    below = here;
    above = runs.size();
  }
  pieces_.assign(size(), 0);
  for (int r = 0; r < static_cast<int>(runs.size()); ++r) {
    const auto piece = static_cast<std::uint32_t>(root(r)) + 1;
    std::fill(pieces_.begin() + index(runs[r].first, runs[r].row),
              pieces_.begin() + index(runs[r].last, runs[r].row) + 1, piece);
  }
}

bool FreeSpace::segmentFree(const Point2& a, const Point2& b, double radius) const {
  const double r = radius - world::kPenetrationTolerance;
  // The walls bound a convex box of centres: the segment is inside when both ends are.
  const double x0 = world_.room.origin.x, y0 = world_.room.origin.y;
  for (const Point2& p : {a, b}) {
    if (p.x < x0 + r || p.y < y0 + r || p.x > x0 + world_.room.width - r ||
        p.y > y0 + world_.room.height - r) {
      return false;
    }
  }
  const geometry::Segment s{a, b};
  for (const world::Circle& c : world_.room.circles) {
    if (geometry::segmentMeets(s, c, r)) return false;
  }
  for (const world::Rectangle& box : world_.room.rectangles) {
    if (geometry::segmentMeets(s, box, r)) return false;
  }
  return !(world_.room.map && geometry::segmentMeetsBlocked(*world_.room.map, s, r));
}

std::optional<int> FreeSpace::connect(const Point2& p, Class least) const {
  const int ci = static_cast<int>(std::floor((p.x - origin_.x) / h_));
  const int cj = static_cast<int>(std::floor((p.y - origin_.y) / h_));
  const int reach = static_cast<int>(std::ceil(kConnectReach / h_));
  std::vector<std::pair<double, int>> candidates;  // (squared distance, index): nearest first
  for (int j = cj - reach; j <= cj + reach; ++j) {
    for (int i = ci - reach; i <= ci + reach; ++i) {
      if (!inside(i, j) || at(index(i, j)) < least) continue;
      const double d = geometry::squaredDistance(p, point(i, j));
      if (d <= kConnectReach * kConnectReach) candidates.emplace_back(d, index(i, j));
    }
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& [d, k] : candidates) {
    if (segmentFree(p, point(k), robot_radius_)) return k;
  }
  return std::nullopt;
}

std::optional<Polyline> FreeSpace::shortestPath(int from, int to) const {
  if (at(from) != kFree || at(to) != kFree || pieces_[from] != pieces_[to]) return std::nullopt;
  const double diagonal = h_ * std::sqrt(2.0);
  const int ti = column(to), tj = row(to);
  auto heuristic = [&](int k) {  // octile distance: exact on an empty 8-connected lattice
    const int di = std::abs(column(k) - ti), dj = std::abs(row(k) - tj);
    return h_ * std::max(di, dj) + (diagonal - h_) * std::min(di, dj);
  };
  thread_local SearchRecords records;
  records.begin(size());
  using Entry = std::pair<double, int>;  // (cost + heuristic, index): ties go to the lower index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  records.reach(from, 0, -1);
  open.emplace(heuristic(from), from);
  while (!open.empty()) {
    const auto [f, k] = open.top();
    open.pop();
    if (k == to) break;
    const double cost = records.cost(k);
    if (f > cost + heuristic(k)) continue;  // a stale entry: k was reached cheaper since
    const int i = column(k), j = row(k);
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        if ((di == 0 && dj == 0) || !inside(i + di, j + dj)) continue;
        const int n = index(i + di, j + dj);
        if (at(n) != kFree) continue;
        const double c = cost + (di != 0 && dj != 0 ? diagonal : h_);
        if (c < records.cost(n)) {
          records.reach(n, c, k);
          open.emplace(c + heuristic(n), n);
        }
      }
    }
  }
  if (from != to && records.parent(to) < 0) return std::nullopt;
  Polyline path;
  for (int k = to; k != -1; k = records.parent(k)) path.push_back(point(k));
  std::reverse(path.begin(), path.end());
  return shortcut(path);
}

Polyline FreeSpace::shortcut(const Polyline& path) const {
  if (path.empty()) return path;
  Polyline out{path.front()};
  std::size_t anchor = 0;
  while (anchor + 1 < path.size()) {
    std::size_t next = anchor + 1;
    while (next + 1 < path.size() && segmentFree(path[anchor], path[next + 1])) ++next;
    out.push_back(path[next]);
    anchor = next;
  }
  return out;
}

Polyline FreeSpace::rounded(const Polyline& path, double radius,
                            std::vector<double>* passes) const {
  Polyline out;
  std::vector<double> passed;
  double length = 0;  // of `out`
  const auto append = [&](const Point2& p) {
    if (!out.empty()) {
      const double step = geometry::distance(out.back(), p);
      if (step == 0) return;
      length += step;
    }
    out.push_back(p);
  };
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (i == 0 || i + 1 == path.size()) {
      append(path[i]);
      passed.push_back(length);
      continue;
    }
    const Point2 &a = path[i - 1], &b = path[i], &c = path[i + 1];
    const double in_length = geometry::distance(a, b), out_length = geometry::distance(b, c);
    double turn = 0;
    Point2 u{0, 0}, w{0, 0};  // the directions in and out
    if (in_length > 0 && out_length > 0) {
      u = {(b.x - a.x) / in_length, (b.y - a.y) / in_length};
      w = {(c.x - b.x) / out_length, (c.y - b.y) / out_length};
      turn = std::atan2(u.x * w.y - u.y * w.x, u.x * w.x + u.y * w.y);  // left positive
    }
    std::vector<Point2> arc;
    if (std::fabs(turn) >= kMinRoundedTurn && radius > 0) {
      const double half = std::tan(std::fabs(turn) / 2);
      const double tangent = std::min({radius * half, in_length / 2, out_length / 2});
      const double r = tangent / half;
      const double side = turn > 0 ? 1.0 : -1.0;
      const Point2 from{b.x - tangent * u.x, b.y - tangent * u.y};
      const Point2 centre{from.x - side * r * u.y, from.y + side * r * u.x};
      const double start = std::atan2(from.y - centre.y, from.x - centre.x);
      // An even number of steps, so that the arc's middle is one of its points.
      const int steps =
          2 * std::max(1, static_cast<int>(std::ceil(std::fabs(turn) * r / (2 * kArcStep))));
      for (int k = 0; k <= steps; ++k) {
        const double angle = start + turn * k / steps;
        arc.push_back({centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)});
      }
      bool free = true;
      for (std::size_t k = 0; free && k + 1 < arc.size(); ++k) {
        free = segmentFree(arc[k], arc[k + 1]);
      }
      if (!free) arc.clear();
    }
    if (arc.empty()) {
      append(b);
      passed.push_back(length);
      continue;
    }
    for (std::size_t k = 0; k < arc.size(); ++k) {
      append(arc[k]);
      if (2 * k + 1 == arc.size()) passed.push_back(length);
    }
  }
  if (passes) *passes = std::move(passed);
  return out;
}

Mask flood(const FreeSpace& space, int seed, FreeSpace::Class least) {
  Mask region(space.size(), 0);
  forComponent(
      space, seed, [&](int n) { return space.at(n) >= least; }, region, [](int) {});
  return region;
}

double area(const FreeSpace& space, const Mask& mask) {
  return std::count(mask.begin(), mask.end(), 1) * space.resolution() * space.resolution();
}

}  // namespace roomba_rrt::coverage
