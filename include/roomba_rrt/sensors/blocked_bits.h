// A map's blocked cells as bits, one line of the grid after another (its rows, or its columns),
// with a border of blocked bits round the grid: what ray_cast.h reads to test every cell a ray
// touches along a line with one word, however many cells that is. One bit per cell for each
// orientation (a 10^8-cell map: 12.5 MB each); built once per map. ROS-free.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "roomba_rrt/geometry/occupancy_grid.h"

namespace roomba_rrt::sensors {

/// Bit (u, v) is 1 when cell u of line v is blocked (OccupancyGrid::blocked: occupied, unknown,
/// or beyond the grid). Along x the lines are the grid's rows (u = column i, v = row j); along y
/// its columns (u = row j, v = column i). Lines −kPadLines .. lines() + kPadLines − 1 and cells
/// −kPadCells .. length() + kPadCells − 1 of each exist (the border, all blocked), and the 8 bytes
/// from any byte of a line can be read as one word.
class BlockedBits {
 public:
  static constexpr int kPadLines = 2;
  static constexpr int kPadCells = 8;

  BlockedBits() = default;
  /// Along x: the grid's rows.
  explicit BlockedBits(const geometry::OccupancyGrid& grid);
  /// The same cells along the other axis (the grid's columns), by 8 × 8 blocks of bits.
  BlockedBits transposed() const;

  int lines() const { return lines_; }    ///< rows along x, columns along y
  int length() const { return length_; }  ///< cells per line
  std::ptrdiff_t stride() const { return static_cast<std::ptrdiff_t>(stride_); }  ///< bytes

  /// Line v's bytes: cell u is bit (u + kPadCells) % 8 of byte (u + kPadCells) / 8.
  const std::uint8_t* line(int v) const {
    return bytes_.data() + static_cast<std::size_t>(v + kPadLines) * stride_;
  }
  /// The bits of cells u .. u + n − 1 of `line` (bit k: cell u + k), n ≤ 57.
  static std::uint64_t cells(const std::uint8_t* line, int u, int n) {
    const int bit = u + kPadCells;
    std::uint64_t word;
    std::memcpy(&word, line + (bit >> 3), sizeof word);
    return (word >> (bit & 7)) & ((std::uint64_t{2} << (n - 1)) - 1);
  }
  static bool blocked(const std::uint8_t* line, int u) {
    const int bit = u + kPadCells;
    return (line[bit >> 3] >> (bit & 7)) & 1;
  }

 private:
  int lines_ = 0, length_ = 0;
  std::size_t stride_ = 0;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace roomba_rrt::sensors
