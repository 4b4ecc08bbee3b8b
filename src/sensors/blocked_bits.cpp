// A map's blocked cells as bits (blocked_bits.h).
#include "roomba_rrt/sensors/blocked_bits.h"

#include <algorithm>

namespace roomba_rrt::sensors {

namespace {

/// Bytes per line of `length` cells: the border's cells before and after them, and the 7 bytes
/// past the last that a word read from it may take.
std::size_t strideFor(int length) { return static_cast<std::size_t>((length + 2 * 8 + 7) / 8 + 7); }

/// The 8 × 8 bit matrix with row k in byte k, transposed: bit b of byte k becomes bit k of byte
/// b (Hacker's Delight, 7-3).
std::uint64_t transpose8(std::uint64_t x) {
  x = (x & 0xAA55AA55AA55AA55ull) | ((x & 0x00AA00AA00AA00AAull) << 7) |
      ((x >> 7) & 0x00AA00AA00AA00AAull);
  x = (x & 0xCCCC3333CCCC3333ull) | ((x & 0x0000CCCC0000CCCCull) << 14) |
      ((x >> 14) & 0x0000CCCC0000CCCCull);
  x = (x & 0xF0F0F0F00F0F0F0Full) | ((x & 0x00000000F0F0F0F0ull) << 28) |
      ((x >> 28) & 0x00000000F0F0F0F0ull);
  return x;
}

}  // namespace

static_assert(BlockedBits::kPadCells == 8, "the cells of a line start at its second byte");

BlockedBits::BlockedBits(const geometry::OccupancyGrid& grid)
    : lines_(grid.height), length_(grid.width), stride_(strideFor(grid.width)) {
  bytes_.assign(static_cast<std::size_t>(lines_ + 2 * kPadLines) * stride_, 0xff);
  for (int j = 0; j < lines_; ++j) {
    const std::int8_t* cell = grid.cells.data() + static_cast<std::size_t>(j) * length_;
    std::uint8_t* out = bytes_.data() + static_cast<std::size_t>(j + kPadLines) * stride_ + 1;
    for (int i = 0; i < length_; i += 8) {
      unsigned byte = 0;
      const int n = std::min(8, length_ - i);
      for (int k = 0; k < n; ++k) {
        byte |= static_cast<unsigned>(geometry::OccupancyGrid::blockedValue(cell[i + k])) << k;
      }
      out[i / 8] =
          static_cast<std::uint8_t>(byte | (0xff << n));  // beyond the last column: blocked
    }
  }
}

BlockedBits BlockedBits::transposed() const {
  BlockedBits t;
  t.lines_ = length_;
  t.length_ = lines_;
  t.stride_ = strideFor(t.length_);
  t.bytes_.assign(static_cast<std::size_t>(t.lines_ + 2 * kPadLines) * t.stride_, 0xff);
  // Block (p, q): cells 8p .. 8p + 7 of lines 8q .. 8q + 7 here, 8q .. 8q + 7 of 8p .. 8p + 7
  // there.
  for (int q = 0; 8 * q < lines_; ++q) {
    for (int p = 0; 8 * p < length_; ++p) {
      std::uint64_t block = 0;
      for (int k = 0; k < 8; ++k) {
        // Lines beyond the last (the border and after it) are blocked.
        const std::uint64_t byte = 8 * q + k < lines_ ? line(8 * q + k)[1 + p] : 0xff;
        block |= byte << (8 * k);
      }
      block = transpose8(block);
      for (int b = 0; b < 8 && 8 * p + b < length_; ++b) {
        t.bytes_[static_cast<std::size_t>(8 * p + b + kPadLines) * t.stride_ + 1 + q] =
            static_cast<std::uint8_t>(block >> (8 * b));
      }
    }
  }
  return t;
}

}  // namespace roomba_rrt::sensors
