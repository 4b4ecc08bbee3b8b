#include "roomba_rrt/planning/problem.h"

#include <utility>

#include "roomba_rrt/planning/grid_regions.h"

namespace roomba_rrt::planning {

Problem mapProblem(std::shared_ptr<const geometry::OccupancyGrid> map, bool allow_unknown) {
  Problem p;
  const geometry::Rectangle e = map->extent();
  p.bounds = {e.min_x, e.max_x, e.min_y, e.max_y};
  p.map = std::make_shared<const geometry::ClearanceMap>(std::move(map), allow_unknown);
  p.regions = std::make_shared<const GridRegionsCache>(p.map);
  return p;
}

}  // namespace roomba_rrt::planning
