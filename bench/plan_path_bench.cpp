// plan_path_bench: round trip of the rrt_planner's ~plan_path service (client call -> response),
// compared with the planning time the node reports, over many calls of one lab scenario.
//
//   rosrun roomba_rrt rrt_planner &          # with a master running
//   rosrun roomba_rrt plan_path_bench [--calls 1000] [--warmup 100] [--scenario a]
//                                     [--service /rrt_planner/plan_path] [--no-markers] [--json]
//
// By default the bench subscribes to ~tree, so every plan's markers are serialised and sent as
// they would be to rviz. It measures two kinds of client: a persistent connection (one TCP
// connection for all calls, what a planning loop would use) and a fresh connection per call
// (what `rosservice call` or ros::service::call does). Prints p50/p99 of the round trip, of the
// planning time and of their difference (the service's overhead).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include <roomba_rrt/PlanPath.h>
#include "arguments.h"

namespace {

struct Options {
  int calls = 1000;
  int warmup = 100;
  std::string scenario = "a";
  std::string service = "/rrt_planner/plan_path";
  bool markers = true;
  bool json = false;
};

Options parseOptions(int argc, char** argv) {
  Options o;
  roomba_rrt::bench::Arguments args(argc, argv, "plan_path_bench",
                                    "usage: plan_path_bench [--calls N] [--warmup N] "
                                    "[--scenario NAME] [--service NAME] [--no-markers] [--json]\n");
  while (args.next()) {
    if (args.is("--calls")) {
      o.calls = args.count(1);
    } else if (args.is("--warmup")) {
      o.warmup = args.count();
    } else if (args.is("--scenario")) {
      o.scenario = args.value();
    } else if (args.is("--service")) {
      o.service = args.value();
    } else if (args.is("--no-markers")) {
      o.markers = false;
    } else if (args.is("--json")) {
      o.json = true;
    } else {
      args.unknown();
    }
  }
  return o;
}

// Nearest-rank percentile of microsecond samples.
double percentile(std::vector<double> samples, double p) {
  std::sort(samples.begin(), samples.end());
  const auto rank = static_cast<std::size_t>(p / 100.0 * (samples.size() - 1) + 0.5);
  return samples[std::min(rank, samples.size() - 1)];
}

struct Series {
  std::string client;  // "persistent" or "per_call"
  std::vector<double> round_trip_us, planning_us, overhead_us;
  int lost = 0;  // calls whose connection was lost (client.call() false): counted, not timed
};

// Calls the service until `calls` answers after the first `warmup` ones are recorded.
Series measure(const Options& o, bool persistent) {
  Series s;
  s.client = persistent ? "persistent" : "per_call";
  ros::NodeHandle nh;
  ros::ServiceClient client = nh.serviceClient<roomba_rrt::PlanPath>(o.service, persistent);
  roomba_rrt::PlanPath srv;
  srv.request.scenario = o.scenario;
  for (int i = 0; static_cast<int>(s.round_trip_us.size()) < o.calls; ++i) {
    const auto begin = std::chrono::steady_clock::now();
    const bool ok = client.call(srv);
    const auto end = std::chrono::steady_clock::now();
    if (!ok) {
      // roscpp occasionally loses a connection under heavy load; a persistent client must then
      // reconnect (the ROS wiki's advice for persistent clients).
      if (++s.lost > o.calls / 10) throw std::runtime_error("too many lost calls (node gone?)");
      if (!client.isValid()) {
        client = nh.serviceClient<roomba_rrt::PlanPath>(o.service, persistent);
      }
      continue;
    }
    if (!srv.response.success) {
      throw std::runtime_error("call " + std::to_string(i) + " answered: " + srv.response.message);
    }
    if (i < o.warmup) continue;
    const double round_trip = std::chrono::duration<double, std::micro>(end - begin).count();
    const double planning = srv.response.planning_time * 1e6;
    s.round_trip_us.push_back(round_trip);
    s.planning_us.push_back(planning);
    s.overhead_us.push_back(round_trip - planning);
  }
  return s;
}

void printTable(const Options& o, const std::vector<Series>& all) {
  std::printf("~plan_path round trip, scenario %s, %d calls (after %d warm-up), markers %s\n\n",
              o.scenario.c_str(), o.calls, o.warmup, o.markers ? "subscribed" : "not subscribed");
  std::printf(
      "| client | round trip p50 | p99 | planning p50 | p99 | overhead p50 | p99 | lost |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const Series& s : all) {
    std::printf("| %s | %.0f us | %.0f us | %.0f us | %.0f us | %.0f us | %.0f us | %d |\n",
                s.client.c_str(), percentile(s.round_trip_us, 50), percentile(s.round_trip_us, 99),
                percentile(s.planning_us, 50), percentile(s.planning_us, 99),
                percentile(s.overhead_us, 50), percentile(s.overhead_us, 99), s.lost);
  }
}

void printJson(const Options& o, const std::vector<Series>& all) {
  std::printf("[");
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Series& s = all[i];
    std::printf(
        "%s{\"scenario\": \"%s\", \"client\": \"%s\", \"calls\": %d, \"markers\": %s, "
        "\"round_trip_p50_us\": %.1f, \"round_trip_p99_us\": %.1f, \"planning_p50_us\": %.1f, "
        "\"planning_p99_us\": %.1f, \"overhead_p50_us\": %.1f, \"overhead_p99_us\": %.1f, "
        "\"lost_calls\": %d}",
        i == 0 ? "" : ", ", o.scenario.c_str(), s.client.c_str(), o.calls,
        o.markers ? "true" : "false", percentile(s.round_trip_us, 50),
        percentile(s.round_trip_us, 99), percentile(s.planning_us, 50),
        percentile(s.planning_us, 99), percentile(s.overhead_us, 50), percentile(s.overhead_us, 99),
        s.lost);
  }
  std::printf("]\n");
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "plan_path_bench", ros::init_options::AnonymousName);
  const Options o = parseOptions(argc, argv);
  ros::NodeHandle nh;
  if (!ros::service::waitForService(o.service, ros::Duration(30))) {
    std::cerr << "plan_path_bench: " << o.service << " is not offered (is rrt_planner running?)\n";
    return 1;
  }
  // Receive the markers as rviz would, so the node's publishing is part of what is measured.
  ros::Subscriber tree;
  ros::AsyncSpinner spinner(1);
  if (o.markers) {
    const std::string topic = o.service.substr(0, o.service.rfind('/')) + "/tree";
    const boost::function<void(const visualization_msgs::MarkerArrayConstPtr&)> ignore =
        [](const visualization_msgs::MarkerArrayConstPtr&) {};
    tree = nh.subscribe<visualization_msgs::MarkerArray>(topic, 10, ignore);
    spinner.start();
    for (int i = 0; i < 100 && tree.getNumPublishers() == 0; ++i) ros::WallDuration(0.05).sleep();
  }
  std::vector<Series> all;
  try {
    all = {measure(o, /*persistent=*/true), measure(o, /*persistent=*/false)};
  } catch (const std::exception& e) {
    std::cerr << "plan_path_bench: " << e.what() << "\n";
    return 1;
  }
  if (o.json) {
    printJson(o, all);
  } else {
    printTable(o, all);
  }
  return 0;
}
