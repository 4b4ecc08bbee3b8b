// roomba_coverage's pictures: one robot's run in the room (--png) and the union coverage of
// several robots over time (--plot).
#pragma once

#include <string>
#include <vector>

#include "coverage_run.h"
#include "coverage_statistics.h"
#include "roomba_rrt/sim/simulator.h"

namespace roomba_rrt::tools {

/// The room, its furniture, the floor the run cleaned and its path coloured by state (Rotate, in
/// place, as dots), the start, a title and a legend. `simulator` holds the run's end state.
void drawRunPicture(const std::string& file, const sim::Simulator& simulator, const Run& run,
                    const std::string& title);

/// Union coverage over time (the vertical `axis`), one curve per robot count (or labelled one): the
/// mean over the seeds, a band of ± one standard deviation, and the checkpoints' values in the
/// legend.
void drawCoveragePlot(const std::string& file, const std::vector<FleetStatistics>& fleets,
                      double duration, const std::string& title,
                      const std::string& axis = "floor cleaned by the robots together");

}  // namespace roomba_rrt::tools
