#include "coverage_arguments.h"

#include <cmath>
#include <stdexcept>

#include "roomba_rrt/sim/multi_robot_simulator.h"
#include "tool_arguments.h"

namespace roomba_rrt::tools {
namespace {

const char* const kUsage =
    "usage: roomba_coverage --behavior fsm|bt|coverage [--duration 600] [--seed 1] [--seeds N]\n"
    "                       [--world FILE] [--pose X,Y[,THETA]] [--crop X0,Y0,X1,Y1]\n"
    "                       [--config FILE] [--tree FILE] [--lag N] [--predict N]\n"
    "                       [--csv traj.csv] [--png map.png]\n"
    "                       [--unknown [--known-map FILE] [--sensors S]]\n"
    "                       [--robots N[,N...]] [--plot coverage.png]\n"
    "       roomba_coverage --compare [--duration 600] [--seeds N] [--world FILE] [--pose ...]\n"
    "                       [--crop ...] [--plot coverage.png]\n"
    "                       [--unknown [--known-map FILE] [--sensors S]]\n"
    "  --behavior  fsm (state machine), bt (behavior tree) or coverage (the cleaning tree,\n"
    "              config/roomba_coverage_tree.xml: planned rows; reports the coverage of the\n"
    "              reachable floor, the time to 90 / 95 / 99 % of it and the bumps)\n"
    "  --compare   fsm, bt and coverage side by side, on the reachable floor; --plot draws them\n"
    "  --unknown   with coverage: the robot does not know the world; it maps it with its lidar\n"
    "              (the world's sensors), explores to the nearest frontier until none is left,\n"
    "              then cleans the map it built; with --compare a fourth column, unknown.\n"
    "              A robot whose sensors reach less than 1 m (the IR light bumper) or that has\n"
    "              none cleans by touch: boustrophedon rows into the unknown, cut short by the\n"
    "              IR light bumper and the bumper, backtracking over the floor it swept\n"
    "  --known-map with --unknown: the map the robot is given (a map_server YAML or a world\n"
    "              file, e.g. config/maps/apartment_walls.yaml: its walls, not its\n"
    "              furniture): it plans its rows on it at once and plans the rest again when\n"
    "              its lidar shows them blocked; the column is known-map\n"
    "  --sensors   with --unknown, the robot's range sensors instead of the world file's:\n"
    "              lds (a 360° lidar), ir_bumper (the Roomba's IR light bumper, 0.15 m),\n"
    "              lds,ir_bumper, or none (the bumper alone)\n"
    "  --duration  simulated seconds per run (default 600)\n"
    "  --seed      seed of the rotation angle (default 1); --seeds N runs seeds seed..seed+N-1\n"
    "  --world     empty (the lab's room, the default), furnished, apartment (a map), or a\n"
    "              world or map_server YAML\n"
    "  --pose      where the robot starts (m, rad); default the world's (a map's (0, 0))\n"
    "  --crop      keep only this region of the world (m): its edges become walls (a large\n"
    "              map cut to a few rooms); rounded in to whole cells (the header says\n"
    "              what was kept)\n"
    "  --config    behaviour YAML (default config/roomba_behavior.yaml)\n"
    "  --tree      behavior-tree XML for --behavior bt (default: the lab's tree) or coverage\n"
    "              (default: config/roomba_coverage_tree.xml)\n"
    "  --lag       the behaviour sees the pose and bumper N steps late (default 0; over ROS\n"
    "              it is 1: roomba_sim steps once more before a command arrives)\n"
    "  --predict   steps the cleaning tree drives the pose it sees forward along its own\n"
    "              commands (roomba_bt's ~pose_latency; default: --lag's)\n"
    "  --csv       trajectory of the first seed: t,x,y,theta,v,w,state,bumper\n"
    "  --png       picture of a typical run: with --seeds N, the seed whose final coverage is\n"
    "              closest to the mean of the N (its title says which)\n"
    "  --robots    N robots spread evenly over the room (replacing the world's), each running the\n"
    "              behaviour with its own seed (robot k of seed s: s + 1000 k); the coverage is\n"
    "              their union's. A list (1,2,4) runs each count. A world that names robots runs\n"
    "              those without --robots. --csv and --png need one unnamed robot.\n"
    "  --plot      union coverage over time, mean ± std over the seeds, one curve per count\n"
    "              (needs --robots: with one robot, --png and --csv draw the run); with\n"
    "              coverage or --compare, the reachable floor's coverage, one curve per behaviour\n"
    "A progress bar counts the runs on stderr when it is a terminal.\n";

std::vector<int> parseCounts(const std::string& flag, const std::string& text) {
  std::vector<int> counts;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string item = text.substr(begin, end - begin);
    double n = 0;
    try {
      n = parseDoubleFlag(flag, item);
    } catch (const std::invalid_argument&) {
      n = -1;
    }
    if (n < 1 || n > static_cast<double>(world::kMaxRobots) || n != std::floor(n)) {
      throw std::invalid_argument(flag + " needs robot counts in [1, " +
                                  std::to_string(world::kMaxRobots) + "] like 4 or 1,2,4, got '" +
                                  text + "'");
    }
    counts.push_back(static_cast<int>(n));
    begin = end + 1;
  }
  return counts;
}

}  // namespace

