// rrt_plot: plans once and draws the result like the lab's figures, into a PNG (Cairo).
//
//   rrt_plot --scenario a --goal-bias 0.9 --seed 42 -o a_p09.png
//            [--algorithm A] [--collision points|segments] [--smooth] [--width 900]
//
// Drawn: the sampling bounds, the obstacles, the tree's edges and nodes, the path, the start and
// the goal, axes with ticks in metres, a legend, and a title with scenario, p, seed and length.
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "drawing.h"
#include "roomba_rrt/planning/planner.h"
#include "tool_arguments.h"

namespace rp = roomba_rrt::planning;
namespace tools = roomba_rrt::tools;

namespace {

using tools::drawText;
using tools::Rgb;
using tools::setColour;

constexpr Rgb kBoundsColor{0.1, 0.1, 0.1};
constexpr Rgb kObstacleColor{0.55, 0.55, 0.6};
constexpr Rgb kTreeColor{0.25, 0.5, 0.85};
constexpr Rgb kPathColor{0.85, 0.1, 0.1};
constexpr Rgb kStartColor{0.1, 0.65, 0.2};
constexpr Rgb kGoalColor{0.95, 0.6, 0.0};

// World metres -> image pixels (y up in the world, down in the image).
struct View {
  rp::Bounds bounds;
  double left, top, scale;
  double x(double wx) const { return left + (wx - bounds.x_min) * scale; }
  double y(double wy) const { return top + (bounds.y_max - wy) * scale; }
};

std::string number(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

void drawAxes(cairo_t* cr, const View& v) {
  const rp::Bounds& b = v.bounds;
  const double span = std::max(b.x_max - b.x_min, b.y_max - b.y_min);
  const double tick = span <= 12 ? 1.0 : std::pow(10.0, std::floor(std::log10(span / 2)));
  const int decimals = tick >= 1 ? 0 : 1;
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  cairo_set_font_size(cr, 13);
  for (double t = std::ceil(b.x_min / tick) * tick; t <= b.x_max + 1e-9; t += tick) {
    cairo_move_to(cr, v.x(t), v.y(b.y_min));
    cairo_line_to(cr, v.x(t), v.y(b.y_min) + 6);
    drawText(cr, number(t, decimals), v.x(t), v.y(b.y_min) + 9, 0.5, 0);
  }
  for (double t = std::ceil(b.y_min / tick) * tick; t <= b.y_max + 1e-9; t += tick) {
    cairo_move_to(cr, v.x(b.x_min), v.y(t));
    cairo_line_to(cr, v.x(b.x_min) - 6, v.y(t));
    drawText(cr, number(t, decimals), v.x(b.x_min) - 9, v.y(t), 1, 0.5);
  }
  cairo_stroke(cr);
  cairo_set_font_size(cr, 15);
  drawText(cr, "x [m]", v.x((b.x_min + b.x_max) / 2), v.y(b.y_min) + 32, 0.5, 0);
  cairo_save(cr);
  cairo_translate(cr, v.x(b.x_min) - 48, v.y((b.y_min + b.y_max) / 2));
  cairo_rotate(cr, -M_PI / 2);
  drawText(cr, "y [m]", 0, 0, 0.5, 0.5);
  cairo_restore(cr);
}

// A filled disc of `radius` pixels with a thin dark outline.
void outlinedDisc(cairo_t* cr, double x, double y, double radius, const Rgb& fill,
                  const Rgb& outline) {
  cairo_arc(cr, x, y, radius, 0, 2 * M_PI);
  setColour(cr, fill);
  cairo_fill_preserve(cr);
  setColour(cr, outline);
  cairo_set_line_width(cr, 1.2);
  cairo_stroke(cr);
}

void drawWorld(cairo_t* cr, const View& v, const rp::Problem& problem,
               const rp::PlanResult& result) {
  // A map's occupied (and unknown) cells, through the tools' room canvas placed on this view.
  if (problem.map) {
    const roomba_rrt::geometry::OccupancyGrid& g = problem.map->grid();
    tools::RoomCanvas canvas;
    canvas.height = v.bounds.y_max - v.bounds.y_min;
    canvas.scale = v.scale;
    canvas.origin = {v.bounds.x_min, v.bounds.y_min};
    canvas.margin = v.left;
    canvas.header = v.top - v.left;
    setColour(cr, kObstacleColor);
    tools::fillCells(cr, canvas, g.origin, g.resolution, g.width, g.height,
                     [&](int i, int j) { return g.blocked(i, j, problem.map->unknownIsFree()); });
  }
  // Obstacles.
  for (const rp::Circle& c : problem.obstacles) {
    outlinedDisc(cr, v.x(c.center.x), v.y(c.center.y), c.radius * v.scale, kObstacleColor,
                 {0.3, 0.3, 0.35});
  }
  for (const rp::Rectangle& r : problem.rectangles) {
    cairo_rectangle(cr, v.x(r.min_x), v.y(r.max_y), (r.max_x - r.min_x) * v.scale,
                    (r.max_y - r.min_y) * v.scale);
    setColour(cr, kObstacleColor);
    cairo_fill_preserve(cr);
    setColour(cr, {0.3, 0.3, 0.35});
    cairo_set_line_width(cr, 1.2);
    cairo_stroke(cr);
  }
  // Tree: every edge, then the nodes.
  const rp::Tree& tree = result.tree;
  setColour(cr, kTreeColor, 0.8);
  cairo_set_line_width(cr, 0.9);
  for (int i = 0; i < tree.size(); ++i) {
    const int p = tree.parent[i];
    if (p < 0) continue;
    cairo_move_to(cr, v.x(tree.nodes[p].x), v.y(tree.nodes[p].y));
    cairo_line_to(cr, v.x(tree.nodes[i].x), v.y(tree.nodes[i].y));
  }
  cairo_stroke(cr);
  for (const rp::Point2& n : tree.nodes) {
    cairo_arc(cr, v.x(n.x), v.y(n.y), 1.6, 0, 2 * M_PI);
    cairo_fill(cr);
  }
  // Path.
  if (!result.path.empty()) {
    setColour(cr, kPathColor);
    cairo_set_line_width(cr, 3.0);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_move_to(cr, v.x(result.path[0].x), v.y(result.path[0].y));
    for (const rp::Point2& p : result.path) cairo_line_to(cr, v.x(p.x), v.y(p.y));
    cairo_stroke(cr);
  }
  // Start and goal on top.
  for (const auto& [p, color] :
       {std::pair{problem.start, kStartColor}, {problem.goal, kGoalColor}}) {
    outlinedDisc(cr, v.x(p.x), v.y(p.y), 7, color, {0, 0, 0});
  }
  // Bounds.
  const rp::Bounds& b = problem.bounds;
  setColour(cr, kBoundsColor);
  cairo_set_line_width(cr, 1.5);
  cairo_rectangle(cr, v.x(b.x_min), v.y(b.y_max), (b.x_max - b.x_min) * v.scale,
                  (b.y_max - b.y_min) * v.scale);
  cairo_stroke(cr);
}

void drawLegend(cairo_t* cr, double x, double y) {
  enum class Mark { kLine, kThinLine, kDisc, kBox };
  struct Item {
    const char* label;
    Rgb color;
    Mark mark;
  };
  const Item items[] = {
      {"bounds", kBoundsColor, Mark::kBox},  {"obstacle", kObstacleColor, Mark::kDisc},
      {"tree", kTreeColor, Mark::kThinLine}, {"path", kPathColor, Mark::kLine},
      {"start", kStartColor, Mark::kDisc},   {"goal", kGoalColor, Mark::kDisc}};
  cairo_set_font_size(cr, 14);
  for (const Item& item : items) {
    setColour(cr, item.color);
    switch (item.mark) {
      case Mark::kLine:
      case Mark::kThinLine:
        cairo_set_line_width(cr, item.mark == Mark::kLine ? 3.0 : 1.0);
        cairo_move_to(cr, x, y);
        cairo_line_to(cr, x + 28, y);
        cairo_stroke(cr);
        break;
      case Mark::kDisc:
        cairo_arc(cr, x + 14, y, 7, 0, 2 * M_PI);
        cairo_fill(cr);
        break;
      case Mark::kBox:
        cairo_set_line_width(cr, 1.5);
        cairo_rectangle(cr, x + 4, y - 7, 20, 14);
        cairo_stroke(cr);
        break;
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    drawText(cr, item.label, x + 38, y, 0, 0.5);
    y += 26;
  }
}

std::string title(const std::string& scenario, const rp::PlannerOptions& o,
                  const rp::PlanResult& r) {
  std::string t = "scenario " + scenario + ", " + rp::toString(o.algorithm) + " (" +
                  rp::toString(o.collision) + "), p = " + number(o.goal_bias, 2) + ", seed " +
                  std::to_string(o.seed) + ": ";
  t += r.success ? "length " + number(r.length, 3) + " m" : "no path";
  return t + ", " + std::to_string(r.iterations) + " iterations, " + std::to_string(r.tree.size()) +
         " nodes";
}

}  // namespace

int main(int argc, char** argv) {
  tools::ToolArguments args;
  rp::Problem problem;
  std::string output;
  int width = 900;
  try {
    for (int i = 1; i < argc; ++i) {
      if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
        std::cout << "usage: rrt_plot --scenario a [--goal-bias P] [--seed S] -o file.png\n"
                  << "       rrt_plot --world config/roomba_world_furnished.yaml --start 3.2,2.4"
                     " --goal 3.0,4.55 -o room.png\n"
                  << tools::commonFlagsHelp()
                  << "  -o FILE                  output PNG (required)\n"
                  << "  --width PX               image width (default 900)\n"
                  << "  --world FILE             plan in the simulator's room (scenario room:\n"
                     "                           its furniture and robot radius), from --start\n"
                     "                           X,Y to --goal X,Y; empty, furnished and\n"
                     "                           apartment (a map) name the package's worlds\n"
                     "  --map FILE               plan on a map_server map (its occupied and\n"
                     "                           unknown cells; the Roomba's 0.17 m radius) from\n"
                     "                           --start X,Y to --goal X,Y\n";
        return 0;
      }
    }
    args = tools::parseToolArguments(
        argc, argv, {"-o", "--output", "--width", "--world", "--map", "--start", "--goal"}, {});
    output = args.tool.count("-o") ? args.tool["-o"] : args.tool["--output"];
    if (output.empty()) throw std::invalid_argument("-o: an output file is required");
    if (args.tool.count("--width")) width = tools::parseIntFlag("--width", args.tool["--width"]);
    if (width < 300 || width > 8000) throw std::invalid_argument("--width: must be in [300, 8000]");
    if (args.tool.count("--world") || args.tool.count("--map")) {
      problem = tools::worldProblem(args, &args.scenario);
    } else {
      const auto scenarios = rp::loadScenarios(args.scenario_file);
      const auto found = scenarios.find(args.scenario);
      if (found == scenarios.end()) {
        throw std::invalid_argument("--scenario: unknown scenario '" + args.scenario + "'");
      }
      problem = found->second;
    }
  } catch (const std::exception& e) {
    std::cerr << "rrt_plot: " << e.what() << " (see --help)\n";
    return 2;
  }

  const rp::PlanResult result = rp::plan(problem, args.options);
  if (!result.success && result.tree.size() == 0) {  // invalid input: nothing to draw
    std::cerr << "rrt_plot: " << result.message << "\n";
    return 2;
  }

  // Layout: title on top, square-ish plot left, legend right; sizes scale with the width.
  const double k = width / 900.0;
  const rp::Bounds& b = problem.bounds;
  const double plot_w = 640 * k;
  const double scale = plot_w / std::max(b.x_max - b.x_min, b.y_max - b.y_min);
  const double left = 80 * k, top = 60 * k;
  const int height = static_cast<int>(top + (b.y_max - b.y_min) * scale + 70 * k);
  tools::PngImage image(width, height, CAIRO_FORMAT_RGB24);
  cairo_t* cr = image.cr();
  cairo_scale(cr, k, k);  // draw in a 900-pixel-wide design space
  const View view{b, left / k, top / k, scale / k};
  drawWorld(cr, view, problem, result);
  drawAxes(cr, view);
  drawLegend(cr, view.x(b.x_max) + 30, view.y(b.y_max) + 15);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_font_size(cr, 16);
  drawText(cr, title(args.scenario, args.options, result), 450, 22, 0.5, 0.5);
  try {
    image.write(output);
  } catch (const std::runtime_error& e) {
    std::cerr << "rrt_plot: " << e.what() << "\n";
    return 1;
  }
  std::cout << output << ": " << title(args.scenario, args.options, result) << "\n";
  return 0;
}
