// A map the robot builds: a log-odds occupancy grid updated from range scans and the robot's pose
// (every cell a ray crosses is evidence of free space, the cell it ends in of an obstacle) and
// from the bumper (the cells it pressed). gmapping's mapping half without its localisation: the
// pose is taken as exact (our simulator's odometry is). ROS-free; roomba_mapper publishes what
// grid() returns, and an in-process user (a tool, a cleaning tree) calls it directly.
//
// Each ray is walked through the grid exactly (Amanatides & Woo: every cell the segment passes
// through, in order, by its crossings of the cell edges). The log-odds of a cell is the sum of
// its evidence, each free observation adding log_odds_free (< 0) and each hit log_odds_occupied
// (> 0), clamped to ±log_odds_limit so that a moved chair is unlearned in a few scans. A ray that
// reads +inf (REP 117: nothing within range_max) is free space up to range_max.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/robot/robot_state.h"

namespace roomba_rrt::mapping {

/// One scan as sensor_msgs/LaserScan gives it, without copying its ranges: ray k leaves the
/// sensor at angle_min + k · angle_increment from its heading and reads ranges[k] (m; −inf
/// nearer than range_min, +inf nothing within range_max, NaN an error: REP 117).
struct ScanView {
  double angle_min = 0;
  double angle_max = 0;
  double angle_increment = 0;
  double range_min = 0;
  double range_max = 0;
  const float* ranges = nullptr;
  std::size_t count = 0;
};

/// How the map is made. The names follow gmapping's parameters where it has one.
struct MapperOptions {
  double resolution = 0.05;  ///< cell edge, m (gmapping's delta)
  /// The region the map covers from the start (m; gmapping's xmin, ymin, xmax, ymax). The map
  /// grows, by whole cells on the same lattice, when a scan reaches beyond it.
  double xmin = -5, ymin = -5, xmax = 5, ymax = 5;
  /// A return beyond this (m) only clears the cells up to it (gmapping's maxUrange); a ray is
  /// also never used beyond the scan's range_max.
  double max_range = 1000;
  double log_odds_occupied = 0.85;  ///< added at a ray's end (p = 0.70)
  double log_odds_free = -0.4;      ///< added to each cell a ray crosses (p = 0.40)
  double log_odds_limit = 3.5;      ///< |log-odds| ≤ this (p within 0.03 of 0 or 1)
  /// A known cell whose occupancy probability is above this is published occupied (100), else
  /// free (0) (as gmapping's occ_thresh; the published map is trinary, as map_server's).
  double occupied_threshold = 0.5;
  /// The grid never grows beyond this many cells (a scan that would need more updates only the
  /// part inside).
  long long max_cells = 40'000'000;
};

/// The supported ranges (validate() refuses anything outside them, naming the field).
struct MapperLimits {
  static constexpr double kMinResolution = 1e-3;  ///< m
  static constexpr double kMaxResolution = 10;    ///< m
  static constexpr double kMaxCoordinate = 1e5;   ///< |xmin|, ..., |ymax| ≤ this, m
  static constexpr double kMaxLogOdds = 50;       ///< every log-odds parameter, in magnitude
  static constexpr long long kMaxCells = 100'000'000;
};

/// Throws util::InvalidInput naming the field ("resolution: must be in [0.001, 10] m, got 0"):
/// non-finite values, xmin ≥ xmax or ymin ≥ ymax, a region of more than max_cells cells, a
/// non-positive max_range, log_odds_occupied ≤ 0, log_odds_free ≥ 0, log_odds_limit ≤ 0,
/// occupied_threshold outside (0, 1).
void validate(const MapperOptions& options);

/// Why a scan was not used: "" when it was. The scan's fields named as in sensor_msgs/LaserScan.
std::string checkScan(const ScanView& scan);

/// The direction (rad, in the map) of the first ray of `scan` taken with the sensor heading
/// `heading`: each angle within a turn before they are added (a heading and an angle_min that
/// are finite but near ±1.8e308 would add up to −inf).
double firstRayAngle(double heading, const ScanView& scan);

class OccupancyMapper {
 public:
  /// Throws util::InvalidInput as validate() does.
  explicit OccupancyMapper(const MapperOptions& options);

