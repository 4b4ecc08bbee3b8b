// Boustrophedon rows in a home the robot has never seen, with backtracking: what the classic
// Roomba (bumper and IR light bumper, no lidar; bump_clean.h) drives next. ROS-free.
//
// In the spirit of BA* (Viet et al., "BA*: an online complete coverage algorithm for cleaning
// robots", Applied Intelligence 39, 2013): the robot sweeps back and forth until it is blocked,
// then goes over the floor it has swept to the nearest place where it can start sweeping again,
// and it is done when there is no such place. Here, on the map of swept_map.h, in moves of two
// kinds:
//   - a row: straight along x (east or west) from where the robot is, on for as long as its disc
//     sweeps new floor ahead and nothing it has found is in its way; the floor it has not seen is
//     taken as floor (optimistic), the IR light bumper or the bumper cuts the row short;
//   - a shift: straight along y (north or south) to the next row line (the lines lie a swath
//     apart through the start; a swath on from a row off the lines), or as far as it can go
//     before something it found is in the way, and on to what it finds just beyond the line
//     (kSnapToWall): the row after it runs along that obstacle, sweeping the strip beside it.
// After a row the robot shifts to the side it sweeps towards (then the other); after a shift it
// drives the row back the way the last row came (then the other way): boustrophedon. When
// neither gives new floor (each move must promise `min_gain` of floor it has not swept within
// its first `lookahead`), it backtracks: Dijkstra from the robot over the centres whose disc it
// has swept (safe: it never plans through floor it has not been on, nor near a point it found on
// an obstacle), the first centre from which a row or a shift promises new floor, and the path
// there. No such centre: done. Each centre and heading is tried `max_tries` times at most, so
// that a move that finds nothing new (a bump the map cannot place) is not repeated for ever.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>
#include <vector>

#include "roomba_rrt/exploration/swept_map.h"
#include "roomba_rrt/geometry/geometry.h"

namespace roomba_rrt::exploration {

/// The four headings of the moves: rows east (+x) or west (−x), shifts north (+y) or south (−y).
enum class Heading : std::uint8_t { kEast, kWest, kNorth, kSouth };

geometry::Point2 unit(Heading heading);  ///< the unit vector
double yaw(Heading heading);             ///< rad in the map
Heading opposite(Heading heading);
const char* toString(Heading heading);

struct BoustrophedonOptions {
  /// m between row lines: the Roomba's 0.34 m disc less 1.5 cm of overlap (13 cells of 2.5 cm,
  /// so that the lines run through cell centres).
  double swath = 0.325;
  double min_shift = 0.04;  ///< m: a shift to a line nearer than this goes to the next line
  double lookahead = 0.3;   ///< m of a move over which the new floor it promises is counted
  double min_gain = 0.02;   ///< m² of new floor a move must promise (a 0.34 m disc, 6 cm on)
  /// m² a move must promise to be chosen before those that promise less (next()'s first pass)
  double first_gain = 0.035;
  /// m: a centre is safe (a transit passes it) when its disc but for this rim is swept floor.
  double safe_rim = 0.03;
  int max_tries = 3;  ///< moves started from one cell in one heading
  /// m: points found on both sides of a move's way, at most this far from it and as far ahead,
  /// are guessed to be one straight wall across it (the move is left for last).
  double wall_gap = 1.0;
};

/// One move: from `start`, in `heading`, with the transit that gets the robot there.
struct Move {
  enum class Kind : std::uint8_t { kRow, kShift };
  Kind kind = Kind::kRow;
  geometry::Point2 start;
  Heading heading = Heading::kEast;
  /// m: a shift's (to the next row line); a row goes on while it sweeps new floor (infinite).
  double length = std::numeric_limits<double>::infinity();
  double gain = 0;  ///< m² of new floor it promises (a shift: with the row after it)
  /// From the robot to `start` over safe centres; empty when the robot starts where it stands.
  std::vector<geometry::Point2> transit;
};

class OnlineBoustrophedon {
 public:
  /// Row lines through `start` (its y), the first row towards the side `start_yaw` faces.
  OnlineBoustrophedon(const geometry::Point2& start, double start_yaw,
                      const BoustrophedonOptions& options = {});

