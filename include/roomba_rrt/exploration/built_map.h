// The map a robot builds of a home it has never seen, as its planners need it: the log-odds map of
// its scans and bumps (mapping::OccupancyMapper, as roomba_mapper publishes it), the cells its
// returns ended in, and where it stood. ROS-free. Exploring and cleaning (explore_clean.h) and
// navigating (navigate_unknown.h) plan on it. Given a map of the home (known_map.h, perhaps
// stale), it starts from that: the map's walls stay walls, its floor is floor until seen
// otherwise (clean_known_map.h, and navigate_unknown.h with a known map).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "roomba_rrt/geometry/occupancy_grid.h"
#include "roomba_rrt/mapping/occupancy_mapper.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::exploration {

class BuiltMap {
 public:
  /// For `robot` (its radius, sensors and initial_pose): a map of 0.05 m cells (gmapping's
  /// default), 10 m round the initial pose, growing as the scans reach farther. With `known`
  /// (a map of the home in the same frame: known_map.h), the map covers it from the start and
  /// takes it as the prior of every grid below: its occupied cells occupied for good, its free
  /// cells free unless a return ended in them or the mapper holds them more likely occupied
  /// than not (a cell of known map is resampled onto the 0.05 m cells: occupied where any
  /// occupied cell meets it, free where only free ones do). With `fine_split` > 1 also a map of
  /// cells `fine_split` times smaller (fineGrid()).
  explicit BuiltMap(const world::RobotSpec& robot,
                    std::shared_ptr<const geometry::OccupancyGrid> known = nullptr,
                    int fine_split = 0);

  /// A scan taken from `sensor` (the sensor's pose in the map): into the map. "" or why it was
  /// refused (mapping::checkScan), naming the field.
  std::string addScan(const robot::Pose2D& sensor, const mapping::ScanView& scan);
  /// Whether the map started from a known map.
  bool hasPrior() const { return !prior_.empty(); }
  /// Whether the cell holding `p` was seen occupied: a return ended in it (for good, whatever
  /// rays pass it later), or the mapper holds it more likely occupied than not (a bump).
  bool seenOccupied(const geometry::Point2& p) const;
  /// The cells the pressed bumper touches at `pose` become occupied.
  void addBump(const robot::Pose2D& pose, const robot::BumperState& bumper);
  /// The robot stands at `p`: its disc is floor in the strict grid, whatever the map says.
  void stoodAt(const geometry::Point2& p) { footprints_.push_back(p); }

  /// How unknown cells are planned over.
  enum class Unknown {
    kWall,  ///< unknown as walls: free only where clearly free (kClearlyFree); cleaning, frontiers
    kFree,  ///< unknown as floor until seen: a goal beyond what the robot has seen
  };
  /// The mapper's grid with the cells returns ended in occupied (an obstacle's edge crosses
  /// them, however many rays passed their free part), and:
  ///   - kWall: free only where clearly free, and free under where the robot stood (and the
  ///     unknown cells its disc reaches into: its lidar starts range_min from its centre);
  ///   - kFree: unknown cells free, grown to take in every point of `include` (the goal) with a
  ///     metre round it.
  geometry::OccupancyGrid grid(Unknown unknown,
                               const std::vector<geometry::Point2>& include = {}) const;
  /// The mapper's grid with the returns' cells occupied: the map frontiers are found on.
  geometry::OccupancyGrid seenGrid() const;
  /// grid(Unknown::kWall) in cells fine_split times smaller (the constructor's; the strict grid
  /// itself without it), for cleaning along the walls. A wall lies anywhere in the 0.05 m cell
  /// its returns end in, and the strict grid blocks all of that cell: a band 2.5 cm wide on
  /// average along every wall and piece of furniture that no row may sweep, 1–2 % of a room's
  /// floor. In the fine grid a cell is occupied where a return (or the chord between two
  /// neighbouring ones) ended in it, free where more rays crossed it than ended in it, and
  /// otherwise what its 0.05 m cell is in the strict grid; free under where the robot stood.
  geometry::OccupancyGrid fineGrid() const;
  /// `grid` as a world (its unknown and occupied cells as walls) with the robot at `pose`.
  world::World world(std::shared_ptr<const geometry::OccupancyGrid> grid,
                     const robot::Pose2D& pose) const;

  const mapping::OccupancyMapper& mapper() const { return mapper_; }
  const world::RobotSpec& robot() const { return robot_; }

  static constexpr double kResolution = 0.05;  ///< m: the map's cells (gmapping's delta)
  /// A cell the robot plans over as floor (Unknown::kWall) has log-odds below this (p < 0.27:
  /// more rays passed it than ended in it, by three free observations).
  static constexpr double kClearlyFree = -1.0;
  /// m: two neighbouring returns this close are taken as one obstacle's (hits_).
  static constexpr double kChord = 0.1;
  /// m beyond a return where it counts as hitting (inside the obstacle, not on its edge).
  static constexpr double kInside = 1e-3;

 private:
  /// Remembers the cells the scan's returns end in (hits_, fine_hits_).
  void markHits(const robot::Pose2D& sensor, const mapping::ScanView& scan);
  /// The returns' cells occupied; cells clearly free only (`strict`); the prior's walls
  /// occupied and its floor free where nothing was seen there.
  void markGrid(geometry::OccupancyGrid& grid, bool strict) const;
  /// Free where the robot stood (see grid()).
  void markFootprints(geometry::OccupancyGrid& grid) const;
  /// The prior's value of the cell (gi, gj) of the lattice from lattice_ (kUnknown off it).
  std::int8_t prior(std::int64_t gi, std::int64_t gj) const;
  static std::int64_t cellKey(std::int64_t i, std::int64_t j) {
    return (i << 32) ^ (j & 0xffffffff);
  }

  world::RobotSpec robot_;
  mapping::OccupancyMapper mapper_;
  /// The mapper's first origin: its lattice's cells stay where they are as the map grows.
  geometry::Point2 lattice_;
  /// Every cell a return ended in (cellKey of its column and row from lattice_).
  std::unordered_set<std::int64_t> hits_;
  /// fineGrid()'s: the mapper at fine_split times the resolution, and its hits (on the same
  /// lattice, cells fine_split times smaller); none without fine_split.
  std::unique_ptr<mapping::OccupancyMapper> fine_;
  std::unordered_set<std::int64_t> fine_hits_;
  std::vector<geometry::Point2> footprints_;  ///< where the robot stood (stoodAt)
  /// The known map resampled onto the mapper's first lattice (prior_width_ columns from
  /// lattice_); empty without one.
  std::vector<std::int8_t> prior_;
  int prior_width_ = 0, prior_height_ = 0;
};

}  // namespace roomba_rrt::exploration
