// roomba_coverage: how much of the floor the lab's Roomba cleans, without ROS.
//
// Runs the simulation core with the FSM or the BT in one process, in the lab's step order
// (contact → bumper → behaviour → move), deterministic by seed. Prints the coverage at 60, 300
// and 600 s (mean ± standard deviation over seeds with --seeds), writes the first seed's
// trajectory as CSV and draws a typical run as a PNG (room, furniture, cleaned floor, path
// coloured by state): the seed whose final coverage is closest to the mean. Shows a progress bar
// on a terminal. See README.md, "Behaviours".
#include <cairo.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "progress_bar.h"
#include "room_drawing.h"
#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/behavior/roomba_fsm.h"
#include "roomba_rrt/sim/simulator.h"
#include "roomba_rrt/sim/world.h"

namespace {

using roomba_rrt::behavior::RoombaBehavior;
using roomba_rrt::behavior::RoombaParams;
using roomba_rrt::behavior::RoombaState;
namespace sim = roomba_rrt::sim;

constexpr double kPi = 3.14159265358979323846;
const double kCheckpoints[] = {60.0, 300.0, 600.0};

const char* const kUsage =
    "usage: roomba_coverage --behavior fsm|bt [--duration 600] [--seed 1] [--seeds N]\n"
    "                       [--world FILE] [--config FILE] [--tree FILE]\n"
    "                       [--csv traj.csv] [--png map.png]\n"
    "  --behavior  fsm (state machine) or bt (behavior tree)\n"
    "  --duration  simulated seconds per run (default 600)\n"
    "  --seed      seed of the rotation angle (default 1); --seeds N runs seeds seed..seed+N-1\n"
    "  --world     world YAML (default config/roomba_world.yaml)\n"
    "  --config    behaviour YAML (default config/roomba_behavior.yaml)\n"
    "  --tree      behavior-tree XML for --behavior bt (default: the lab's tree)\n"
    "  --csv       trajectory of the first seed: t,x,y,theta,v,w,state,bumper\n"
    "  --png       picture of a typical run: with --seeds N, the seed whose final coverage is\n"
    "              closest to the mean of the N (its title says which)\n"
    "A progress bar counts the runs on stderr when it is a terminal.\n";

struct Options {
  std::string behavior;
  double duration = 600;
  unsigned seed = 1;
  int seeds = 1;
  std::string world = ROOMBA_RRT_CONFIG_DIR "/roomba_world.yaml";
  std::string config = ROOMBA_RRT_CONFIG_DIR "/roomba_behavior.yaml";
  std::string tree;
  std::string csv;
  std::string png;
};

double parseNumber(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value)) {
    throw std::invalid_argument(flag + " needs a number, got '" + text + "'");
  }
  return value;
}

Options parseOptions(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "-h" || flag == "--help") {
      std::cout << kUsage;
      std::exit(0);
    }
    if (i + 1 >= argc) throw std::invalid_argument(flag + " needs a value");
    const std::string value = argv[++i];
    if (flag == "--behavior") {
      o.behavior = value;
    } else if (flag == "--duration") {
      o.duration = parseNumber(flag, value);
    } else if (flag == "--seed") {
      const double seed = parseNumber(flag, value);
      if (seed < 0 || seed > 4294967295.0 || seed != std::floor(seed)) {
        throw std::invalid_argument("--seed needs an integer in [0, 2^32), got " + value);
      }
      o.seed = static_cast<unsigned>(seed);
    } else if (flag == "--seeds") {
      const double seeds = parseNumber(flag, value);
      if (seeds < 1 || seeds != std::floor(seeds)) {
        throw std::invalid_argument("--seeds needs a positive integer, got " + value);
      }
      o.seeds = static_cast<int>(seeds);
    } else if (flag == "--world") {
      o.world = value;
    } else if (flag == "--config") {
      o.config = value;
    } else if (flag == "--tree") {
      o.tree = value;
    } else if (flag == "--csv") {
      o.csv = value;
    } else if (flag == "--png") {
      o.png = value;
    } else {
      throw std::invalid_argument("unknown option " + flag);
    }
  }
  if (o.behavior != "fsm" && o.behavior != "bt") {
    throw std::invalid_argument("--behavior must be fsm or bt, got '" + o.behavior + "'");
  }
  if (!(o.duration > 0)) throw std::invalid_argument("--duration must be > 0");
  if (!o.tree.empty() && o.behavior != "bt") {
    throw std::invalid_argument("--tree needs --behavior bt");
  }
  return o;
}