  /// The next move for the robot at `at`, the last move (if any) ended: the boustrophedon's next
  /// row or shift from here, else the nearest over safe floor. None: no floor the robot can reach
  /// is left to sweep, it is done.
  std::optional<Move> next(const SweptMap& map, const geometry::Point2& at);

  /// `move` (the last next()'s) swept nothing: it is not started from its cell in its heading
  /// again.
  void sweptNothing(const SweptMap& map, const Move& move);

  /// The new floor (m², cells neither swept nor occupied) the disc sweeps going from `from` in
  /// `heading` for `length`, or less where it would come within reach of a point found on an
  /// obstacle; the floor under the disc at `from` does not count.
  static double newFloor(const SweptMap& map, const geometry::Point2& from, Heading heading,
                         double length);
  /// The y of the first row line beyond `y` towards `side` (kNorth or kSouth) at least min_shift
  /// away.
  double nextRowLine(double y, Heading side) const;
  const BoustrophedonOptions& options() const { return options_; }
  int backtracks() const { return backtracks_; }  ///< next() calls that had to backtrack

  /// m: a shift goes on past its row line to a point found ahead less than this beyond it (the
  /// IR light bumper sees 0.15 m beyond the bumper), so that the row after it runs along the
  /// obstacle.
  static constexpr double kSnapToWall = 0.1;
  /// m: a row or a shift stops this short of where its disc would come within reach of a point
  /// found ahead.
  static constexpr double kStopShort = 0.003;

 private:
  /// next()'s tiers: moves that promise first_gain with walls guessed straight, min_gain so, and
  /// min_gain without guessing.
  static constexpr int kTiers = 3;
  /// A row or a shift from `from` (its transit not yet known), what it promises with walls
  /// guessed straight and without, and the map's cell (an index of backtrack()'s) it starts on.
  struct Candidate {
    Move move;
    double guessed = 0, unguessed = 0;
    int cell = -1;
  };
  /// The row (heading east or west) or shift (north or south) from `from`; none when it was
  /// tried out there.
  std::optional<Candidate> candidate(const SweptMap& map, const geometry::Point2& from,
                                     Heading heading) const;
  /// The tier `c` belongs to (kTiers: none).
  int tier(const Candidate& c) const;
  static double gainOf(const Candidate& c, int tier) { return tier < 2 ? c.guessed : c.unguessed; }
  /// The nearest candidate of each tier over safe centres, with its transit, searching until one
  /// of the first tier is found.
  void backtrack(const SweptMap& map, const geometry::Point2& at,
                 std::optional<Candidate> (&found)[kTiers]) const;
  /// How far ahead of `from` (at most `max`) a straight wall crosses the way in `heading`,
  /// guessed from the points found nearest to the way on each side (within wall_gap), as far
  /// ahead of `from` give or take kInLine, when the line between them crosses no swept floor;
  /// infinite without such points.
  double guessedWall(const SweptMap& map, const geometry::Point2& from, Heading heading,
                     double max) const;
  /// Counts a try of `move`, promising `gain`; returns it.
  Move chosen(const SweptMap& map, Move move, double gain);
  bool triedOut(const SweptMap& map, const geometry::Point2& from, Heading heading) const;
  static std::int64_t tryKey(const SweptMap& map, const geometry::Point2& from, Heading heading);

  BoustrophedonOptions options_;
  double line_y_;  ///< a row line's y (the start's)
  std::optional<Move::Kind> last_;
  Heading row_heading_;                          ///< the last row's
  Heading side_ = Heading::kNorth;               ///< the side the rows go towards
  std::unordered_map<std::int64_t, int> tries_;  ///< by cell and heading
  int backtracks_ = 0;
};

}  // namespace roomba_rrt::exploration
