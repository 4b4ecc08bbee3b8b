// Coverage planning: a path that sweeps the robot's disc over all the floor it can reach, as a
// list of straight cleaning rows joined by collision-free transits. ROS-free.
//
// A boustrophedon cellular decomposition (Choset & Pignon, 1997) of the free space of the disc's
// CENTRE, on a lattice: sample the free space and keep what the start reaches (free_space.h;
// reachable_floor.h measures the floor the disc reaches), pass small islands round instead of
// splitting at them, decompose and lay each cell's rows a swath apart, prune the rows to the
// floor only they sweep (boustrophedon.h), order the cells and the rows' directions
// (cell_order.h), join the rows with transits, and once round the walls where they lie at a slant
// to the rows (wall_loop.h). After the rows, touchUp() plans a tour over the floor the robot did
// not sweep (touch_up.h, tour.h). doc/coverage.md describes each step, why boustrophedon, the
// results and the limits.
//
// Every row and transit segment keeps the planning radius (robot radius + clearance) from every
// wall, piece of furniture and blocked map cell, exactly (FreeSpace: the lattice's free points
// are joined by provably free edges; other segments pass FreeSpace::segmentFree).
//
// Areas are measured on the lattice (each point stands for an h × h square of floor): the floor
// (not inside a wall or obstacle), the reachable floor (within the robot's radius of a centre it
// can reach from the start, with its own radius: a gap the disc fits through only without the
// clearance is reachable, but not planned; the centres between the lattice points at the edge of
// the free space are tested exactly, so the floor in a map's stepped walls counts as far as the
// disc reaches into them), the part the rows sweep, and the unreachable floor (floor minus
// reachable floor: corners the disc cannot enter, gaps narrower than the disc, closed rooms).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "roomba_rrt/coverage/free_space.h"
#include "roomba_rrt/world/world.h"

namespace roomba_rrt::coverage {

/// How the floor is covered.
struct CoverageOptions {
  /// How much neighbouring rows' strips overlap at least (m): more than the follower's tracking
  /// error on a straight row (millimetres); what a wider error leaves, the touch-up sweeps.
  static constexpr double kMinOverlap = 0.005;
  /// Largest distance between neighbouring rows (m): at most the robot's diameter, so the swept
  /// strips overlap. 0.335 m for the 0.34 m Roomba. A cell's rows are as few as keep neighbours
  /// at most this far apart, so a little more swath saves a row where a cell is just over a
  /// whole number of swaths high; the full diameter (no overlap) leaves unswept lines between
  /// rows wherever the follower is a millimetre off.
  double swath = 0.34 - kMinOverlap;
  /// Edge of the lattice the free space is sampled on (m): the coverage grid's cell size. Finer
  /// brings rows closer to curved furniture; cost grows with its inverse square.
  double resolution = 0.025;
  /// Kept between the robot's disc and everything, on top of its radius (m): rows run this far
  /// from the walls, so a follower's small tracking errors do not bump.
  double clearance = 0.01;
  /// Kept by the touch-up's rows along a wall where the clearance leaves a band of floor no row
  /// sweeps (m): edge cleaning, driven parallel to the wall. A wall that does not lie on the
  /// lattice's cell boundaries (a map cut anywhere with --crop) has lattice points within the
  /// clearance of it: floor the disc reaches, which 1 cm keeps it from (about 1 % of a small
  /// room). Closer than 3 mm bumps with a late pose. At or above the clearance: no edge cleaning.
  double edge_clearance = 0.003;
};

/// The options for cleaning `world`: the defaults on a lattice of the world's coverage cell, so
/// the planner samples the floor on the grid the simulator measures the cleaned floor on (a
/// large map's coarser cell: world::defaultCoverageCellSize), with rows the world's robot's
/// diameter apart less the overlap (kMinOverlap; at least two cells): 0.335 m for the Roomba.
/// roomba_bt, roomba_coverage and coverage_planner use it, so they plan alike for any robot.
CoverageOptions cleaningOptions(const world::World& world);

/// One leg of a plan.
struct Leg {
  enum class Kind { kRow, kTransit };
  Kind kind = Kind::kRow;
  /// A row: its two ends (the disc cleans along it). A transit: a polyline of two or more
  /// points from the previous leg's end to the next row's start.
  Polyline points;
  /// A touch-up row along a wall, closer to it than the clearance (edge cleaning): its ends keep
  /// the clearance, the rest CoverageOptions::edge_clearance.
  bool along_wall = false;
};

/// A coverage path and what it achieves. Areas in m².
struct CoveragePlan {
  std::vector<Leg> legs;
  double floor_area = 0;        ///< the room's floor: not inside a wall, obstacle or blocked cell
  double reachable_area = 0;    ///< floor the robot's disc can reach from the start
  double swept_area = 0;        ///< floor the disc sweeps along the rows
  double unreachable_area = 0;  ///< floor_area − reachable_area
  int cells = 0;                ///< cells of the decomposition (islands do not split cells)

