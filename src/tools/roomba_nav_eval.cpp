// roomba_nav_eval: how well the navigation tree drives to goals, without ROS.
//
// The simulator, a navigation tree (config/roomba_nav_tree.xml) and the in-process planner in one
// loop, deterministic by seed: N random reachable goal poses one after another. Prints reached %,
// bumper presses, time per goal, driven length ÷ the shortest length for the robot's disc, and
// the planning time. See doc/navigation.md.
#include <unistd.h>

#include <cairo.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include "drawing.h"
#include "nav_eval_run.h"
#include "roomba_rrt/bt/tree_factory.h"
#include "tool_arguments.h"

namespace {

const char* const kUsage =
    "usage: roomba_nav_eval [--goals 20] [--seed 1] [--world FILE] [--pose X,Y[,THETA]]\n"
    "                       [--tree FILE] [--json] [--unknown [--known-map FILE]]\n"
    "                       [--csv FILE] [--png FILE] [--timeout 120]\n"
    "  --goals    random reachable goals, one after another (default 20)\n"
    "  --seed     seed of the goals and the planner (default 1)\n"
    "  --world    furnished (the default), empty (the lab's room), apartment (a map), or a\n"
    "             world or map_server YAML\n"
    "  --pose     where the robot starts (m, rad); default the world's (a map's (0, 0))\n"
    "  --tree     navigation tree (default config/roomba_nav_tree.xml)\n"
    "  --json     print one JSON object: goals, reached_pct, bumps, mean_time_s,\n"
    "             mean_length_ratio, planning_ms_p50 (0 with --unknown: not timed)\n"
    "  --csv      per goal: goal,start_x,start_y,goal_x,goal_y,goal_theta,reached,bumps,time_s,\n"
    "             driven_m,shortest_m,message\n"
    "  --png      picture: room, traces (green reached, red not), goals as arrows\n"
    "  --timeout  robot seconds per goal before it counts as not reached (default 120)\n"
    "  --unknown  every goal in a home the robot has never seen: it starts a fresh map where\n"
    "             it stands, maps with its lidar (the world's sensors) and plans on that map,\n"
    "             unknown cells as floor until seen, again whenever its path is blocked\n"
    "  --known-map with --unknown: the map the robot is given for every goal (a map_server\n"
    "             YAML or a world file, e.g. config/maps/furnished_walls.yaml: its walls, not\n"
    "             its furniture); its walls stay walls, the lidar finds the rest\n";

/// The room, every run's trace (green: reached, red: not) and each goal as an arrow.
void drawPng(const std::string& file, const roomba_rrt::world::World& world,
             const roomba_rrt::tools::NavEvalReport& report, const std::string& title) {
  const roomba_rrt::tools::RoomCanvas c = roomba_rrt::tools::roomCanvas(world);
  const int width = static_cast<int>(world.room.width * c.scale + 2 * c.margin);
  const int height = static_cast<int>(world.room.height * c.scale + 2 * c.margin + c.header);
  roomba_rrt::tools::PngImage image(width, height);
  cairo_t* cr = image.cr();
  roomba_rrt::tools::drawFloor(cr, world, c);
  roomba_rrt::tools::drawFurnitureAndWalls(cr, world, c);
  cairo_set_line_width(cr, 1.0);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const auto& run : report.runs) {
    if (run.reached) {
      cairo_set_source_rgba(cr, 0.1, 0.55, 0.2, 0.6);
    } else {
      cairo_set_source_rgba(cr, 0.85, 0.1, 0.1, 0.9);
    }
    cairo_move_to(cr, c.px(run.start.x), c.py(run.start.y));
    for (const auto& p : run.trace) cairo_line_to(cr, c.px(p.x), c.py(p.y));
    cairo_stroke(cr);
    // The goal: a short arrow along its heading.
    const double gx = c.px(run.goal.x), gy = c.py(run.goal.y);
    const double ex = gx + 12 * std::cos(run.goal.theta), ey = gy - 12 * std::sin(run.goal.theta);
    cairo_set_source_rgb(cr, 0.1, 0.2, 0.7);
    cairo_move_to(cr, gx, gy);
    cairo_line_to(cr, ex, ey);
    cairo_stroke(cr);
    cairo_arc(cr, gx, gy, 2.5, 0, 2 * M_PI);
    cairo_fill(cr);
  }
  roomba_rrt::tools::drawTitle(cr, title, c.margin, 24, 13);
  image.write(file);
}

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "roomba_nav_eval: " << problem << "\n" << kUsage;
  std::exit(2);
}

