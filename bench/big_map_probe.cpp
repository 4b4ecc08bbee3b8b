// big_map_probe: rrt_planner serving make_plan on a 10^8-cell map over ROS (issue 47, item 3).
// The probe tiles a shared map T × T in memory (default nav2_bench_100by100_15 × 5 = 10 000 ×
// 10 000 cells, 100 MB of /map), publishes it latched on /map as map_server would, and measures
// what a user pays:
//   publish   building the nav_msgs/OccupancyGrid and publish() (roscpp serialises a latched
//             message once, here);
//   ready     publish() -> the first make_plan across the map that succeeds: the transfer of
//             100 MB over TCPROS, rrt_planner's deserialisation, validation and inflation
//             (distance transform), and the plan;
//   plans     N make_plan requests between free points at least half the map's diagonal apart
//             (drawn on the probe's own inflated copy): round trip p50 / p95 / max, poses;
//   memory    the planner's peak resident set (VmHWM of --planner-pid) per cell.
//
//   big_map_probe [--map FILE.yaml] [--tile 5] [--plans 20] [--planner-pid PID] [--json]
//                                                (rrt_planner running with no world file)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <nav_msgs/GetPlan.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>

#include "far_apart_pairs.h"
#include "map_messages.h"
#include "roomba_rrt/geometry/clearance_map.h"
#include "roomba_rrt/geometry/map_file.h"

namespace {

namespace geometry = roomba_rrt::geometry;
using Clock = std::chrono::steady_clock;

const char* const kService = "/rrt_planner/make_plan";
constexpr double kRadius = 0.17;  // m: rrt_planner's default robot

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// `map` repeated `tiles` times along x and along y.
geometry::OccupancyGrid tiled(const geometry::OccupancyGrid& map, int tiles) {
  geometry::OccupancyGrid out = map;
  out.width = map.width * tiles;
  out.height = map.height * tiles;
  out.cells.resize(static_cast<std::size_t>(out.width) * out.height);
  for (int j = 0; j < out.height; ++j) {
    const std::int8_t* row =
        map.cells.data() + static_cast<std::size_t>(j % map.height) * map.width;
    std::int8_t* to = out.cells.data() + static_cast<std::size_t>(j) * out.width;
    for (int t = 0; t < tiles; ++t) std::copy(row, row + map.width, to + t * map.width);
  }
  return out;
}

/// The peak resident set of process `pid` in bytes (VmHWM), 0 when unknown.
double peakRssBytes(int pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kib = 0;
      status >> kib;
      return kib * 1024;
    }
    status.ignore(1 << 12, '\n');
  }
  return 0;
}