  /// Length of all legs (m) and of the rows alone.
  double length() const;
  double rowLength() const;
};

/// Plans coverage in one world. Sampling the world is done once, in the constructor; plan() and
/// resume() can then be called for any start. Deterministic: the same world, options and start
/// give the same plan.
class CoveragePlanner {
 public:
  /// util::InvalidInput naming the option when swath is not in [2·resolution, 2·robot radius],
  /// resolution not in [0.001, robot radius] m (or too fine for the world: more than 2·10^7
  /// lattice points) or clearance not in [0, robot radius] m.
  explicit CoveragePlanner(const world::World& world, const CoverageOptions& options = {});

  /// The plan from `start` (where the robot is). The first leg is the transit from `start` to the
  /// first row (none when the row starts there). A start the disc cannot be at (inside furniture)
  /// gives no legs and no reachable floor; one from which the robot cannot drive to a point that
  /// has the clearance gives the reachable floor but no legs.
  CoveragePlan plan(const Point2& start) const;

  /// What is left of `plan` for a robot that stopped at `at` during leg `leg` (after a bump and a
  /// back-up): a transit from `at` to where the work resumes — the closest point of that row
  /// when `leg` is a row, else the next row's start — then the rest of that row and every later
  /// leg unchanged. Never starts over. A row that cannot be reached from `at` is skipped (the
  /// next one is tried); no legs means nothing is left that can be reached from `at`. To give up
  /// on the row the robot was in (it bumped there too often), resume from `leg + 1`. The areas
  /// are those of `plan`.
  CoveragePlan resume(const CoveragePlan& plan, std::size_t leg, const Point2& at) const;

  /// What is left of `plan`, made in another world (the same room as the robot saw it before:
  /// furniture it did not know has appeared since), for a robot at `at` during leg `leg`, made
  /// free in this planner's world: the rest of the current row (from its point closest to `at`)
  /// and every later row in their order, each row cut to its pieces that keep the planning
  /// radius here (a row along a wall: its own clearance, and whole or not at all; a row cut
  /// where something now stands ends 2 cm before it, as round an island), and new transits to
  /// each piece from where the previous one ended (from `at` first). A piece that cannot be
  /// reached is left out. The areas are those of `plan`. It keeps the order the robot was
  /// driving in: a robot that saw a chair where its rows ran goes on with the same rows (a new
  /// plan of the floor left from where it stands took the furnished room's cleaning from 216 s
  /// to 315 s to 95 %: clean_known_map.h).
  CoveragePlan repair(const CoveragePlan& plan, std::size_t leg, const Point2& at) const;

  /// Marks in `swept` (one flag per lattice point of freeSpace(), sized on first use) the floor
  /// under the robot's disc at `at`: what a robot knows it has cleaned, from its own poses.
  void markSwept(std::vector<std::uint8_t>& swept, const Point2& at) const;
  /// The part of the floor's lattice points that `swept` marks (0..1).
  double sweptFraction(const std::vector<std::uint8_t>& swept) const;

  /// The touch-up after the rows: a tour from `at` over the spots of reachable floor that
  /// `swept` does not mark (each spot of at least `min_spot_area`: the corners a U-turn cut, a
  /// skipped row, the floor beside a bump), in the order of touchUpTour() (tour.h: nearest first,
  /// then 2-opt). What lies along a wall closer than any free lattice point reaches is swept by a
  /// row beside it: at the clearance when one reaches it, else (the floor within the clearance
  /// of the wall) along the wall at the edge clearance, ramping in from the clearance and out to
  /// it again (Leg::along_wall). Each other spot is visited by a transit to the free lattice
  /// point whose disc covers most of it, then a row of no length there (the robot passes or
  /// stops there, in any heading).
  /// No legs when nothing is missed. The areas are those of the reachable floor from `at`.
  /// Without `edge_cleaning`, no rows along the walls at the edge clearance: what only they
  /// would sweep is left for a later pass.
  /// The steps are TouchUp's (touch_up.h).
  CoveragePlan touchUp(const std::vector<std::uint8_t>& swept, const Point2& at,
                       double min_spot_area = kMinSpotArea, bool edge_cleaning = true) const;

  /// A spot of missed floor smaller than this (m²) is not worth going back for.
  static constexpr double kMinSpotArea = 0.004;

  const FreeSpace& freeSpace() const { return space_; }
  const CoverageOptions& options() const { return options_; }

 private:
  friend class TouchUp;  // touch_up.h: one touch-up pass, from transit() and reachableFloor()

  /// A collision-free polyline from `from` (where the robot stands) to `to` (a point of a row):
  /// the straight segment when it is free, else via the nearest lattice points and the shortest
  /// lattice path between them. nullopt when `to` cannot be reached.
  std::optional<Polyline> transit(const Point2& from, const Point2& to) const;
  /// The floor reachable from `start` (one flag per lattice point), with the plan's areas set.
  std::vector<std::uint8_t> reachableFloor(CoveragePlan& plan, const Point2& start) const;

  /// The pieces of the segment a–b that are free in space_ for a disc of `radius`, in order from
  /// a: the segment itself when nothing is in its way (a row planned in open_ across an island;
  /// a row of another world's plan, repair()).
  std::vector<std::pair<Point2, Point2>> freePieces(const Point2& a, const Point2& b,
                                                    double radius) const;

  CoverageOptions options_;
  FreeSpace space_;
  std::optional<FreeSpace> open_;  ///< the free space without its islands, if it has any
};

}  // namespace roomba_rrt::coverage
