// The coverage grid: which part of the floor the robot's disc has swept.
#pragma once

#include <cstdint>
#include <vector>

#include "roomba_rrt/world/world.h"

namespace roomba_rrt::sim {

/// A grid of square cells over the room (cell (0, 0) has its lower-left corner at the room's
/// origin (x0, y0); cell (i, j) covers x ∈ [x0 + i·c, x0 + (i+1)·c), y likewise).
///
/// - A cell is *free* when its centre is not inside (or on the edge of) a piece of furniture,
///   nor on a blocked cell of the world's map (the map's free floor).
///   The corners of the room are free floor even though the round robot can never reach them,
///   so a perfect run stays below 100 %.
/// - A cell is *swept* when its centre has been inside (or on the edge of) the robot's disc at
///   the end of some step. Steps are short (≤ 1.7 cm at the lab's 1 m/s), so this union of discs
///   differs from the exactly swept band by less than a millimetre.
/// - coverage() = swept free cells / free cells.
///
/// Rows are bit sets, so marking a disc costs one short span per row it crosses.
class CoverageGrid {
 public:
  explicit CoverageGrid(const world::World& world);

  /// Marks every cell whose centre lies in the disc of radius r around (x, y).
  void markDisc(double x, double y, double r);
  /// Forgets everything swept.
  void clear();
  /// Adds every cell `other` has swept (a grid of the same world): the union of several robots'.
  void merge(const CoverageGrid& other);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double cellSize() const { return cell_; }
  const geometry::Point2& origin() const { return origin_; }  ///< the room's lower-left corner
  bool isFree(int column, int row) const { return test(free_, column, row); }
  bool isSwept(int column, int row) const { return test(swept_, column, row); }

  long freeCells() const { return free_count_; }
  long sweptFreeCells() const { return swept_free_count_; }
  /// Fraction of the free floor swept so far, in [0, 1].
  double coverage() const;

 private:
  bool test(const std::vector<std::uint64_t>& bits, int column, int row) const;
  /// markDisc for rows first_row … first_row + row_count − 1 (≤ kRowsPerBatch), in cell units.
  void markRows(int first_row, int row_count, double cx, double cy, double cr);
  static constexpr int kRowsPerBatch = 32;  ///< the robot's disc spans 14 rows of 2.5 cm

  double cell_;
  double inverse_cell_;
  geometry::Point2 origin_;
  int columns_;
  int rows_;
  int words_per_row_;
  std::vector<std::uint64_t> free_;   ///< bit set: cell centre is not inside furniture
  std::vector<std::uint64_t> swept_;  ///< bit set: cell centre was inside the disc
  long free_count_ = 0;
  long swept_free_count_ = 0;
};

}  // namespace roomba_rrt::sim
