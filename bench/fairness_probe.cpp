// fairness_probe: how long an ordinary plan_path request waits while other clients hammer the
// planner with long plans (issue 20). Eight hostile threads, each its own connection, ask without
// pause for unreachable plans at the 5 000 000-iteration cap (each would run for the node's whole
// time budget); meanwhile one client sends N ordinary requests (scenario a, the node's defaults),
// one every 50 ms, and times each round trip. Prints the latencies' p50 / p99 / max, the ordinary
// requests that failed, and what the hostile clients heard.
//
//   fairness_probe [--requests 100] [--json]      (rrt_planner running; its ~threads as it likes)
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include <roomba_rrt/PlanPath.h>
#include <ros/ros.h>

namespace {

const char* const kService = "/rrt_planner/plan_path";

roomba_rrt::PlanPath::Request unreachable() {
  roomba_rrt::PlanPath::Request r;
  r.start.x = r.start.y = 1;
  r.goal.x = r.goal.y = 9.9;
  roomba_rrt::CircleObstacle wall;
  wall.center.x = wall.center.y = 9;
  wall.radius = 1.2;  // the goal is inside it: no plan reaches it
  r.obstacles.push_back(wall);
  r.max_iterations = 5'000'000;
  return r;
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * (v.size() - 1) + 0.5))];
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "fairness_probe", ros::init_options::AnonymousName);
  int requests = 100;
  bool json = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--requests") == 0 && i + 1 < argc) {
      requests = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--json") == 0) {
      json = true;
    } else {
      const bool help = std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0;
      std::fprintf(help ? stdout : stderr, "usage: fairness_probe [--requests 100] [--json]\n");
      return help ? 0 : 2;
    }
  }
  ros::NodeHandle nh;
  if (!ros::service::waitForService(kService, ros::Duration(30))) {
    std::fprintf(stderr, "fairness_probe: %s is not available\n", kService);
    return 1;
  }
  std::atomic<bool> stop{false};
  std::atomic<int> busy{0}, preempted{0}, other{0};
  std::vector<std::thread> hostile;
  for (int i = 0; i < 8; ++i) {
    hostile.emplace_back([&] {
      while (!stop) {
        roomba_rrt::PlanPath srv;
        srv.request = unreachable();
        if (!ros::service::call(kService, srv)) continue;
        const std::string& m = srv.response.message;
        (m.rfind("busy", 0) == 0 ? busy : m.rfind("preempted", 0) == 0 ? preempted : other)++;
      }
    });
  }
  ros::WallDuration(0.5).sleep();  // every thread is taken by now
  std::vector<double> latencies_ms;
  int failed = 0;
  for (int i = 0; i < requests; ++i) {
    roomba_rrt::PlanPath srv;
    srv.request.scenario = "a";
    const ros::WallTime t0 = ros::WallTime::now();
    const bool called = ros::service::call(kService, srv);
    latencies_ms.push_back((ros::WallTime::now() - t0).toSec() * 1000);
    if (!called || !srv.response.success) ++failed;
    ros::WallDuration(0.05).sleep();
  }
  stop = true;
  for (auto& t : hostile) t.join();
  const double p50 = percentile(latencies_ms, 0.5), p99 = percentile(latencies_ms, 0.99);
  const double max = *std::max_element(latencies_ms.begin(), latencies_ms.end());
  if (json) {
    std::printf(
        "{\"requests\": %d, \"failed\": %d, \"p50_ms\": %.2f, \"p99_ms\": %.2f, \"max_ms\": %.2f, "
        "\"hostile_busy\": %d, \"hostile_preempted\": %d, \"hostile_other\": %d}\n",
        requests, failed, p50, p99, max, busy.load(), preempted.load(), other.load());
  } else {
    std::printf(
        "%d ordinary requests beside 8 hostile clients: %d failed, p50 %.1f ms, p99 %.1f ms, "
        "max %.1f ms; hostile answers: %d busy, %d preempted, %d other\n",
        requests, failed, p50, p99, max, busy.load(), preempted.load(), other.load());
  }
  return 0;
}