  /// Adds one scan taken by a sensor at `sensor_pose` (in the map's frame). Returns "" when it
  /// was used, or why not (checkScan(), a pose that is not finite or beyond
  /// MapperLimits::kMaxCoordinate): the map is then unchanged.
  /// Rays reading NaN, −inf or a finite range outside [range_min, range_max] are skipped; a
  /// finite range beyond max_range, or +inf, clears the cells up to min(range_max, max_range).
  std::string addScan(const robot::Pose2D& sensor_pose, const ScanView& scan);
  /// How far the rays of `scan` are trusted: its range_max, at most max_range.
  double trustedRange(const ScanView& scan) const {
    return std::min<double>(scan.range_max, options_.max_range);
  }
  /// Whether `range`, one of `scan`'s, is a return addScan() counts as a hit: in
  /// [range_min, trustedRange()].
  bool isReturn(double range, const ScanView& scan) const {
    return range >= scan.range_min && range <= trustedRange(scan);
  }

  /// Adds the bumper's evidence for a robot of `radius` at `pose`: each closed switch marks the
  /// cell at the bumper's edge where it points (both switches: straight ahead; left only: 45°
  /// to the left; right only: 45° to the right) as occupied, once per call. Nothing when the
  /// bumper is not pressed.
  void addBump(const robot::Pose2D& pose, double radius, const robot::BumperState& bumper);

  /// Adds one hit's evidence to the cell holding `p` (the map grows to hold it).
  void markOccupied(const geometry::Point2& p);

  /// The map as nav_msgs/OccupancyGrid means it: kUnknown (−1) where nothing was observed,
  /// kOccupied (100) where the occupancy is above occupied_threshold, else kFree (0).
  geometry::OccupancyGrid grid() const;
  /// The same into `out`, reusing its memory.
  void grid(geometry::OccupancyGrid& out) const;

  /// The log-odds of cell (i, j) of grid() (0 for an unobserved cell; kept in steps of
  /// 1/256), and whether it was observed.
  double logOdds(int i, int j) const {
    return observed(i, j) ? log_odds_[index(i, j)] / kLogOddsScale : 0.0;
  }
  bool observed(int i, int j) const { return log_odds_[index(i, j)] != kUnobserved; }

  int width() const { return width_; }
  int height() const { return height_; }
  geometry::Point2 origin() const { return origin_; }
  double resolution() const { return options_.resolution; }
  const MapperOptions& options() const { return options_; }
  std::size_t scans() const { return scans_; }  ///< scans used so far

 private:
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(width_) + i;
  }
  /// Grows the grid (whole cells, same lattice, at least `margin` cells more on a side that
  /// grows) so that it holds [x0, x1] × [y0, y1], within max_cells.
  void cover(double x0, double y0, double x1, double y1);
  /// Adds the free evidence along the segment from (x0, y0) to (x1, y1) (in cells), and the hit
  /// evidence at its end when `hit`.
  void traceRay(double x0, double y0, double x1, double y1, bool hit);
  void add(std::size_t k, int delta);

  MapperOptions options_;
  int width_ = 0, height_ = 0;
  geometry::Point2 origin_;
  /// Each cell's log-odds in steps of 1 / kLogOddsScale (two bytes a cell: a 10^6-cell map
  /// is 2 MB, which stays in the caches), or kUnobserved (above every log-odds the limit
  /// allows).
  static constexpr double kLogOddsScale = 256;
  static constexpr std::int16_t kUnobserved = INT16_MAX;
  std::vector<std::int16_t> log_odds_;
  int occupied_ = 0, free_ = 0, limit_ = 0;  ///< the options' log-odds in those steps
  std::size_t scans_ = 0;
};

}  // namespace roomba_rrt::mapping
