#include "roomba_rrt/sim/robot_grid.h"

#include <cmath>
#include <stdexcept>

namespace roomba_rrt::sim {

namespace {
/// Enough cells that a robot has only a few neighbours to test, few enough that the grid stays
/// small for a huge room with tiny robots.
constexpr double kMaxCells = 1 << 20;
}  // namespace

RobotGrid::RobotGrid(double width, double height, double reach, int robots) {
  if (!(width > 0 && height > 0 && reach > 0 && robots >= 0)) {
    throw std::invalid_argument("RobotGrid needs a positive room size and reach");
  }
  double cell = reach;
  while (std::ceil(width / cell) * std::ceil(height / cell) > kMaxCells) cell *= 2;
  inverse_cell_ = 1.0 / cell;
  columns_ = std::max(1, static_cast<int>(std::ceil(width / cell)));
  rows_ = std::max(1, static_cast<int>(std::ceil(height / cell)));
  head_.assign(static_cast<std::size_t>(columns_) * rows_, -1);
  next_.assign(robots, -1);
  previous_.assign(robots, -1);
  cell_.assign(robots, -1);
}

void RobotGrid::insert(int robot, double x, double y) {
  link(robot, rowOf(y) * columns_ + columnOf(x));
}

void RobotGrid::move(int robot, double x, double y) {
  const int cell = rowOf(y) * columns_ + columnOf(x);
  if (cell == cell_[robot]) return;  // the common case: a step of a few millimetres
  unlink(robot);
  link(robot, cell);
}

void RobotGrid::link(int robot, int cell) {
  next_[robot] = head_[cell];
  previous_[robot] = -1;
  if (head_[cell] >= 0) previous_[head_[cell]] = robot;
  head_[cell] = robot;
  cell_[robot] = cell;
}

void RobotGrid::unlink(int robot) {
  const int cell = cell_[robot];
  if (previous_[robot] >= 0) {
    next_[previous_[robot]] = next_[robot];
  } else {
    head_[cell] = next_[robot];
  }
  if (next_[robot] >= 0) previous_[next_[robot]] = previous_[robot];
  cell_[robot] = -1;
}

}  // namespace roomba_rrt::sim
