// roomba_coverage: how much of the floor the lab's Roomba cleans, without ROS.
//
// Runs the simulation core with the FSM or the BT in one process, in the lab's step order
// (contact → bumper → behaviour → move), deterministic by seed. Prints the coverage at 60, 300
// and 600 s (mean ± standard deviation over seeds with --seeds), writes the first seed's
// trajectory as CSV and draws a typical run as a PNG (room, furniture, cleaned floor, path
// coloured by state): the seed whose final coverage is closest to the mean. Shows a progress bar
// on a terminal. With --robots N (or a world that names robots) several Roombas run the behaviour
// in one room, each its own, and the coverage is that of their union; --plot draws it over time
// for each N. See README.md, "Behaviours" and "Several robots".
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
#include "drawing.h"
#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/behavior/roomba_fsm.h"
#include "roomba_rrt/sim/multi_robot_simulator.h"
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
    "                       [--robots N[,N...]] [--plot coverage.png]\n"
    "  --behavior  fsm (state machine) or bt (behavior tree)\n"
    "  --duration  simulated seconds per run (default 600)\n"
    "  --seed      seed of the rotation angle (default 1); --seeds N runs seeds seed..seed+N-1\n"
    "  --world     world YAML (default config/roomba_world.yaml)\n"
    "  --config    behaviour YAML (default config/roomba_behavior.yaml)\n"
    "  --tree      behavior-tree XML for --behavior bt (default: the lab's tree)\n"
    "  --csv       trajectory of the first seed: t,x,y,theta,v,w,state,bumper\n"
    "  --png       picture of a typical run: with --seeds N, the seed whose final coverage is\n"
    "              closest to the mean of the N (its title says which)\n"
    "  --robots    N robots spread evenly over the room (replacing the world's), each running the\n"
    "              behaviour with its own seed (robot k of seed s: s + 1000 k); the coverage is\n"
    "              their union's. A list (1,2,4) runs each count. A world that names robots runs\n"
    "              those without --robots. --csv and --png need one unnamed robot.\n"
    "  --plot      union coverage over time, mean ± std over the seeds, one curve per count\n"
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
  std::vector<int> robots;  ///< robot counts (--robots); empty: the world's robots
  std::string plot;
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

