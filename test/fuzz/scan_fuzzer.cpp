// libFuzzer harness: scans as they arrive on /scan, with the pose tf gave them and the bumper,
// into the mapper's core (mapping/occupancy_mapper.h), as roomba_mapper hands them over. A
// FuzzedDataProvider draws a few scans: every LaserScan field (often NaN, ±inf, denormals, 3e38,
// angles of 1e300), ranges of every kind, a pose near or very far, a bump. Checks what a map's
// user relies on: a scan is used or refused with a field's name, a refused scan changes nothing,
// the map never exceeds max_cells and holds only −1, 0 and 100.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "request_fuzzing.h"
#include "roomba_rrt/mapping/occupancy_mapper.h"

namespace {

namespace fuzz = roomba_rrt::fuzz;
namespace mapping = roomba_rrt::mapping;
using roomba_rrt::geometry::OccupancyGrid;

void require(bool ok, const char* what) { fuzz::require(ok, "scan_fuzzer", what); }

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kSpecial[] = {
    0.0,    -0.0,   1e-300, 4.9e-324, 0.12, 3.5,   0.0174533,
    6.2657, 3.4e38, 1e300,  -1e300,   kInf, -kInf, std::numeric_limits<double>::quiet_NaN()};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  mapping::MapperOptions options;
  options.resolution = in.ConsumeBool() ? 0.05 : in.ConsumeFloatingPointInRange(0.05, 1.0);
  options.max_range = in.ConsumeFloatingPointInRange(0.5, 20.0);  // rays of at most 400 cells
  options.max_cells = 1 << 18;  // small enough to grow often, and quick
  options.xmin = options.ymin = -5;
  options.xmax = options.ymax = 5;
  mapping::OccupancyMapper mapper(options);
  for (int n = in.ConsumeIntegralInRange(1, 4); n > 0 && in.remaining_bytes() > 0; --n) {
    std::vector<float> ranges(in.ConsumeIntegralInRange<std::size_t>(0, 400));
    for (float& r : ranges) r = static_cast<float>(fuzz::pickDouble(in, kSpecial, 0, 4));
    mapping::ScanView scan;
    scan.angle_min = fuzz::pickDouble(in, kSpecial, -4, 4);
    scan.angle_increment = fuzz::pickDouble(in, kSpecial, -0.1, 0.1);
    scan.angle_max = in.ConsumeBool() ? scan.angle_min + (static_cast<double>(ranges.size()) - 1) *
                                                             scan.angle_increment
                                      : fuzz::pickDouble(in, kSpecial, -4, 4);
    scan.range_min = fuzz::pickDouble(in, kSpecial, 0, 1);
    scan.range_max = fuzz::pickDouble(in, kSpecial, 0, 10);
    scan.ranges = ranges.data();
    scan.count = ranges.size();
    const roomba_rrt::robot::Pose2D pose{fuzz::pickDouble(in, kSpecial, -20, 20),
                                         fuzz::pickDouble(in, kSpecial, -20, 20),
                                         fuzz::pickDouble(in, kSpecial, -4, 4)};
    const OccupancyGrid before = mapper.grid();
    const std::string why = mapper.addScan(pose, scan);
    if (!why.empty()) {
      require(why.find(':') != std::string::npos, "a refusal names a field");
      const OccupancyGrid after = mapper.grid();
      require(after.cells == before.cells && after.width == before.width,
              "a refused scan changes nothing");
    }
    if (in.ConsumeBool()) {
      mapper.addBump(pose, in.ConsumeFloatingPointInRange(0.0, 1.0),
                     {true, in.ConsumeBool(), in.ConsumeBool()});
    }
  }
  const OccupancyGrid map = mapper.grid();
  require(static_cast<long long>(map.width) * map.height <= options.max_cells, "within max_cells");
  require(map.cells.size() == static_cast<std::size_t>(map.width) * map.height, "w × h cells");
  for (const std::int8_t v : map.cells) {
    require(
        v == OccupancyGrid::kUnknown || v == OccupancyGrid::kFree || v == OccupancyGrid::kOccupied,
        "only -1, 0 and 100");
  }
  return 0;
}
