#include "roomba_rrt/coverage/tour.h"

#include <algorithm>

namespace roomba_rrt::coverage {
namespace {

/// Where the robot enters and leaves `stop`.
Point2 entryOf(const std::vector<Polyline>& visits, const TourStop& stop) {
  return stop.reversed ? visits[stop.visit].back() : visits[stop.visit].front();
}
Point2 exitOf(const std::vector<Polyline>& visits, const TourStop& stop) {
  return stop.reversed ? visits[stop.visit].front() : visits[stop.visit].back();
}

}  // namespace

std::vector<TourStop> touchUpTour(const std::vector<Polyline>& visits, const Point2& start) {
  std::vector<TourStop> tour;
  std::vector<bool> visited(visits.size(), false);
  Point2 here = start;
  for (std::size_t n = 0; n < visits.size(); ++n) {
    std::size_t next = visits.size();
    double next_distance = 0;
    for (std::size_t v = 0; v < visits.size(); ++v) {
      if (visited[v]) continue;
      const double d = std::min(geometry::distance(here, visits[v].front()),
                                geometry::distance(here, visits[v].back()));
      if (next == visits.size() || d < next_distance) next = v, next_distance = d;
    }
    visited[next] = true;
    const bool reversed = geometry::distance(here, visits[next].back()) <
                          geometry::distance(here, visits[next].front());
    tour.push_back({next, reversed});
    here = exitOf(visits, tour.back());
  }

  // 2-opt: driving stops i..j in the opposite order, each the other way, changes only the jump
  // into i and the jump out of j (the jumps between them are the same, walked backwards).
  double checks = 0;
  for (bool improved = true; improved && checks < kMaxTourChecks;) {
    improved = false;
    for (std::size_t i = 0; i < tour.size() && checks < kMaxTourChecks; ++i) {
      checks += static_cast<double>(tour.size() - i - 1);
      const Point2 before = i == 0 ? start : exitOf(visits, tour[i - 1]);  // i..j move, not i − 1
      for (std::size_t j = i + 1; j < tour.size(); ++j) {
        double now = geometry::distance(before, entryOf(visits, tour[i]));
        double then = geometry::distance(before, exitOf(visits, tour[j]));
        if (j + 1 < tour.size()) {
          const Point2 after = entryOf(visits, tour[j + 1]);
          now += geometry::distance(exitOf(visits, tour[j]), after);
          then += geometry::distance(entryOf(visits, tour[i]), after);
        }
        if (then < now - kMinLegLength) {
          std::reverse(tour.begin() + static_cast<std::ptrdiff_t>(i),
                       tour.begin() + static_cast<std::ptrdiff_t>(j) + 1);
          for (std::size_t k = i; k <= j; ++k) tour[k].reversed = !tour[k].reversed;
          improved = true;
        }
      }
    }
  }
  return tour;
}

double tourJumps(const std::vector<Polyline>& visits, const std::vector<TourStop>& tour,
                 const Point2& start) {
  double total = 0;
  Point2 here = start;
  for (const TourStop& stop : tour) {
    total += geometry::distance(here, entryOf(visits, stop));
    here = exitOf(visits, stop);
  }
  return total;
}

}  // namespace roomba_rrt::coverage
