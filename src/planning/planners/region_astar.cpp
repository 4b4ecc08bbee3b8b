#include "roomba_rrt/planning/planners/region_astar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "roomba_rrt/planning/path_smoothing.h"

namespace roomba_rrt::planning {
namespace {

constexpr double kDiagonal = 1.4142135623730951;
constexpr double kInf = std::numeric_limits<double>::infinity();
/// How far (in cells, Chebyshev) from the start or goal a free centre is looked for when the
/// point's own cell centre is blocked or not reachable in a straight line.
constexpr int kEndpointReach = 2;
/// How many blocks around each region of the way the cells are searched when the regions'
/// points do not see each other.
constexpr int kCorridorBlocks = 1;
/// The longest straight line (in blocks) the search of the regions looks along.
constexpr int kMaxLineBlocks = 8;
/// How far from each corner (cells) the final pass cuts it, and the spacing (cells) of the
/// points it may turn at there.
constexpr double kCornerReach = 8;
constexpr double kCornerSpacing = 2;

/// A queue entry: the smallest f first, and of equal f the largest g (the deeper node).
struct Entry {
  double f;
  float g;
  int node;
};
struct Later {
  bool operator()(const Entry& a, const Entry& b) const {
    return a.f > b.f || (a.f == b.f && a.g < b.g);
  }
};
using Queue = std::priority_queue<Entry, std::vector<Entry>, Later>;

/// The free cell centre nearest `p` (its own cell's first) within kEndpointReach cells that the
/// disc reaches from p in a straight line and that has an edge; −1 if none.
int endpointCell(const GridRegions& r, const Point2& p) {
  const int cell = r.cellOf(p);
  if (cell < 0) return -1;
  if (r.edges(cell) != 0 && r.map().sweepFree(p, r.centre(cell), r.disc())) return cell;
  const int ci = cell % r.width(), cj = cell / r.width();
  int best = -1;
  double best_d = kInf;
  for (int j = std::max(cj - kEndpointReach, 0); j <= std::min(cj + kEndpointReach, r.height() - 1);
       ++j) {
    for (int i = std::max(ci - kEndpointReach, 0);
         i <= std::min(ci + kEndpointReach, r.width() - 1); ++i) {
      const int c = j * r.width() + i;
      if (c == cell || r.edges(c) == 0) continue;
      const double d = distance(p, r.centre(c));
      if (d < best_d && r.map().sweepFree(p, r.centre(c), r.disc())) best = c, best_d = d;
    }
  }
  return best;
}

/// Whether region `a`'s point sees region `b`'s across clear blocks, looked at only when they
/// are at most `max_line` apart (so that each look costs at most kMaxLineBlocks look-ups).
bool seesInLine(const GridRegions& r, int a, int b, double max_line) {
  if (!r.blockClear(r.blockOfRegion(a)) || !r.blockClear(r.blockOfRegion(b))) return false;
  const Point2 &p = r.regionPoint(a), &q = r.regionPoint(b);
  return squaredDistance(p, q) <= max_line * max_line && r.clearBetween(p, q);
}

/// Lazy Theta* (Nash, Koenig and Tovey 2010) over the regions from `from` to `to`: as A* over
/// them, but a region reached from another may take that one's parent as its own when the
/// straight segment between their points crosses clear blocks only (GridRegions::clearBetween(),
/// a look-up per block; checked lazily, when the region is taken from the queue), so that across
/// open floor the costs are straight-line distances rather than sums of steps between
/// neighbouring blocks (up to 8 % longer, by direction): which way round is chosen by lengths
/// close to the final path's. Returns the regions whose points the path turns at (the first
/// and last included), or empty if none (or stopped).
std::vector<int> regionPath(const GridRegions& r, int from, int to, StopCondition* stop,
                            int& taken) {
  struct State {
    double g = kInf;
    int parent = -1;
    bool closed = false;
  };
  std::vector<State> at(r.regionCount());
  const Point2 goal = r.regionPoint(to);
  const std::vector<int>& next = r.adjacency();
  const double max_line = kMaxLineBlocks * r.block() * r.map().grid().resolution;
  Queue open;
  at[from].g = 0;
  at[from].parent = from;
  open.push({distance(r.regionPoint(from), goal), 0, from});
  while (!open.empty()) {
    const int s = open.top().node;
    open.pop();
    State& here = at[s];
    if (here.closed) continue;  // reached shorter since: a stale entry
    here.closed = true;
    ++taken;
    if (stop && (*stop)()) return {};
    // The parent was assumed to see s: if it does not, the best closed neighbour instead.
    if (here.parent != s && !seesInLine(r, here.parent, s, max_line)) {
      const Point2& p = r.regionPoint(s);
      here.g = kInf;
      for (int k = r.adjacencyBegin(s); k < r.adjacencyBegin(s + 1); ++k) {
        const State& n = at[next[k]];
        if (!n.closed) continue;
        const double through = n.g + static_cast<float>(distance(r.regionPoint(next[k]), p));
        if (through < here.g) here.g = through, here.parent = next[k];
      }
    }
    if (s == to) break;
    const int via = here.parent;
    const double via_g = at[via].g;
    const Point2& from_point = r.regionPoint(via);
    for (int k = r.adjacencyBegin(s); k < r.adjacencyBegin(s + 1); ++k) {
      const int t = next[k];
      State& there = at[t];
      if (there.closed) continue;
      // Through s's parent in a straight line (checked when t is taken).
      const Point2& p = r.regionPoint(t);
      const double straight = via_g + distance(from_point, p);
      if (straight < there.g) {
        there.g = straight;
        there.parent = via;
        open.push({straight + distance(p, goal), static_cast<float>(straight), t});
      }
    }
  }
  if (!at[to].closed) return {};
  std::vector<int> path;
  for (int region = to;; region = at[region].parent) {
    path.push_back(region);
    if (region == from) break;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

/// The blocks of a corridor, each with a slot 0, 1, ...: open addressing over a power-of-two
/// table, so a query costs the corridor's size, not the map's.
class BlockSlots {
 public:
  BlockSlots(const GridRegions& regions, std::size_t expected) : regions_(regions) {
    std::size_t capacity = 16;
    hash_shift_ = 60;
    while (capacity < 2 * expected) capacity *= 2, --hash_shift_;
    keys_.assign(capacity, -1);
    slots_.assign(capacity, -1);
    mask_ = capacity - 1;
  }
  /// Adds `block` if new.
  void insert(int block) {
    std::size_t at = hash(block);
    while (keys_[at] >= 0) {
      if (keys_[at] == block) return;
      at = (at + 1) & mask_;
    }
    keys_[at] = block;
    slots_[at] = static_cast<int>(origin_i_.size());
    origin_i_.push_back((block % regions_.blocksX()) << regions_.blockShift());
    origin_j_.push_back((block / regions_.blocksX()) << regions_.blockShift());
  }
  /// The slot of `block`, −1 if it is not in the corridor.
  int find(int block) const {
    for (std::size_t at = hash(block);; at = (at + 1) & mask_) {
      if (keys_[at] == block) return slots_[at];
      if (keys_[at] < 0) return -1;
    }
  }
  /// The column and row of the first cell of the block in `slot`.
  int originI(int slot) const { return origin_i_[slot]; }
  int originJ(int slot) const { return origin_j_[slot]; }
  int size() const { return static_cast<int>(origin_i_.size()); }

 private:
  std::size_t hash(int block) const {
    return static_cast<std::size_t>(block) * 0x9E3779B97F4A7C15ull >> hash_shift_;  // Fibonacci
  }
  const GridRegions& regions_;
  std::vector<int> keys_, slots_, origin_i_, origin_j_;
  std::size_t mask_ = 0;
  int hash_shift_ = 60;
};

/// The octile distance in cells: the 8-connected path length on an empty grid.
double octile(int di, int dj) {
  const int a = std::abs(di), b = std::abs(dj);
  return std::max(a, b) + (kDiagonal - 1) * std::min(a, b);
}

/// A* over the fine graph's cells in the corridor's blocks, from cell `from` to cell `to`: the
/// cells of the shortest 8-connected path inside it, or empty if none (or stopped). A cell of
/// the corridor is its block's slot × block² + its place in the block.
std::vector<int> cellPath(const GridRegions& r, const BlockSlots& corridor, int from, int to,
                          StopCondition* stop, int& taken) {
  const int w = r.width(), shift = r.blockShift(), mask = r.block() - 1;
  const int shift2 = 2 * shift;
  const auto local = [&](int i, int j) {
    const int slot = corridor.find(r.blockAt(i, j));
    return slot < 0 ? -1 : (slot << shift2) | ((j & mask) << shift) | (i & mask);
  };
  const std::size_t size = static_cast<std::size_t>(corridor.size()) << shift2;
  std::vector<double> g(size, kInf);
  std::vector<int> parent(size, -1);
  std::vector<char> closed(size, 0);
  const int gi = to % w, gj = to / w;
  const int from_local = local(from % w, from / w), to_local = local(gi, gj);
  if (from_local < 0 || to_local < 0) return {};
  const auto cellOfLocal = [&](int l) {
    const int slot = l >> shift2;
    return (corridor.originJ(slot) + ((l >> shift) & mask)) * w + corridor.originI(slot) +
           (l & mask);
  };
  Queue open;
  g[from_local] = 0;
  open.push({octile(from % w - gi, from / w - gj), 0, from_local});
  while (!open.empty()) {
    const int node = open.top().node;
    open.pop();
    if (closed[node]) continue;
    closed[node] = 1;
    ++taken;
    if (node == to_local) break;
    if (stop && (*stop)()) return {};
    const int slot = node >> shift2;
    const int li = node & mask, lj = (node >> shift) & mask;
    const int i = corridor.originI(slot) + li, j = corridor.originJ(slot) + lj;
    const std::uint8_t e = r.edges(j * w + i);
    const double at = g[node];
    for (int k = 0; k < 8; ++k) {
      if (!(e & (1u << k))) continue;
      const int ni = li + GridRegions::kMoves[k][0], nj = lj + GridRegions::kMoves[k][1];
      // In the same block: the same slot; otherwise the neighbour block's, if in the corridor.
      const int next = (ni & ~mask) == 0 && (nj & ~mask) == 0
                           ? (slot << shift2) | (nj << shift) | ni
                           : local(i + GridRegions::kMoves[k][0], j + GridRegions::kMoves[k][1]);
      if (next < 0 || closed[next]) continue;
      const double through = at + (k < 4 ? 1.0 : kDiagonal);
      if (through < g[next]) {
        g[next] = through;
        parent[next] = node;
        open.push({through + octile(i + GridRegions::kMoves[k][0] - gi,
                                    j + GridRegions::kMoves[k][1] - gj),
                   static_cast<float>(through), next});
      }
    }
  }
  if (!closed[to_local]) return {};
  std::vector<int> path;
  for (int l = to_local; l >= 0; l = parent[l]) path.push_back(cellOfLocal(l));
  std::reverse(path.begin(), path.end());
  return path;
}

/// The corridor of a region path (the regions it turns at): the blocks of those regions and of
/// the segments between their points, each with its neighbours within kCorridorBlocks blocks.
BlockSlots corridorOf(const GridRegions& r, const std::vector<int>& coarse) {
  std::vector<int> blocks;
  for (std::size_t k = 0; k < coarse.size(); ++k) {
    blocks.push_back(r.blockOfRegion(coarse[k]));
    if (k + 1 < coarse.size()) {
      r.forEachBlockAlong(r.regionPoint(coarse[k]), r.regionPoint(coarse[k + 1]), [&](int block) {
        blocks.push_back(block);
        return true;
      });
    }
  }
  const int reach = kCorridorBlocks;
  BlockSlots corridor(r,
                      static_cast<std::size_t>((2 * reach + 1) * (2 * reach + 1)) * blocks.size());
  for (int blk : blocks) {
    const int bi = blk % r.blocksX(), bj = blk / r.blocksX();
    for (int j = std::max(bj - reach, 0); j <= std::min(bj + reach, r.blocksY() - 1); ++j) {
      for (int i = std::max(bi - reach, 0); i <= std::min(bi + reach, r.blocksX() - 1); ++i) {
        corridor.insert(j * r.blocksX() + i);
      }
    }
  }
  return corridor;
}

/// start, the centres of the cells where the path of `cells` turns, goal (the cells between two
/// turns lie on the fine edges joining them).
std::vector<Point2> turningPoints(const GridRegions& r, const std::vector<int>& cells,
                                  const Point2& start, const Point2& goal) {
  std::vector<Point2> path{start};
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (k > 0 && k + 1 < cells.size() && cells[k] - cells[k - 1] == cells[k + 1] - cells[k]) {
      continue;
    }
    const Point2 c = r.centre(cells[k]);
    if (c.x != path.back().x || c.y != path.back().y) path.push_back(c);
  }
  if (goal.x != path.back().x || goal.y != path.back().y) path.push_back(goal);
  return path;
}

}  // namespace

PlanResult solveRegionAStar(const GridRegions& regions, const Point2& start, const Point2& goal,
                            StopCondition* stop) {
  PlanResult result;
  const geometry::ClearanceMap& map = regions.map();
  const geometry::ClearanceMap::Disc& disc = regions.disc();
  for (const auto& [field, p] : {std::pair<const char*, Point2>{"start", start}, {"goal", goal}}) {
    if (!map.discFree(p, disc)) {
      setNoPath(result, std::string(field) + ": the disc is not free there");
      return result;
    }
  }
  const auto sweep = [&](const Point2& a, const Point2& b) { return map.sweepFree(a, b, disc); };
  if (sweep(start, goal)) {
    setPathFound(result, {start, goal}, "in a straight line");
    return result;
  }
  const int from = endpointCell(regions, start), to = endpointCell(regions, goal);
  if (from < 0 || to < 0) {
    setNoPath(result, std::string(from < 0 ? "start" : "goal") + ": no free cell centre within " +
                          std::to_string(kEndpointReach) +
                          " cells that the disc reaches in a straight line");
    return result;
  }
  const std::vector<int> coarse =
      regionPath(regions, regions.regionOf(from), regions.regionOf(to), stop, result.iterations);
  if (coarse.empty()) {
    setNoPath(result, stop && !stop->reason().empty()
                          ? stop->reason()
                          : "no path: the goal is not reachable from the start");
    return result;
  }
  // The regions' points, from the start's cell centre to the goal's, pulled taut.
  std::vector<Point2> through{start, regions.centre(from)};
  for (std::size_t k = 1; k + 1 < coarse.size(); ++k)
    through.push_back(regions.regionPoint(coarse[k]));
  through.push_back(regions.centre(to));
  through.push_back(goal);
  std::vector<Point2> path = pullPolyline(through, sweep);
  if (path.empty()) {
    // Some region's point does not see the next one: the cells along the way instead.
    const std::vector<int> cells =
        cellPath(regions, corridorOf(regions, coarse), from, to, stop, result.iterations);
    if (cells.empty()) {
      setNoPath(result,
                stop && !stop->reason().empty() ? stop->reason() : "no path inside the corridor");
      return result;
    }
    path = pullStringFar(turningPoints(regions, cells, start, goal), sweep);
  }
  const double cell = map.grid().resolution;
  path = pullStringFar(cutCorners(path, sweep, kCornerReach * cell, kCornerSpacing * cell), sweep);
  setPathFound(result, std::move(path));
  return result;
}

}  // namespace roomba_rrt::planning