std::vector<int> parseCounts(const std::string& flag, const std::string& text) {
  std::vector<int> counts;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string item = text.substr(begin, end - begin);
    double n = 0;
    try {
      n = parseNumber(flag, item);
    } catch (const std::invalid_argument&) {
      n = -1;
    }
    if (n < 1 || n > static_cast<double>(sim::kMaxRobots) || n != std::floor(n)) {
      throw std::invalid_argument(flag + " needs robot counts in [1, " +
                                  std::to_string(sim::kMaxRobots) + "] like 4 or 1,2,4, got '" +
                                  text + "'");
    }
    counts.push_back(static_cast<int>(n));
    begin = end + 1;
  }
  return counts;
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
    } else if (flag == "--robots") {
      o.robots = parseCounts(flag, value);
    } else if (flag == "--plot") {
      o.plot = value;
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
  if (!o.robots.empty() && (!o.csv.empty() || !o.png.empty())) {
    throw std::invalid_argument("--csv and --png draw one robot; with --robots use --plot");
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

/// Writes the drawing to `file` and frees both.
void writePng(const std::string& file, cairo_t* cr, cairo_surface_t* surface) {
  cairo_destroy(cr);
  const cairo_status_t status = cairo_surface_write_to_png(surface, file.c_str());
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(file + ": cannot write the PNG (" + cairo_status_to_string(status) +
                             ")");
  }
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

  writePng(file, cr, surface);
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

// ---- several robots ------------------------------------------------------------------------

constexpr double kCurveInterval = 5.0;  ///< simulated s between two points of a --plot curve

/// One run of several robots: their union's coverage at the checkpoints and over time.
struct FleetRun {
  std::vector<double> coverage_at;  ///< at each checkpoint ≤ duration
  double final_coverage = 0;
  std::vector<double> curve;  ///< at 0, kCurveInterval, 2 kCurveInterval, … ≤ duration
};

/// The lab's step order for every robot at once: all bumpers, every behaviour, every move.
FleetRun simulateFleet(const Options& o, const RoombaParams& params, unsigned seed,
                       sim::MultiRobotSimulator& simulator) {
  simulator.reset();
  std::vector<std::unique_ptr<RoombaBehavior>> behaviors;
  for (std::size_t i = 0; i < simulator.size(); ++i) {
    behaviors.push_back(makeBehavior(o, params, seed + 1000u * static_cast<unsigned>(i)));
  }
  std::vector<sim::Velocity> commands(simulator.size());
  const double step = simulator.world().step;
  const long steps = std::lround(o.duration / step);
  const long per_point = std::max(1L, std::lround(kCurveInterval / step));
  FleetRun run;
  run.curve.push_back(simulator.unionCoverage());
  std::size_t next_checkpoint = 0;
  for (long k = 0; k < steps; ++k) {
    simulator.senseContact();
    for (std::size_t i = 0; i < commands.size(); ++i) {
      commands[i] = behaviors[i]->tick(simulator.bumper(i));
    }
    simulator.move(commands);
    while (next_checkpoint < std::size(kCheckpoints) &&
           std::lround(kCheckpoints[next_checkpoint] / step) == k + 1) {
      run.coverage_at.push_back(simulator.unionCoverage());
      ++next_checkpoint;
    }
    if ((k + 1) % per_point == 0) run.curve.push_back(simulator.unionCoverage());
  }
  run.final_coverage = simulator.unionCoverage();
  return run;
}

/// Every seed's runs with one robot count.
struct FleetStatistics {
  int robots = 0;
  std::vector<std::vector<double>> at;      ///< [checkpoint][seed]
  std::vector<double> finals;               ///< [seed]
  std::vector<std::vector<double>> curves;  ///< [seed][point]
};

Rgb colourOfCount(std::size_t index) {
  const Rgb palette[] = {{0.12, 0.35, 0.80}, {0.10, 0.60, 0.25}, {0.85, 0.15, 0.15},
                         {0.95, 0.55, 0.00}, {0.50, 0.25, 0.70}, {0.30, 0.30, 0.30}};
  return palette[index % std::size(palette)];
}

/// Union coverage over time, one curve per robot count: the mean over the seeds, a band of ± one
/// standard deviation, and the checkpoints' values written beside the curve.
void drawCoveragePlot(const std::string& file, const std::vector<FleetStatistics>& fleets,
                      double duration, const std::string& title) {
  const int width = 900, height = 560;
  const double left = 70, right = 220, top = 50, bottom = 60;
  const double plot_w = width - left - right, plot_h = height - top - bottom;
  const auto px = [&](double t) { return left + t / duration * plot_w; };
  const auto py = [&](double c) { return top + (1.0 - c) * plot_h; };
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);

  // Grid and axes: every 10 % and every 60 s (or a tenth of the duration).
  const double tick = duration >= 300 ? 60.0 : duration / 10;
  cairo_set_font_size(cr, 12);
  cairo_set_line_width(cr, 1);
  for (int percent = 0; percent <= 100; percent += 10) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, px(0), py(percent / 100.0));
    cairo_line_to(cr, px(duration), py(percent / 100.0));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, left - 34, py(percent / 100.0) + 4);
    cairo_show_text(cr, (std::to_string(percent) + " %").c_str());
  }
  for (double t = 0; t <= duration + 1e-9; t += tick) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, px(t), py(0));
    cairo_line_to(cr, px(t), py(1));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    char label[32];
    std::snprintf(label, sizeof label, "%.0f", t);
    cairo_move_to(cr, px(t) - 8, py(0) + 18);
    cairo_show_text(cr, label);
  }
  cairo_move_to(cr, left + plot_w / 2 - 60, height - 18);
  cairo_show_text(cr, "simulated time [s]");
  cairo_save(cr);
  cairo_move_to(cr, 18, top + plot_h / 2 + 80);
  cairo_rotate(cr, -kPi / 2);
  cairo_show_text(cr, "floor cleaned by the robots together");
  cairo_restore(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.5);
  cairo_rectangle(cr, px(0), py(1), plot_w, plot_h);
  cairo_stroke(cr);

  double legend_y = top + 10;
  for (std::size_t f = 0; f < fleets.size(); ++f) {
    const FleetStatistics& fleet = fleets[f];
    const std::size_t points = fleet.curves.front().size();
    std::vector<double> mean_at(points), std_at(points);
    for (std::size_t p = 0; p < points; ++p) {
      std::vector<double> values;
      for (const auto& curve : fleet.curves) values.push_back(curve[p]);
      mean_at[p] = mean(values);
      double sum = 0;
      for (double v : values) sum += (v - mean_at[p]) * (v - mean_at[p]);
      std_at[p] = values.size() > 1 ? std::sqrt(sum / (values.size() - 1)) : 0.0;
    }
    const auto t_of = [&](std::size_t p) { return std::min(duration, p * kCurveInterval); };
    const Rgb rgb = colourOfCount(f);
    // The band: up along mean + std, back along mean − std.
    cairo_set_source_rgba(cr, rgb.r, rgb.g, rgb.b, 0.15);
    cairo_move_to(cr, px(t_of(0)), py(std::min(1.0, mean_at[0] + std_at[0])));
    for (std::size_t p = 1; p < points; ++p) {
      cairo_line_to(cr, px(t_of(p)), py(std::min(1.0, mean_at[p] + std_at[p])));
    }
    for (std::size_t p = points; p-- > 0;) {
      cairo_line_to(cr, px(t_of(p)), py(std::max(0.0, mean_at[p] - std_at[p])));
    }
    cairo_close_path(cr);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, rgb.r, rgb.g, rgb.b);
    cairo_set_line_width(cr, 2.2);
    cairo_move_to(cr, px(t_of(0)), py(mean_at[0]));
    for (std::size_t p = 1; p < points; ++p) cairo_line_to(cr, px(t_of(p)), py(mean_at[p]));
    cairo_stroke(cr);
    // Legend: the count and its checkpoint means.
    cairo_set_line_width(cr, 3);
    const double lx = left + plot_w + 20;
    cairo_move_to(cr, lx, legend_y);
    cairo_line_to(cr, lx + 24, legend_y);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_font_size(cr, 13);
    cairo_move_to(cr, lx + 32, legend_y + 4);
    const std::string name =
        std::to_string(fleet.robots) + (fleet.robots == 1 ? " robot" : " robots");
    cairo_show_text(cr, name.c_str());
    cairo_set_font_size(cr, 11);
    for (std::size_t c = 0; c < fleet.at.size(); ++c) {
      if (fleet.at[c].empty()) continue;
      legend_y += 16;
      const std::string row =
          std::to_string(static_cast<int>(kCheckpoints[c])) + " s: " + meanStd(fleet.at[c]) + " %";
      cairo_move_to(cr, lx + 32, legend_y + 4);
      cairo_show_text(cr, row.c_str());
    }
    legend_y += 30;
  }
  cairo_set_font_size(cr, 15);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_move_to(cr, left, 30);
  cairo_show_text(cr, title.c_str());

  writePng(file, cr, surface);
}

