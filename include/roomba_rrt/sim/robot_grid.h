// The spatial index of robot–robot contact: a uniform bucket grid over the room, so a robot looks
// only at the robots in the 3 × 3 cells around it instead of at all of them.
#pragma once

#include <algorithm>
#include <vector>

namespace roomba_rrt::sim {

/// Robots 0 … n−1 filed by the cell their centre is in. Cells are at least `reach` wide, so every
/// robot within `reach` of a point lies in the 3 × 3 cells around that point's cell; a point
/// outside the room is filed in the nearest border cell, which only brings it closer.
///
/// Each cell is an intrusive doubly-linked list (head per cell, next/previous per robot), so
/// moving a robot to another cell costs O(1) and the index allocates nothing while stepping.
class RobotGrid {
 public:
  RobotGrid(double width, double height, double reach, int robots);

  /// Files `robot` (not yet filed) at (x, y).
  void insert(int robot, double x, double y);
  /// Moves `robot` (already filed) to (x, y).
  void move(int robot, double x, double y);

  /// Calls visit(j) for every filed robot in the 3 × 3 cells around (x, y): a superset of the
  /// robots within `reach` of it.
  template <typename Visit>
  void forEachNear(double x, double y, Visit visit) const {
    const int column = columnOf(x), row = rowOf(y);
    const int last_column = std::min(column + 1, columns_ - 1);
    const int last_row = std::min(row + 1, rows_ - 1);
    for (int r = std::max(row - 1, 0); r <= last_row; ++r) {
      for (int c = std::max(column - 1, 0); c <= last_column; ++c) {
        for (int j = head_[r * columns_ + c]; j >= 0; j = next_[j]) visit(j);
      }
    }
  }

 private:
  int columnOf(double x) const {
    return std::clamp(static_cast<int>(x * inverse_cell_), 0, columns_ - 1);
  }
  int rowOf(double y) const {
    return std::clamp(static_cast<int>(y * inverse_cell_), 0, rows_ - 1);
  }
  void unlink(int robot);
  void link(int robot, int cell);

  double inverse_cell_;
  int columns_;
  int rows_;
  std::vector<int> head_;      ///< per cell: first robot, −1 when empty
  std::vector<int> next_;      ///< per robot: next robot in its cell, −1 at the end
  std::vector<int> previous_;  ///< per robot: previous robot in its cell, −1 at the head
  std::vector<int> cell_;      ///< per robot: its cell, −1 when not filed
};

}  // namespace roomba_rrt::sim
