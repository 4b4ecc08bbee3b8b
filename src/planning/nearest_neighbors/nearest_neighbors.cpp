#include "roomba_rrt/planning/nearest_neighbors/nearest_neighbors.h"

#include "roomba_rrt/planning/nearest_neighbors/brute_force_nearest_neighbors.h"
#include "roomba_rrt/planning/nearest_neighbors/grid_nearest_neighbors.h"

namespace roomba_rrt::planning {

std::unique_ptr<NearestNeighbors> makeNearestNeighbors(NearestSearch kind) {
  switch (kind) {
    case NearestSearch::kIndex:
      return std::make_unique<GridNearestNeighbors>();
    case NearestSearch::kBruteForce:
      return std::make_unique<BruteForceNearestNeighbors>();
  }
  return std::make_unique<BruteForceNearestNeighbors>();
}

}  // namespace roomba_rrt::planning