const char* coverageUsage() { return kUsage; }

CoverageArguments parseCoverageArguments(int argc, const char* const* argv) {
  CoverageArguments o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "-h" || flag == "--help") {
      o.help = true;
      return o;
    }
    if (flag == "--compare" || flag == "--unknown") {
      (flag == "--compare" ? o.compare : o.unknown) = true;
      continue;
    }
    if (i + 1 >= argc) throw std::invalid_argument(flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--behavior") {
      o.behavior = value;
    } else if (flag == "--duration") {
      o.duration = parseDoubleFlag(flag, value);
    } else if (flag == "--seed") {
      const double seed = parseDoubleFlag(flag, value);
      if (seed < 0 || seed > 4294967295.0 || seed != std::floor(seed)) {
        throw std::invalid_argument("--seed needs an integer in [0, 2^32), got " + value);
      }
      o.seed = static_cast<unsigned>(seed);
    } else if (flag == "--seeds") {
      const double seeds = parseDoubleFlag(flag, value);
      if (seeds < 1 || seeds != std::floor(seeds)) {
        throw std::invalid_argument("--seeds needs a positive integer, got " + value);
      }
      o.seeds = static_cast<int>(seeds);
    } else if (flag == "--world") {
      o.world = worldFile(value);
    } else if (flag == "--pose") {
      o.pose = value;
    } else if (flag == "--crop") {
      o.crop = value;
    } else if (flag == "--config") {
      o.config = value;
    } else if (flag == "--tree") {
      o.tree = value;
    } else if (flag == "--csv") {
      o.csv = value;
    } else if (flag == "--png") {
      o.png = value;
    } else if (flag == "--robots") {
      o.robots = parseCounts(flag, value);
    } else if (flag == "--lag" || flag == "--predict") {
      const double ticks = parseDoubleFlag(flag, value);
      if (ticks < 0 || ticks > 60 || ticks != std::floor(ticks)) {
        throw std::invalid_argument(flag + " needs a whole number of steps in [0, 60], got " +
                                    value);
      }
      (flag == "--lag" ? o.lag : o.predict) = static_cast<int>(ticks);
    } else if (flag == "--plot") {
      o.plot = value;
    } else if (flag == "--known-map") {
      o.known_map = value;
    } else if (flag == "--sensors") {
      o.sensors.emplace();
      for (std::size_t begin = 0; value != "none" && begin <= value.size();) {
        const std::size_t end = std::min(value.find(',', begin), value.size());
        const std::string name = value.substr(begin, end - begin);
        if (name != "lds" && name != "ir_bumper") {
          throw std::invalid_argument(
              "--sensors needs lds, ir_bumper, both (lds,ir_bumper) or "
              "none, got '" +
              value + "'");
        }
        o.sensors->push_back(name);
        begin = end + 1;
      }
    } else {
      throw std::invalid_argument("unknown option " + flag);
    }
  }
  if (o.compare) {
    if (!o.behavior.empty() || !o.tree.empty() || !o.csv.empty() || !o.png.empty() ||
        !o.robots.empty()) {
      throw std::invalid_argument(
          "--compare runs fsm, bt and coverage: no --behavior, --tree, --csv, --png or --robots");
    }
  } else if (o.behavior != "fsm" && o.behavior != "bt" && o.behavior != "coverage") {
    throw std::invalid_argument("--behavior must be fsm, bt or coverage, got '" + o.behavior + "'");
  }
  if (!(o.duration > 0)) throw std::invalid_argument("--duration must be > 0");
  if (o.unknown && !o.compare && o.behavior != "coverage") {
    throw std::invalid_argument(
        "--unknown is the cleaning tree's: --behavior coverage or --compare");
  }
  if (!o.known_map.empty() && !o.unknown) {
    throw std::invalid_argument(
        "--known-map is the map a robot that does not know the world is given: add --unknown");
  }
  if (o.sensors && !o.unknown) {
    throw std::invalid_argument("--sensors is what --unknown cleans with: add --unknown");
  }
  if (o.unknown && !o.tree.empty()) {
    throw std::invalid_argument(
        "--unknown explores and cleans with the package's trees: no --tree");
  }
  if (!o.tree.empty() && o.behavior != "bt" && o.behavior != "coverage") {
    throw std::invalid_argument("--tree needs --behavior bt or coverage");
  }
  if (o.predict >= 0 && o.behavior != "coverage" && !o.compare) {
    throw std::invalid_argument("--predict is the cleaning tree's: --behavior coverage");
  }
  if (o.behavior == "coverage" && !o.robots.empty()) {
    throw std::invalid_argument("--robots runs the lab's behaviours: fsm or bt");
  }
  if (!o.robots.empty() && (!o.csv.empty() || !o.png.empty())) {
    throw std::invalid_argument("--csv and --png draw one robot; with --robots use --plot");
  }
  return o;
}

}  // namespace roomba_rrt::tools