/// --robots (or a world naming robots): every count × every seed, a table of union coverage, and
/// the plot.
int runFleets(const Options& o, const sim::World& world, const RoombaParams& params) {
  if (!o.csv.empty() || !o.png.empty()) {
    throw std::invalid_argument("--csv and --png draw one unnamed robot; " + o.world +
                                " names robots: use --plot");
  }
  std::vector<int> counts = o.robots;
  if (counts.empty()) counts.push_back(static_cast<int>(world.robots.size()));
  std::vector<FleetStatistics> fleets;
  roomba_rrt::tools::ProgressBar progress(o.seeds * static_cast<int>(counts.size()), "runs");
  const auto begin = std::chrono::steady_clock::now();
  for (const int n : counts) {
    sim::World fleet_world = world;
    if (!o.robots.empty()) fleet_world.robots = sim::spreadRobots(world, n);
    sim::MultiRobotSimulator simulator(fleet_world);
    FleetStatistics fleet;
    fleet.robots = n;
    fleet.at.resize(std::size(kCheckpoints));
    for (int i = 0; i < o.seeds; ++i) {
      const FleetRun result =
          simulateFleet(o, params, o.seed + static_cast<unsigned>(i), simulator);
      for (std::size_t c = 0; c < result.coverage_at.size(); ++c) {
        fleet.at[c].push_back(result.coverage_at[c]);
      }
      fleet.finals.push_back(result.final_coverage);
      fleet.curves.push_back(result.curve);
      progress.update(static_cast<int>(fleets.size()) * o.seeds + i + 1);
    }
    fleets.push_back(std::move(fleet));
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  progress.finish(o.seeds * static_cast<int>(counts.size()));

  const std::string seeds =
      o.seeds > 1 ? "seeds " + std::to_string(o.seed) + "–" + std::to_string(o.seed + o.seeds - 1)
                  : "seed " + std::to_string(o.seed);
  std::printf("roomba_coverage: %s, %s, %.0f s of robot time per run, world %s\n",
              o.behavior.c_str(), seeds.c_str(), o.duration, o.world.c_str());
  std::printf("  floor cleaned by the robots together [%%]%s\n",
              o.seeds > 1 ? " (mean ± std)" : "");
  std::printf("  robots");
  for (std::size_t c = 0; c < std::size(kCheckpoints); ++c) {
    if (!fleets.front().at[c].empty()) std::printf("  %12.0f s", kCheckpoints[c]);
  }
  bool final_is_checkpoint = false;
  for (double t : kCheckpoints)
    final_is_checkpoint |= std::lround(t / world.step) == std::lround(o.duration / world.step);
  if (!final_is_checkpoint) std::printf("  %12.0f s", o.duration);
  std::printf("\n");
  for (const FleetStatistics& fleet : fleets) {
    std::printf("  %6d", fleet.robots);
    for (const auto& values : fleet.at) {
      if (!values.empty()) std::printf("  %14s", meanStd(values).c_str());
    }
    if (!final_is_checkpoint) std::printf("  %14s", meanStd(fleet.finals).c_str());
    std::printf("\n");
  }
  std::printf("  simulated %zu × %d × %.0f s in %.3f s of wall time\n", counts.size(), o.seeds,
              o.duration, seconds);
  if (!o.plot.empty()) {
    const std::string title = std::string(o.behavior == "fsm" ? "FSM" : "BT") +
                              " on every robot in the room: floor cleaned together, mean ± std, " +
                              std::to_string(o.seeds) + (o.seeds == 1 ? " seed" : " seeds");
    drawCoveragePlot(o.plot, fleets, o.duration, title);
    std::printf("  plot: %s\n", o.plot.c_str());
  }
  return 0;
}

int run(int argc, char** argv) {
  const Options o = parseOptions(argc, argv);
  const sim::World world = sim::loadWorld(o.world);
  RoombaParams params = roomba_rrt::behavior::loadRoombaParams(o.config);
  params.rate = 1.0 / world.step;  // one behaviour tick per simulation step, as in the lab
  if (!o.robots.empty() || !world.robots.empty()) return runFleets(o, world, params);
  if (!o.plot.empty()) throw std::invalid_argument("--plot needs --robots");

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