long integer(const std::string& flag, const char* text, long lo, long hi) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (!*text || *end || v < lo || v > hi) {
    usage(flag + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
          "], got '" + text + "'");
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace roomba_rrt::tools;
  NavEvalOptions options;
  std::string world_file = ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml";
  std::string pose;
  std::string tree_file = ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml";
  std::string csv, png;
  bool json = false;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const auto value = [&]() -> const char* {
      if (i + 1 >= argc) usage(flag + " needs a value");
      return argv[++i];
    };
    if (flag == "--goals") {
      options.goals = static_cast<int>(integer(flag, value(), 1, 100000));
    } else if (flag == "--seed") {
      options.seed = static_cast<std::uint32_t>(integer(flag, value(), 0, 4294967295L));
    } else if (flag == "--timeout") {
      options.timeout_s = static_cast<double>(integer(flag, value(), 1, 86400));
    } else if (flag == "--world") {
      world_file = roomba_rrt::tools::worldFile(value());
    } else if (flag == "--pose") {
      pose = value();
    } else if (flag == "--tree") {
      tree_file = value();
    } else if (flag == "--csv") {
      csv = value();
    } else if (flag == "--png") {
      png = value();
    } else if (flag == "--json") {
      json = true;
    } else if (flag == "--unknown") {
      options.unknown = true;
    } else if (flag == "--known-map") {
      options.known_map = value();
    } else if (flag == "-h" || flag == "--help") {
      std::cout << kUsage;
      return 0;
    } else {
      usage("unknown argument '" + flag + "'");
    }
  }
  if (!options.known_map.empty() && !options.unknown) {
    usage("--known-map is the map a robot that does not know the world is given: add --unknown");
  }
  try {
    const roomba_rrt::world::World world = roomba_rrt::tools::loadToolWorld(world_file, pose);
    const bool bar = isatty(STDERR_FILENO);
    const NavEvalReport report =
        evaluateNavigation(world, tree_file, options, [bar](int done, int total) {
          if (!bar) return;
          const int width = 40, filled = width * done / total;
          std::fprintf(stderr, "\r[%s%s] %d/%d goals", std::string(filled, '#').c_str(),
                       std::string(width - filled, ' ').c_str(), done, total);
          if (done == total) std::fprintf(stderr, "\n");
        });
    if (!csv.empty()) {
      std::ofstream out(csv);
      out << "goal,start_x,start_y,goal_x,goal_y,goal_theta,reached,bumps,time_s,driven_m,"
             "shortest_m,message\n";
      for (std::size_t n = 0; n < report.runs.size(); ++n) {
        const GoalRun& r = report.runs[n];
        out << n << ',' << r.start.x << ',' << r.start.y << ',' << r.goal.x << ',' << r.goal.y
            << ',' << r.goal.theta << ',' << r.reached << ',' << r.bumps << ',' << r.time_s << ','
            << r.driven_m << ',' << r.shortest_m << ",\"" << r.message << "\"\n";
      }
      if (!out) throw std::runtime_error("cannot write " + csv);
    }
    if (!png.empty()) {
      char title[200];
      std::snprintf(title, sizeof title,
                    "%zu goals, seed %u: %.1f %% reached, %d bumper presses, length ratio %.3f",
                    report.runs.size(), options.seed, report.reached_pct, report.bumps,
                    report.mean_length_ratio);
      drawPng(png, world, report, title);
    }
    if (json) {
      std::cout << toJson(report) << "\n";
    } else {
      std::printf(
          "goals %zu  reached %.1f %%  bumper presses %d  mean time %.1f s  "
          "mean length ratio %.3f  planning p50 %.2f ms\n",
          report.runs.size(), report.reached_pct, report.bumps, report.mean_time_s,
          report.mean_length_ratio, report.planning_ms_p50);
      std::printf(
          "shortest length: 16-neighbour grid (2 cm) pulled taut with exact disc tests "
          "(never below the true shortest)\n");
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "roomba_nav_eval: " << e.what() << "\n";
    return 1;
  }
}
