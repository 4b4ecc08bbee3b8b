#include "roomba_rrt/coverage/cell_order.h"

#include <limits>
#include <optional>

namespace roomba_rrt::coverage {

Sweep sweepRows(const std::vector<Row>& rows, Way way) {
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

std::vector<CellVisit> orderCells(const Sweeps& sweeps, const Point2& start) {
  auto entry = [&](const CellVisit& v) { return sweeps[v.cell][v.way].front().first; };
  auto exit = [&](const CellVisit& v) { return sweeps[v.cell][v.way].back().second; };
  std::vector<CellVisit> order;
  std::vector<bool> done(sweeps.size(), false);
  Point2 at = start;
  for (;;) {
    std::optional<CellVisit> best;
    double best_distance = 0;
    for (std::size_t c = 0; c < sweeps.size(); ++c) {
      if (done[c] || sweeps[c][0].empty()) continue;
      for (std::size_t way = 0; way < std::size(kWays); ++way) {
        const double d = geometry::distance(at, entry({c, way}));
        if (!best || d < best_distance) best = CellVisit{c, way}, best_distance = d;
      }
    }
    if (!best) break;
    done[best->cell] = true;
    order.push_back(*best);
    at = exit(*best);
  }

  // The straight jump into `v` as the k-th visit of `o` (from the start when k = 0).
  auto jump = [&](const std::vector<CellVisit>& o, std::size_t k, const CellVisit& v) {
    return geometry::distance(k == 0 ? start : exit(o[k - 1]), entry(v));
  };
  for (int round = 0; round < kMaxOrderRounds; ++round) {
    bool improved = false;
    for (std::size_t i = 0; i < order.size(); ++i) {
      const CellVisit moved = order[i];
      std::vector<CellVisit> rest = order;
      rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(i));
      // What taking it out saves, and what putting it back elsewhere costs.
      double saved = jump(order, i, moved);
      if (i + 1 < order.size()) saved += jump(order, i + 1, order[i + 1]) - jump(rest, i, rest[i]);
      for (std::size_t k = 0; k <= rest.size() && !improved; ++k) {
        for (std::size_t way = 0; way < std::size(kWays); ++way) {
          const CellVisit v{moved.cell, way};
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

}  // namespace roomba_rrt::coverage
