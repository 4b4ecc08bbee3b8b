#include "roomba_rrt/planning/grid_regions.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

namespace roomba_rrt::planning {
namespace {

constexpr std::uint8_t kNoLabel = 0xff;

/// The index k of kMoves[k] == (di, dj) (each in −1..1, not both 0).
int moveIndex(int di, int dj) {
  static constexpr int kIndex[3][3] = {{5, 1, 7}, {3, -1, 2}, {6, 0, 4}};  // [di + 1][dj + 1]
  return kIndex[di + 1][dj + 1];
}

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

GridRegions::GridRegions(std::shared_ptr<const geometry::ClearanceMap> map, double radius,
                         int block)
    : map_(std::move(map)) {
  if (!map_) throw std::invalid_argument("GridRegions: no map");
  if (!(radius >= 0) || !std::isfinite(radius)) {
    throw std::invalid_argument("GridRegions: radius must be finite and >= 0");
  }
  if (block != 2 && block != 4 && block != 8 && block != 16) {
    throw std::invalid_argument("GridRegions: block must be 2, 4, 8 or 16");
  }
  const double t0 = threadCpuSeconds();
  disc_ = map_->disc(radius);
  width_ = map_->grid().width;
  height_ = map_->grid().height;
  block_ = block;
  block_shift_ = block == 2 ? 1 : block == 4 ? 2 : block == 8 ? 3 : 4;
  blocks_x_ = (width_ + block_ - 1) / block_;
  blocks_y_ = (height_ + block_ - 1) / block_;
  buildEdges();
  buildRegions();
  build_seconds_ = threadCpuSeconds() - t0;
}

int GridRegions::cellOf(const Point2& p) const {
  const geometry::OccupancyGrid& g = map_->grid();
  const int i = g.column(p.x), j = g.row(p.y);
  return g.inside(i, j) ? j * width_ + i : -1;
}

Point2 GridRegions::centre(int cell) const {
  const geometry::OccupancyGrid& g = map_->grid();
  return {g.origin.x + (cell % width_ + 0.5) * g.resolution,
          g.origin.y + (cell / width_ + 0.5) * g.resolution};
}

bool GridRegions::nodeFree(int cell) const { return map_->discFree(centre(cell), disc_); }

void GridRegions::buildEdges() {
  // Per cell: 0 the disc is not free at its centre, 1 free there, 2 free at every point of the
  // cell: more than radius + √2 cells from every blocked centre (the distance transform's
  // thresholds, ClearanceMap::Disc::free_above) and far enough from the map's edge that the disc
  // stays inside it (radius + 1 cells).
  const std::size_t cells = static_cast<std::size_t>(width_) * height_;
  std::vector<std::uint8_t> state(cells);
  const int edge_margin = static_cast<int>(std::ceil(disc_.radius / map_->grid().resolution)) + 1;
  for (int j = 0; j < height_; ++j) {
    for (int i = 0; i < width_; ++i) {
      const int cell = j * width_ + i;
      const bool inner = i >= edge_margin && j >= edge_margin && i < width_ - edge_margin &&
                         j < height_ - edge_margin;
      if (inner && map_->squaredCellDistance(i, j) > disc_.free_above) {
        state[cell] = 2;
      } else {
        state[cell] = nodeFree(cell) ? 1 : 0;
      }
    }
  }
  // A block is clear when all its cells are free at every point.
  clear_.assign(static_cast<std::size_t>(blocks_x_) * blocks_y_, 1);
  for (int j = 0; j < height_; ++j) {
    for (int i = 0; i < width_; ++i) {
      if (state[static_cast<std::size_t>(j) * width_ + i] != 2) clear_[blockAt(i, j)] = 0;
    }
  }
  // Each edge is looked at once, from the cell where its move has an even index, and set both
  // ways. Between two cells free at every point the segment lies in their two closed squares
  // (a diagonal one through their common corner): free without a sweep.
  edges_.assign(cells, 0);
  for (int j = 0; j < height_; ++j) {
    for (int i = 0; i < width_; ++i) {
      const int cell = j * width_ + i;
      if (!state[cell]) continue;
      for (int k = 0; k < 8; k += 2) {
        const int ni = i + kMoves[k][0], nj = j + kMoves[k][1];
        if (ni < 0 || nj < 0 || ni >= width_ || nj >= height_) continue;
        const int next = nj * width_ + ni;
        if (!state[next]) continue;
        if ((state[cell] == 2 && state[next] == 2) ||
            map_->sweepFree(centre(cell), centre(next), disc_)) {
          edges_[cell] |= 1u << k;
          edges_[next] |= 1u << (k ^ 1);
        }
      }
    }
  }
}

int GridRegions::labelBlock(int block, std::uint8_t* labels, bool* all_joined_out) const {
  const int b = block_, shift = block_shift_, mask = block_ - 1;
  const int i0 = (block % blocks_x_) << shift, j0 = (block / blocks_x_) << shift;
  const int bw = std::min(b, width_ - i0), bh = std::min(b, height_ - j0);  // in the grid
  std::fill(labels, labels + b * b, kNoLabel);
  // Most blocks are open floor (every cell joined to its 8 neighbours) or wall: one part, none.
  bool all_joined = bw == b && bh == b, none = true;
  for (int lj = 0; lj < bh; ++lj) {
    const std::uint8_t* row = &edges_[static_cast<std::size_t>(j0 + lj) * width_ + i0];
    for (int li = 0; li < bw; ++li) {
      all_joined = all_joined && row[li] == 0xff;
      none = none && row[li] == 0;
    }
  }
  if (all_joined_out) *all_joined_out = all_joined;
  if (none) return 0;
  if (all_joined) {
    std::fill(labels, labels + b * b, 0);
    return 1;
  }
  int parts = 0;
  int stack[16 * 16];
  for (int lj = 0; lj < bh; ++lj) {
    for (int li = 0; li < bw; ++li) {
      const int seed = (lj << shift) | li;
      if (labels[seed] != kNoLabel || edges_[(j0 + lj) * width_ + i0 + li] == 0) continue;
      const auto label = static_cast<std::uint8_t>(parts++);
      int top = 0;
      stack[top++] = seed;
      labels[seed] = label;
      while (top > 0) {
        const int local = stack[--top];
        const int ci = local & mask, cj = local >> shift;
        const std::uint8_t e = edges_[(j0 + cj) * width_ + i0 + ci];
        for (int k = 0; k < 8; ++k) {
          if (!(e & (1u << k))) continue;
          const int ni = ci + kMoves[k][0], nj = cj + kMoves[k][1];
          if (ni < 0 || nj < 0 || ni >= b || nj >= b) continue;  // another block
          const int next = (nj << shift) | ni;
          if (labels[next] != kNoLabel) continue;
          labels[next] = label;
          stack[top++] = next;
        }
      }
    }
  }
  return parts;
}

void GridRegions::buildRegions() {
  const int b = block_, b2 = block_ * block_, shift = block_shift_, mask = block_ - 1;
  const int blocks = blocks_x_ * blocks_y_;
  block_first_region_.assign(static_cast<std::size_t>(blocks) + 1, 0);
  region_point_.reserve(blocks);
  region_block_.reserve(blocks);
  adjacency_start_.reserve(static_cast<std::size_t>(blocks) + 1);
  adjacency_.reserve(static_cast<std::size_t>(blocks) * 8);
  // Labels of three rows of blocks at a time (the row being joined and its neighbours), so the
  // build needs no byte per cell of the map.
  std::vector<std::uint8_t> ring(static_cast<std::size_t>(3) * blocks_x_ * b2, kNoLabel);
  const auto labelsOf = [&](int blk) {
    return &ring[(static_cast<std::size_t>((blk / blocks_x_) % 3) * blocks_x_ + blk % blocks_x_) *
                 b2];
  };
  // Per block of the ring: every cell of it joined to its 8 neighbours (open floor).
  std::vector<char> open(static_cast<std::size_t>(3) * blocks_x_, 0);
  const auto isOpen = [&](int blk) {
    return open[static_cast<std::size_t>((blk / blocks_x_) % 3) * blocks_x_ + blk % blocks_x_];
  };
  // Labels row `by` of blocks and numbers its regions, each placed at the free centre of its
  // cells nearest their mean (the first in row order of those as near).
  const auto labelRow = [&](int by) {
    for (int bx = 0; bx < blocks_x_; ++bx) {
      const int blk = by * blocks_x_ + bx;
      std::uint8_t* labels = labelsOf(blk);
      bool all_joined = false;
      const int parts = labelBlock(blk, labels, &all_joined);
      open[static_cast<std::size_t>(by % 3) * blocks_x_ + bx] = all_joined;
      const int first = static_cast<int>(region_block_.size());
      block_first_region_[blk] = first;
      block_first_region_[blk + 1] = first + parts;
      int sx[256] = {}, sy[256] = {}, count[256] = {};
      for (int local = 0; local < b2; ++local) {
        const std::uint8_t l = labels[local];
        if (l == kNoLabel) continue;
        sx[l] += local & mask;
        sy[l] += local >> shift;
        ++count[l];
      }
      const int i0 = bx << shift, j0 = by << shift;
      for (int part = 0; part < parts; ++part) {
        // Compared in units of 1/count² cells², exactly (integers).
        int best = -1;
        long best_d = 0;
        for (int local = 0; local < b2; ++local) {
          if (labels[local] != part) continue;
          const long dx = static_cast<long>(local & mask) * count[part] - sx[part];
          const long dy = static_cast<long>(local >> shift) * count[part] - sy[part];
          const long d = dx * dx + dy * dy;
          if (best < 0 || d < best_d) best = local, best_d = d;
        }
        region_point_.push_back(centre((j0 + (best >> shift)) * width_ + i0 + (best & mask)));
        region_block_.push_back(blk);
      }
    }
  };
  // The border cells of a block and, for each, the moves that leave the block.
  std::vector<std::pair<int, std::uint8_t>> border;
  for (int local = 0; local < b2; ++local) {
    std::uint8_t leaving = 0;
    for (int k = 0; k < 8; ++k) {
      const int ni = (local & mask) + kMoves[k][0], nj = (local >> shift) + kMoves[k][1];
      if (ni < 0 || nj < 0 || ni >= b || nj >= b) leaving |= 1u << k;
    }
    if (leaving) border.push_back({local, leaving});
  }
  adjacency_start_.assign(1, 0);
  std::vector<std::pair<int, int>> joined;  // (region of this block, region of a neighbour)
  labelRow(0);
  for (int by = 0; by < blocks_y_; ++by) {
    if (by + 1 < blocks_y_) labelRow(by + 1);
    for (int bx = 0; bx < blocks_x_; ++bx) {
      const int blk = by * blocks_x_ + bx;
      const std::uint8_t* labels = labelsOf(blk);
      const int first = block_first_region_[blk];
      if (block_first_region_[blk + 1] == first) continue;  // no region
      joined.clear();
      const int i0 = bx << shift, j0 = by << shift;
      // Open floor beside a block of one region: every edge between them is there, so they are
      // joined without looking at the cells.
      std::uint8_t scan = 0xff;  // the moves whose neighbour block is looked at cell by cell
      if (isOpen(blk)) {
        for (int k = 0; k < 8; ++k) {
          const int nbx = bx + kMoves[k][0], nby = by + kMoves[k][1];
          if (nbx < 0 || nby < 0 || nbx >= blocks_x_ || nby >= blocks_y_) {
            scan &= ~(1u << k);
            continue;
          }
          const int other = nby * blocks_x_ + nbx;
          const int count = block_first_region_[other + 1] - block_first_region_[other];
          if (count == 0) {
            scan &= ~(1u << k);
          } else if (count == 1 && isOpen(other)) {
            joined.push_back({first, block_first_region_[other]});
            scan &= ~(1u << k);
          }
        }
      }
      for (const auto& [local, leaving] : border) {
        if (labels[local] == kNoLabel) continue;
        const int ci = i0 + (local & mask), cj = j0 + (local >> shift);
        const std::uint8_t out = edges_[cj * width_ + ci] & leaving;
        for (int k = 0; k < 8; ++k) {
          if (!(out & (1u << k))) continue;
          const int oi = ci + kMoves[k][0], oj = cj + kMoves[k][1];
          const int other = blockAt(oi, oj);
          // The direction of the neighbour block, as a move index.
          const int dbx = (oi >> shift) - bx, dby = (oj >> shift) - by;
          if (!(scan & (1u << moveIndex(dbx, dby)))) continue;
          const std::uint8_t label = labelsOf(other)[((oj & mask) << shift) | (oi & mask)];
          const std::pair<int, int> pair{first + labels[local], block_first_region_[other] + label};
          if (std::find(joined.begin(), joined.end(), pair) == joined.end()) joined.push_back(pair);
        }
      }
      std::sort(joined.begin(), joined.end());
      std::size_t at = 0;
      for (int region = first; region < block_first_region_[blk + 1]; ++region) {
        for (; at < joined.size() && joined[at].first == region; ++at) {
          adjacency_.push_back(joined[at].second);
        }
        adjacency_start_.push_back(static_cast<int>(adjacency_.size()));
      }
    }
  }
}

bool GridRegions::clearBetween(const Point2& a, const Point2& b) const {
  return forEachBlockAlong(a, b, [this](int block) { return clear_[block] != 0; });
}

int GridRegions::regionOf(int cell) const {
  if (cell < 0 || edges_[cell] == 0) return -1;
  std::uint8_t labels[16 * 16];
  const int blk = blockOf(cell);
  labelBlock(blk, labels);
  const int li = (cell % width_) & (block_ - 1), lj = (cell / width_) & (block_ - 1);
  return block_first_region_[blk] + labels[(lj << block_shift_) | li];
}

std::size_t GridRegions::bytes() const {
  return edges_.size() + clear_.size() + block_first_region_.size() * sizeof(int) +
         region_point_.size() * sizeof(Point2) + region_block_.size() * sizeof(int) +
         (adjacency_start_.size() + adjacency_.size()) * sizeof(int);
}

GridRegionsCache::GridRegionsCache(std::shared_ptr<const geometry::ClearanceMap> map)
    : map_(std::move(map)) {}

std::shared_ptr<const GridRegions> GridRegionsCache::get(double radius) const {
  std::promise<std::shared_ptr<const GridRegions>> building;
  std::shared_future<std::shared_ptr<const GridRegions>> regions;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const Entry& e : entries_) {
      if (e.radius == radius) regions = e.regions;
    }
    if (regions.valid()) {
      // Built, or being built by another thread: wait for it outside the lock.
    } else {
      // This thread builds them, outside the lock; others asking meanwhile wait on the future.
      if (entries_.size() == kKept) entries_.erase(entries_.begin());
      entries_.push_back({radius, building.get_future().share()});
    }
  }
  if (regions.valid()) return regions.get();
  try {
    auto built = std::make_shared<const GridRegions>(map_, radius);
    building.set_value(built);
    return built;
  } catch (...) {
    // Those waiting get the same exception; the next to ask tries again.
    building.set_exception(std::current_exception());
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                  [&](const Entry& e) { return e.radius == radius; }),
                   entries_.end());
    throw;
  }
}

std::shared_ptr<const GridRegions> GridRegionsCache::ready(double radius) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const Entry& e : entries_) {
    if (e.radius == radius &&
        e.regions.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
      return e.regions.get();
    }
  }
  return nullptr;
}

}  // namespace roomba_rrt::planning
