#include "roomba_rrt/exploration/swept_map.h"

#include <algorithm>
#include <cmath>

namespace roomba_rrt::exploration {
namespace {

/// Cells held beyond what is asked when the map grows (m): it grows a few times a run, not every
/// step.
constexpr double kGrowthMargin = 1.0;
/// A point this close to one already kept (m) adds nothing: a wall seen by many scans.
constexpr double kSamePoint = 0.005;

}  // namespace

SweptMap::SweptMap(const geometry::Point2& start, double radius, double clearance,
                   double resolution)
    : start_(start), radius_(radius), reach_(radius + clearance), resolution_(resolution) {
  const int n = static_cast<int>(std::ceil(2.0 / resolution_));
  hold(-n, -n, n, n);
}

Cell SweptMap::cellOf(const geometry::Point2& p) const {
  return {static_cast<int>(std::floor((p.x - start_.x) / resolution_ + 0.5)),
          static_cast<int>(std::floor((p.y - start_.y) / resolution_ + 0.5))};
}

void SweptMap::hold(int i_lo, int j_lo, int i_hi, int j_hi) {
  if (i_lo >= i0_ && j_lo >= j0_ && i_hi < i0_ + width_ && j_hi < j0_ + height_) return;
  const int margin = width_ == 0 ? 0 : static_cast<int>(std::ceil(kGrowthMargin / resolution_));
  const int ni0 = width_ == 0 ? i_lo : std::min(i0_, i_lo - margin);
  const int nj0 = height_ == 0 ? j_lo : std::min(j0_, j_lo - margin);
  const int ni1 = width_ == 0 ? i_hi : std::max(i0_ + width_ - 1, i_hi + margin);
  const int nj1 = height_ == 0 ? j_hi : std::max(j0_ + height_ - 1, j_hi + margin);
  const int nw = ni1 - ni0 + 1, nh = nj1 - nj0 + 1;
  std::vector<std::uint8_t> grown(static_cast<std::size_t>(nw) * nh, 0);
  for (int j = 0; j < height_; ++j) {
    std::copy_n(flags_.begin() + static_cast<std::size_t>(j) * width_, width_,
                grown.begin() + static_cast<std::size_t>(j + j0_ - nj0) * nw + (i0_ - ni0));
  }
  flags_.swap(grown);
  i0_ = ni0;
  j0_ = nj0;
  width_ = nw;
  height_ = nh;
}

void SweptMap::sweep(const geometry::Point2& c) {
  const double h = resolution_, r = radius_;
  const int i_lo = static_cast<int>(std::ceil((c.x - r - start_.x) / h));
  const int i_hi = static_cast<int>(std::floor((c.x + r - start_.x) / h));
  const int j_lo = static_cast<int>(std::ceil((c.y - r - start_.y) / h));
  const int j_hi = static_cast<int>(std::floor((c.y + r - start_.y) / h));
  hold(i_lo, j_lo, i_hi, j_hi);
  for (int i = i_lo; i <= i_hi; ++i) {
    const double dx = start_.x + i * h - c.x;
    const double dy = std::sqrt(std::max(0.0, r * r - dx * dx));
    const int lo = static_cast<int>(std::ceil((c.y - dy - start_.y) / h));
    const int hi = static_cast<int>(std::floor((c.y + dy - start_.y) / h));
    for (int j = lo; j <= hi; ++j) {
      std::uint8_t& f = at({i, j});
      if (!(f & kSwept)) {
        f |= kSwept;
        ++swept_count_;
      }
    }
  }
  at(cellOf(c)) |= kVisited;
}

void SweptMap::markObstacle(const geometry::Point2& p) {
  const Cell cell = cellOf(p);
  std::vector<geometry::Point2>& kept = points_[key(cell)];
  for (const geometry::Point2& q : kept) {
    if (geometry::squaredDistance(p, q) < kSamePoint * kSamePoint) return;
  }
  kept.push_back(p);
  ++point_count_;
  const double h = resolution_, R = reach_;
  const int i_lo = static_cast<int>(std::ceil((p.x - R - start_.x) / h));
  const int i_hi = static_cast<int>(std::floor((p.x + R - start_.x) / h));
  const int j_lo = static_cast<int>(std::ceil((p.y - R - start_.y) / h));
  const int j_hi = static_cast<int>(std::floor((p.y + R - start_.y) / h));
  hold(std::min(i_lo, cell.i), std::min(j_lo, cell.j), std::max(i_hi, cell.i),
       std::max(j_hi, cell.j));
  at(cell) |= kOccupied;
  for (int i = i_lo; i <= i_hi; ++i) {
    const double dx = start_.x + i * h - p.x;
    const double dy = std::sqrt(std::max(0.0, R * R - dx * dx));
    const int lo = static_cast<int>(std::ceil((p.y - dy - start_.y) / h));
    const int hi = static_cast<int>(std::floor((p.y + dy - start_.y) / h));
    for (int j = lo; j <= hi; ++j) at({i, j}) |= kBlocked;
  }
}

double SweptMap::freeLength(const geometry::Point2& from, const geometry::Point2& d,
                            double max) const {
  const geometry::Point2 to{from.x + max * d.x, from.y + max * d.y};
  double best = max;
  forPointsNear({std::min(from.x, to.x) - reach_, std::min(from.y, to.y) - reach_},
                {std::max(from.x, to.x) + reach_, std::max(from.y, to.y) + reach_},
                [&](const geometry::Point2& q) {
                  const double ux = q.x - from.x, uy = q.y - from.y;
                  const double along = ux * d.x + uy * d.y;   // ahead of the centre
                  const double across = d.x * uy - d.y * ux;  // beside its path
                  // Behind it or beside its path: never nearer by going on.
                  if (along <= 0 || std::abs(across) >= reach_) return;
                  const double t = along - std::sqrt(reach_ * reach_ - across * across);
                  best = std::min(best, std::max(0.0, t));
                });
  return best;
}

std::vector<geometry::Point2> SweptMap::points() const {
  std::vector<geometry::Point2> all;
  all.reserve(point_count_);
  for (const auto& [cell, kept] : points_) all.insert(all.end(), kept.begin(), kept.end());
  return all;
}

geometry::OccupancyGrid SweptMap::grid() const {
  geometry::OccupancyGrid grid;
  grid.resolution = resolution_;
  grid.width = width_;
  grid.height = height_;
  const geometry::Point2 first = centre({i0_, j0_});
  grid.origin = {first.x - resolution_ / 2, first.y - resolution_ / 2};
  grid.cells.resize(flags_.size());
  for (std::size_t k = 0; k < flags_.size(); ++k) {
    grid.cells[k] = flags_[k] & kOccupied ? geometry::OccupancyGrid::kOccupied
                    : flags_[k] & kSwept  ? geometry::OccupancyGrid::kFree
                                          : geometry::OccupancyGrid::kUnknown;
  }
  return grid;
}

}  // namespace roomba_rrt::exploration