std::unique_ptr<RoombaBehavior> makeBehavior(const Options& o, const RoombaParams& params,
                                             unsigned seed) {
  if (o.behavior == "fsm") return std::make_unique<roomba_rrt::behavior::RoombaFsm>(params, seed);
  if (o.tree.empty()) return std::make_unique<roomba_rrt::behavior::RoombaBt>(params, seed);
  return std::make_unique<roomba_rrt::behavior::RoombaBt>(params, seed, o.tree);
}

/// One point of the path, for the picture.
struct PathPoint {
  double x, y;
  RoombaState state;
};

/// The outcome of one run.
struct Run {
  std::vector<double> coverage_at;  ///< at each checkpoint ≤ duration
  double final_coverage = 0;
  std::vector<PathPoint> path;  ///< only when drawing
};

/// One run in the lab's step order; writes the CSV when `csv` is open.
Run simulate(const Options& o, const sim::World& world, const RoombaParams& params, unsigned seed,
             std::ofstream* csv, bool keep_path, sim::Simulator& simulator) {
  simulator.reset();
  std::unique_ptr<RoombaBehavior> behavior = makeBehavior(o, params, seed);
  const long steps = std::lround(o.duration / world.step);
  Run run;
  std::size_t next_checkpoint = 0;
  double theta = simulator.pose().theta, previous_wrapped = theta;
  for (long k = 0; k < steps; ++k) {
    const sim::BumperState bumper = simulator.senseContact();
    const sim::Pose2D pose = simulator.pose();  // the pose the behaviour sees
    const sim::Velocity cmd = behavior->tick(bumper);
    if (csv || keep_path) {
      theta += std::remainder(pose.theta - previous_wrapped, 2 * kPi);  // unwrapped θ
      previous_wrapped = pose.theta;
    }
    if (csv) {
      *csv << k * world.step << ',' << pose.x << ',' << pose.y << ',' << theta << ',' << cmd.v
           << ',' << cmd.w << ',' << behavior->stateName() << ',' << (bumper.pressed ? 1 : 0)
           << '\n';
    }
    if (keep_path) run.path.push_back({pose.x, pose.y, behavior->state()});
    simulator.move(cmd);
    while (next_checkpoint < std::size(kCheckpoints) &&
           std::lround(kCheckpoints[next_checkpoint] / world.step) == k + 1) {
      run.coverage_at.push_back(simulator.coverage());
      ++next_checkpoint;
    }
  }
  run.final_coverage = simulator.coverage();
  return run;
}

// ---- the picture -------------------------------------------------------------------------

struct Rgb {
  double r, g, b;
};

Rgb colourOf(RoombaState state) {
  switch (state) {
    case RoombaState::kMoveForward:
      return {0.12, 0.35, 0.80};
    case RoombaState::kMoveInSpiral:
      return {0.10, 0.60, 0.25};
    case RoombaState::kGoBack:
      return {0.85, 0.15, 0.15};
    case RoombaState::kRotate:
      return {0.95, 0.55, 0.00};
  }
  return {0, 0, 0};
}

