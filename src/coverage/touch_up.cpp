// The touch-up after the rows (touch_up.h): one member function per step of TouchUp::plan().
#include "roomba_rrt/coverage/touch_up.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

#include "roomba_rrt/coverage/tour.h"

namespace roomba_rrt::coverage {

CoveragePlan CoveragePlanner::touchUp(const std::vector<std::uint8_t>& swept, const Point2& at,
                                      double min_spot_area, bool edge_cleaning) const {
  return TouchUp(*this, swept, at, min_spot_area, edge_cleaning).plan();
}

TouchUp::TouchUp(const CoveragePlanner& planner, const std::vector<std::uint8_t>& swept,
                 const Point2& at, double min_spot_area, bool edge_cleaning)
    : planner_(planner),
      space_(planner.freeSpace()),
      options_(planner.options()),
      swept_(swept),
      at_(at),
      min_spot_area_(min_spot_area),
      edge_cleaning_(edge_cleaning) {}

CoveragePlan TouchUp::plan() {
  CoveragePlan plan;
  missedFloor(plan);
  // Where the robot can drive from here (with the clearance).
  const std::optional<int> seed = space_.connect(at_, FreeSpace::kFree);
  if (!seed) return plan;
  drivable_ = flood(space_, *seed, FreeSpace::kFree);
  unreached();
  sweepStrips(options_.clearance);
  // What no row at the clearance reaches (the floor within the clearance of a wall, which the
  // rows and stops never sweep): edge cleaning, rows along the wall at the edge clearance.
  if (edge_cleaning_ && options_.edge_clearance < options_.clearance) {
    sweepStrips(options_.edge_clearance);
  }
  standAtSpots();
  tour(plan);
  return plan;
}

void TouchUp::missedFloor(CoveragePlan& plan) {
  missed_ = planner_.reachableFloor(plan, at_);
  for (int k = 0; k < space_.size(); ++k) {
    missed_[k] = missed_[k] && !(k < static_cast<int>(swept_.size()) && swept_[k]);
  }
  // The spots: 8-connected pieces of missed floor. Those under min_spot_area are not worth going
  // back for (now).
  const double h = space_.resolution();
  Mask seen(space_.size(), 0);
  for (int k = 0; k < space_.size(); ++k) {
    if (!missed_[k] || seen[k]) continue;
    std::vector<int> spot;
    forComponent(
        space_, k, [&](int n) { return missed_[n] != 0; }, seen, [&](int n) { spot.push_back(n); });
    if (spot.size() * h * h < min_spot_area_) {
      for (int q : spot) missed_[q] = 0;
    }
  }
}

void TouchUp::unreached() {
  // What is missed along a wall or a piece of furniture, closer to it than any drivable lattice
  // point reaches (the floor U-turns' arcs leave between the rows' ends).
  const double r = space_.robotRadius();
  uncovered_.assign(space_.size(), 0);
  for (int k = 0; k < space_.size(); ++k) {
    if (!missed_[k]) continue;
    bool reached = false;
    const Point2 p = space_.point(k);
    forPointsNear(space_, p, p, r, [&](int c) { reached = reached || drivable_[c]; });
    uncovered_[k] = !reached;
  }
}

void TouchUp::sweepStrips(double clearance) {
  // In runs of a lattice column or row: a row along each run, as close as stays free
  // (stripRow()), when the disc reaches the run from there. It sweeps the missed floor beside
  // the run too.
  for (const bool vertical : {true, false}) {
    const int lines = vertical ? space_.width() : space_.height();
    const int length = vertical ? space_.height() : space_.width();
    for (int line = 0; line < lines; ++line) {
      std::vector<std::vector<int>> runs;  // runs of uncovered points, at most kStripGap apart
      int last = -kStripGap - 2;           // where the last uncovered point was along the line
      for (int along = 0; along < length; ++along) {
        const int q = vertical ? space_.index(line, along) : space_.index(along, line);
        if (!uncovered_[q]) continue;
        if (along - last > kStripGap + 1) {
          sweepStrip(runs, vertical, clearance);
          runs.clear();
        }
        if (runs.empty() || along - last > 1) runs.emplace_back();
        runs.back().push_back(q);
        last = along;
      }
      sweepStrip(runs, vertical, clearance);
    }
  }
}

void TouchUp::sweepStrip(const std::vector<std::vector<int>>& runs, bool vertical,
                         double clearance) {
  // Driving over a few swept centimetres costs less than a transit and two turns more.
  std::vector<int> merged;
  for (const auto& run : runs) merged.insert(merged.end(), run.begin(), run.end());
  if (stripVisit(merged, vertical, clearance)) return;
  for (const auto& run : runs) sweepRun(run, vertical, clearance);
}

void TouchUp::sweepRun(const std::vector<int>& points, bool vertical, double clearance) {
  if (stripVisit(points, vertical, clearance)) return;
  const auto middle = points.begin() + static_cast<std::ptrdiff_t>(points.size() / 2);
  sweepRun(std::vector<int>(points.begin(), middle), vertical, clearance);
  sweepRun(std::vector<int>(middle, points.end()), vertical, clearance);
}

bool TouchUp::stripVisit(const std::vector<int>& points, bool vertical, double clearance) {
  if (static_cast<int>(points.size()) <= kStripLength) return true;
  const std::optional<Polyline> row = stripRow(points, vertical, clearance);
  if (!row) return false;
  const double r = space_.robotRadius();
  for (std::size_t k = 0; k + 1 < row->size(); ++k) {
    forPointsNear(space_, (*row)[k], (*row)[k + 1], r,
                  [&](int c) { uncovered_[c] = missed_[c] = 0; });
  }
  visits_.push_back(Leg{Leg::Kind::kRow, *row, clearance < options_.clearance});
  return true;
}

void TouchUp::standAtSpots() {
  // From the first missed point left (row by row), the drivable lattice point within the
  // robot's radius of it whose disc covers most missed floor, a row of no length there: the
  // robot arrives and drives on to the next spot in any heading (a short row at each spot would
  // make it turn twice there). What it covers is no longer missed. A point no drivable lattice
  // point covers (a corner the clearance keeps the robot out of) is dropped.
  const double r = space_.robotRadius();
  for (int k = 0; k < space_.size(); ++k) {
    if (!missed_[k]) continue;
    std::optional<int> best;
    int best_count = 0;
    const Point2 p = space_.point(k);
    forPointsNear(space_, p, p, r, [&](int c) {
      if (!drivable_[c]) return;
      int count = 0;
      const Point2 centre = space_.point(c);
      forPointsNear(space_, centre, centre, r, [&](int q) { count += missed_[q]; });
      if (count > best_count) best = c, best_count = count;
    });
    if (!best) {
      missed_[k] = 0;
      continue;
    }
    const Point2 centre = space_.point(*best);
    forPointsNear(space_, centre, centre, r, [&](int q) { missed_[q] = 0; });
    visits_.push_back(Leg{Leg::Kind::kRow, {centre, centre}});
  }
}

void TouchUp::tour(CoveragePlan& plan) {
  // In the order of touchUpTour() (tour.h: nearest first, then 2-opt), each a transit and its
  // row.
  std::vector<Polyline> paths;
  paths.reserve(visits_.size());
  for (const Leg& visit : visits_) paths.push_back(visit.points);
  Point2 here = at_;
  for (const TourStop& stop : touchUpTour(paths, at_)) {
    Leg row = std::move(visits_[stop.visit]);
    if (stop.reversed) std::reverse(row.points.begin(), row.points.end());
    const std::optional<Polyline> path = planner_.transit(here, row.points.front());
    if (!path) continue;
    if (geometry::pathLength(*path) > kMinLegLength) {
      plan.legs.push_back(Leg{Leg::Kind::kTransit, *path});
    }
    here = row.points.back();
    plan.legs.push_back(std::move(row));
  }
}

std::optional<Polyline> TouchUp::stripRow(const std::vector<int>& points, bool vertical,
                                          double clearance) const {
  const double h = space_.resolution();
  const double r = space_.robotRadius();
  const double radius = r + clearance;
  // The row along the line, `offset` from it (across it), from its first point to its last.
  const Point2 low = space_.point(points.front()), high = space_.point(points.back());
  auto along = [&](double offset) {
    return vertical ? std::pair{Point2{low.x + offset, low.y}, Point2{low.x + offset, high.y}}
                    : std::pair{Point2{low.x, low.y + offset}, Point2{high.x, low.y + offset}};
  };
  auto free = [&](double offset) {
    const auto [a, b] = along(offset);
    return space_.segmentFree(a, b, radius);
  };
  // Out from the strip, on the side with room, to the first free row; then back towards it as
  // far as it stays free (exactly). Kept when the disc reaches the strip from there.
  const int most = static_cast<int>(std::ceil(radius / h)) + 3;
  for (const double side : {1.0, -1.0}) {
    for (int m = 1; m <= most; ++m) {
      if (!free(side * m * h)) continue;
      const double offset =
          side * (m * h - farthestFree(h, [&](double t) { return free(side * (m * h - t)); }));
      if (std::fabs(offset) >= r) break;
      const auto [a, b] = along(offset);
      if (clearance >= options_.clearance) return Polyline{a, b};
      // Closer than the clearance (edge cleaning): the robot can neither arrive nor stop there
      // with the clearance. It comes in from the clearance beside the row's start along a ramp of
      // a few degrees (kEdgeRamp long), drives along the wall and ramps out again before the end.
      const double length = geometry::distance(a, b);
      const double ramp = std::min(kEdgeRamp, length / 4);
      const Point2 in{a.x + (b.x - a.x) * ramp / length, a.y + (b.y - a.y) * ramp / length};
      const Point2 out{b.x + (a.x - b.x) * ramp / length, b.y + (a.y - b.y) * ramp / length};
      const double lift = side * (options_.clearance - clearance);  // away from the wall
      const Point2 up{vertical ? lift : 0, vertical ? 0 : lift};
      const Point2 from{a.x + up.x, a.y + up.y}, to{b.x + up.x, b.y + up.y};
      if (!space_.segmentFree(from, from) || !space_.segmentFree(to, to) ||
          !space_.segmentFree(from, in, radius) || !space_.segmentFree(out, to, radius)) {
        break;
      }
      return Polyline{from, in, out, to};
    }
  }
  return std::nullopt;
}

}  // namespace roomba_rrt::coverage