geometry_msgs::PoseStamped pose(const geometry::Point2& p) {
  geometry_msgs::PoseStamped s;
  s.header.frame_id = "map";
  s.pose.position.x = p.x;
  s.pose.position.y = p.y;
  s.pose.orientation.w = 1;
  return s;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))];
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "big_map_probe", ros::init_options::AnonymousName);
  std::string map_file = ROOMBA_RRT_SHARED_MAPS "/nav2_bench_100by100_15.yaml";
  int tiles = 5, plans = 20, planner_pid = 0;
  bool json = false;
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (std::strcmp(argv[i], "--map") == 0 && has_value) {
      map_file = argv[++i];
    } else if (std::strcmp(argv[i], "--tile") == 0 && has_value) {
      tiles = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--plans") == 0 && has_value) {
      plans = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--planner-pid") == 0 && has_value) {
      planner_pid = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--json") == 0) {
      json = true;
    } else {
      const bool help = std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0;
      std::fprintf(help ? stdout : stderr,
                   "usage: big_map_probe [--map FILE.yaml] [--tile 5] [--plans 20] "
                   "[--planner-pid PID] [--json]\n");
      return help ? 0 : 2;
    }
  }
  ros::NodeHandle nh;
  if (!ros::service::waitForService(kService, ros::Duration(30))) {
    std::fprintf(stderr, "big_map_probe: %s is not available\n", kService);
    return 1;
  }
  auto grid = std::make_shared<const geometry::OccupancyGrid>(
      tiled(geometry::loadMap(map_file).grid, tiles));
  const double cells = static_cast<double>(grid->width) * grid->height;

  // The start and goal of every request, drawn on the probe's own inflated copy.
  const geometry::ClearanceMap clearance(grid);
  const auto pairs = roomba_rrt::bench::farApartPairs(clearance, kRadius, plans + 1);
  std::vector<nav_msgs::GetPlan> requests(plans + 1);
  for (std::size_t i = 0; i < requests.size(); ++i) {
    requests[i].request.start = pose(pairs[i].first);
    requests[i].request.goal = pose(pairs[i].second);
  }

  ros::Publisher publisher = nh.advertise<nav_msgs::OccupancyGrid>("/map", 1, /*latch=*/true);
  ros::ServiceClient client = nh.serviceClient<nav_msgs::GetPlan>(kService, /*persistent=*/true);
  const Clock::time_point t0 = Clock::now();
  publisher.publish(roomba_rrt::nodes::toMapMessage(*grid, ros::Time::now()));
  const double publish_s = secondsSince(t0);

  // Ready: the first request succeeds once the planner has this map (it waits up to 5 s for a
  // first map and answers "no map yet" after; ask again until 120 s have passed).
  bool ready = false;
  while (!ready && secondsSince(t0) < 120 && ros::ok()) {
    nav_msgs::GetPlan first = requests[0];
    ready = client.call(first) && !first.response.plan.poses.empty();
    if (!ready) ros::Duration(0.05).sleep();
  }
  const double ready_s = secondsSince(t0);
  if (!ready) {
    std::fprintf(stderr, "big_map_probe: no plan on the %gx%g map within 120 s\n",
                 static_cast<double>(grid->width), static_cast<double>(grid->height));
    return 1;
  }

  std::vector<double> ms;
  int solved = 0;
  double poses = 0;
  for (int i = 1; i <= plans && ros::ok(); ++i) {
    const Clock::time_point start = Clock::now();
    const bool ok = client.call(requests[i]) && !requests[i].response.plan.poses.empty();
    ms.push_back(secondsSince(start) * 1e3);
    if (ok) {
      ++solved;
      poses += requests[i].response.plan.poses.size();
    }
  }
  const double planner_peak = planner_pid > 0 ? peakRssBytes(planner_pid) : 0;
  const double p50 = percentile(ms, 0.5), p95 = percentile(ms, 0.95);
  const double max = ms.empty() ? 0 : *std::max_element(ms.begin(), ms.end());
  const std::string name = map_file.substr(map_file.find_last_of('/') + 1);
  if (json) {
    std::printf(
        "{\"map\": \"%s\", \"tiles\": %d, \"width\": %d, \"height\": %d, \"message_mb\": %.1f, "
        "\"publish_ms\": %.1f, \"ready_ms\": %.1f, \"plans\": %d, \"solved\": %d, "
        "\"p50_ms\": %.2f, \"p95_ms\": %.2f, \"max_ms\": %.2f, \"mean_poses\": %.0f, "
        "\"planner_peak_rss_mb\": %.1f, \"planner_peak_bytes_per_cell\": %.2f}\n",
        name.c_str(), tiles, grid->width, grid->height, cells / 1e6, publish_s * 1e3, ready_s * 1e3,
        plans, solved, p50, p95, max, solved ? poses / solved : 0, planner_peak / (1 << 20),
        planner_peak / cells);
  } else {
    std::printf(
        "%s tiled %dx%d: %d x %d cells (/map %.1f MB): publish %.0f ms, first plan %.0f ms after "
        "publishing; make_plan across the map: %d/%d solved, round trip p50 %.1f ms, p95 %.1f "
        "ms, max %.1f ms, %.0f poses; rrt_planner peak RSS %.0f MB (%.2f B/cell)\n",
        name.c_str(), tiles, tiles, grid->width, grid->height, cells / 1e6, publish_s * 1e3,
        ready_s * 1e3, solved, plans, p50, p95, max, solved ? poses / solved : 0,
        planner_peak / (1 << 20), planner_peak / cells);
  }
  return 0;
}