void drawPng(const std::string& file, const sim::Simulator& simulator, const Run& run,
             const std::string& title) {
  const sim::World& world = simulator.world();
  const double scale = 100.0;  // pixels per metre
  const double margin = 20.0, legend = 190.0, header = 30.0;
  const int width = static_cast<int>(world.width * scale + 2 * margin + legend);
  const int height = static_cast<int>(world.height * scale + 2 * margin + header);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  cairo_t* cr = cairo_create(surface);
  const auto px = [&](double x) { return margin + x * scale; };
  const auto py = [&](double y) { return header + margin + (world.height - y) * scale; };

  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);  // floor
  cairo_rectangle(cr, px(0), py(world.height), world.width * scale, world.height * scale);
  cairo_fill(cr);

  // Cleaned floor: one rectangle per run of swept cells in a row.
  const sim::CoverageGrid& grid = simulator.coverageGrid();
  const double c = grid.cellSize();
  cairo_set_source_rgb(cr, 0.70, 0.85, 0.97);
  for (int row = 0; row < grid.rows(); ++row) {
    for (int col = 0; col < grid.columns();) {
      if (!grid.isSwept(col, row)) {
        ++col;
        continue;
      }
      int end = col;
      while (end < grid.columns() && grid.isSwept(end, row)) ++end;
      cairo_rectangle(cr, px(col * c), py((row + 1) * c), (end - col) * c * scale, c * scale);
      col = end;
    }
  }
  cairo_fill(cr);

  roomba_rrt::tools::drawFurnitureAndWalls(cr, world, {world.height, scale, margin, header});

  // The path, one polyline per stretch in the same state; Rotate (in place) as dots.
  cairo_set_line_width(cr, 1.2);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (std::size_t i = 0; i + 1 < run.path.size();) {
    const RoombaState state = run.path[i].state;
    std::size_t end = i;
    while (end + 1 < run.path.size() && run.path[end + 1].state == state) ++end;
    const Rgb rgb = colourOf(state);
    cairo_set_source_rgb(cr, rgb.r, rgb.g, rgb.b);
    if (state == RoombaState::kRotate) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, px(run.path[i].x), py(run.path[i].y), 3.0, 0, 2 * kPi);
      cairo_fill(cr);
    } else {
      cairo_set_line_width(cr, state == RoombaState::kGoBack ? 3.0 : 1.2);  // 5 cm: make it show
      cairo_move_to(cr, px(run.path[i].x), py(run.path[i].y));
      for (std::size_t j = i + 1; j <= end + 1 && j < run.path.size(); ++j) {
        cairo_line_to(cr, px(run.path[j].x), py(run.path[j].y));
      }
      cairo_stroke(cr);
    }
    i = end + 1;
  }
  if (!run.path.empty()) {  // the start
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_arc(cr, px(run.path.front().x), py(run.path.front().y), 4.0, 0, 2 * kPi);
    cairo_fill(cr);
  }

  // Title and legend.
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 15);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_move_to(cr, margin, 26);
  cairo_show_text(cr, title.c_str());
  cairo_set_font_size(cr, 13);
  const double lx = px(world.width) + 25;
  double ly = py(world.height) + 10;
  for (RoombaState state : {RoombaState::kMoveForward, RoombaState::kMoveInSpiral,
                            RoombaState::kGoBack, RoombaState::kRotate}) {
    const Rgb rgb = colourOf(state);
    cairo_set_source_rgb(cr, rgb.r, rgb.g, rgb.b);
    if (state == RoombaState::kRotate) {
      cairo_arc(cr, lx + 12, ly, 3.0, 0, 2 * kPi);
      cairo_fill(cr);
    } else {
      cairo_set_line_width(cr, 3);
      cairo_move_to(cr, lx, ly);
      cairo_line_to(cr, lx + 24, ly);
      cairo_stroke(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, lx + 32, ly + 4);
    cairo_show_text(cr, roomba_rrt::behavior::toString(state));
    ly += 22;
  }
  cairo_set_source_rgb(cr, 0.70, 0.85, 0.97);
  cairo_rectangle(cr, lx, ly - 7, 24, 14);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_move_to(cr, lx + 32, ly + 4);
  cairo_show_text(cr, "cleaned floor");
  ly += 22;
  cairo_arc(cr, lx + 12, ly, 4.0, 0, 2 * kPi);
  cairo_fill(cr);
  cairo_move_to(cr, lx + 32, ly + 4);
  cairo_show_text(cr, "start");

  cairo_destroy(cr);
  const cairo_status_t status = cairo_surface_write_to_png(surface, file.c_str());
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(file + ": cannot write the PNG (" + cairo_status_to_string(status) +
                             ")");
  }
}

// ---- statistics -------------------------------------------------------------------------

double mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

/// Index of the value closest to the mean (the first of equals): a typical run, not the worst.
std::size_t closestToMean(const std::vector<double>& values) {
  const double m = mean(values);
  std::size_t best = 0;
  for (std::size_t i = 1; i < values.size(); ++i) {
    if (std::abs(values[i] - m) < std::abs(values[best] - m)) best = i;
  }
  return best;
}

/// "mean ± std" in percent (sample standard deviation, N − 1; just the value for one run).
std::string meanStd(const std::vector<double>& values) {
  const double mean = ::mean(values);
  char text[64];
  if (values.size() < 2) {
    std::snprintf(text, sizeof text, "%5.1f", 100 * mean);
    return text;
  }
  double sum = 0;
  for (double v : values) sum += (v - mean) * (v - mean);
  const double std = std::sqrt(sum / static_cast<double>(values.size() - 1));
  std::snprintf(text, sizeof text, "%5.1f ± %.1f", 100 * mean, 100 * std);
  return text;
}

int run(int argc, char** argv) {
  const Options o = parseOptions(argc, argv);
  const sim::World world = sim::loadWorld(o.world);
  RoombaParams params = roomba_rrt::behavior::loadRoombaParams(o.config);
  params.rate = 1.0 / world.step;  // one behaviour tick per simulation step, as in the lab

  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv);
    if (!csv) throw std::runtime_error(o.csv + ": cannot write the CSV");
    csv.precision(10);
    csv << "t,x,y,theta,v,w,state,bumper\n";
  }

  sim::Simulator simulator(world);
  std::vector<std::vector<double>> at(std::size(kCheckpoints));
  std::vector<double> finals;
  roomba_rrt::tools::ProgressBar progress(o.seeds, "runs");
  const auto begin = std::chrono::steady_clock::now();
  for (int i = 0; i < o.seeds; ++i) {
    const Run result = simulate(o, world, params, o.seed + static_cast<unsigned>(i),
                                i == 0 && csv.is_open() ? &csv : nullptr, false, simulator);
    for (std::size_t c = 0; c < result.coverage_at.size(); ++c) {
      at[c].push_back(result.coverage_at[c]);
    }
    finals.push_back(result.final_coverage);
    progress.update(i + 1);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  progress.finish(o.seeds);

  // The picture: the typical run, simulated again (runs are deterministic by seed) with its path.
  const unsigned drawn_seed = o.seed + static_cast<unsigned>(closestToMean(finals));
  char title[200] = "";
  if (!o.png.empty()) {
    const Run drawn = simulate(o, world, params, drawn_seed, nullptr, true, simulator);
    const int n = std::snprintf(
        title, sizeof title, "%s, seed %u, %.0f s: %.1f %% of the floor cleaned",
        o.behavior == "fsm" ? "FSM" : "BT", drawn_seed, o.duration, 100 * drawn.final_coverage);
    if (o.seeds > 1) {
      std::snprintf(title + n, sizeof title - n, " (closest to the mean of seeds %u–%u, %.1f %%)",
                    o.seed, o.seed + o.seeds - 1, 100 * mean(finals));
    }
    drawPng(o.png, simulator, drawn, title);
  }

  std::printf("roomba_coverage: %s, seed%s %u%s, %.0f s of robot time per run, world %s\n",
              o.behavior.c_str(), o.seeds > 1 ? "s" : "", o.seed,
              o.seeds > 1 ? ("–" + std::to_string(o.seed + o.seeds - 1)).c_str() : "", o.duration,
              o.world.c_str());
  std::printf("  time [s]   coverage [%%]%s\n", o.seeds > 1 ? " (mean ± std)" : "");
  for (std::size_t c = 0; c < at.size(); ++c) {
    if (!at[c].empty()) std::printf("  %8.0f   %s\n", kCheckpoints[c], meanStd(at[c]).c_str());
  }
  bool final_is_checkpoint = false;
  for (double t : kCheckpoints)
    final_is_checkpoint |= std::lround(t / world.step) == std::lround(o.duration / world.step);
  if (!final_is_checkpoint) std::printf("  %8.0f   %s\n", o.duration, meanStd(finals).c_str());
  std::printf("  simulated %d × %.0f s in %.3f s of wall time\n", o.seeds, o.duration, seconds);
  if (!o.csv.empty()) std::printf("  trajectory: %s\n", o.csv.c_str());
  if (!o.png.empty()) std::printf("  picture: %s, %s\n", o.png.c_str(), title);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "roomba_coverage: %s\n%s", e.what(), kUsage);
    return 2;
  }
}
