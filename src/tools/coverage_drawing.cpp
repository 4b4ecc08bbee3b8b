#include "coverage_drawing.h"

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "drawing.h"

namespace roomba_rrt::tools {
namespace {

using behavior::RoombaState;

const Rgb kCleanedColour{0.70, 0.85, 0.97};

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

Rgb colourOfCount(std::size_t index) {
  const Rgb palette[] = {{0.12, 0.35, 0.80}, {0.10, 0.60, 0.25}, {0.85, 0.15, 0.15},
                         {0.95, 0.55, 0.00}, {0.50, 0.25, 0.70}, {0.30, 0.30, 0.30}};
  return palette[index % std::size(palette)];
}

/// Cleaned floor: one rectangle per run of swept cells in a row.
void drawCleanedFloor(cairo_t* cr, const sim::CoverageGrid& grid, const RoomCanvas& c) {
  setColour(cr, kCleanedColour);
  fillCells(cr, c, grid.origin(), grid.cellSize(), grid.columns(), grid.rows(),
            [&grid](int column, int row) { return grid.isSwept(column, row); });
}

/// The path, one polyline per stretch in the same state; Rotate (in place) as dots; the start.
void drawPath(cairo_t* cr, const std::vector<PathPoint>& path, const RoomCanvas& c) {
  cairo_set_line_width(cr, 1.2);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (std::size_t i = 0; i + 1 < path.size();) {
    const RoombaState state = path[i].state;
    std::size_t end = i;
    while (end + 1 < path.size() && path[end + 1].state == state) ++end;
    setColour(cr, colourOf(state));
    if (state == RoombaState::kRotate) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, c.px(path[i].x), c.py(path[i].y), 3.0, 0, 2 * kPi);
      cairo_fill(cr);
    } else {
      cairo_set_line_width(cr, state == RoombaState::kGoBack ? 3.0 : 1.2);  // 5 cm: make it show
      cairo_move_to(cr, c.px(path[i].x), c.py(path[i].y));
      for (std::size_t j = i + 1; j <= end + 1 && j < path.size(); ++j) {
        cairo_line_to(cr, c.px(path[j].x), c.py(path[j].y));
      }
      cairo_stroke(cr);
    }
    i = end + 1;
  }
  if (!path.empty()) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_arc(cr, c.px(path.front().x), c.py(path.front().y), 4.0, 0, 2 * kPi);
    cairo_fill(cr);
  }
}

/// The states' colours, the cleaned floor and the start, from (x, y) down.
void drawRunLegend(cairo_t* cr, double x, double y) {
  cairo_set_font_size(cr, 13);
  for (RoombaState state : {RoombaState::kMoveForward, RoombaState::kMoveInSpiral,
                            RoombaState::kGoBack, RoombaState::kRotate}) {
    setColour(cr, colourOf(state));
    if (state == RoombaState::kRotate) {
      cairo_arc(cr, x + 12, y, 3.0, 0, 2 * kPi);
      cairo_fill(cr);
    } else {
      cairo_set_line_width(cr, 3);
      cairo_move_to(cr, x, y);
      cairo_line_to(cr, x + 24, y);
      cairo_stroke(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, x + 32, y + 4);
    cairo_show_text(cr, behavior::toString(state));
    y += 22;
  }
  setColour(cr, kCleanedColour);
  cairo_rectangle(cr, x, y - 7, 24, 14);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_move_to(cr, x + 32, y + 4);
  cairo_show_text(cr, "cleaned floor");
  y += 22;
  cairo_arc(cr, x + 12, y, 4.0, 0, 2 * kPi);
  cairo_fill(cr);
  cairo_move_to(cr, x + 32, y + 4);
  cairo_show_text(cr, "start");
}

/// The coverage plot's image and its frame: simulated time [0, duration] across, coverage [0, 1]
/// up, the legend on the right.
constexpr int kPlotImageWidth = 900, kPlotImageHeight = 560;
struct PlotFrame {
  double duration;
  double left = 70, top = 50;
  double width = kPlotImageWidth - left - 220, height = kPlotImageHeight - top - 60;
  double px(double t) const { return left + t / duration * width; }
  double py(double c) const { return top + (1.0 - c) * height; }
};

/// Grid and axes: every 10 % and every 60 s (or a tenth of the duration).
void drawPlotAxes(cairo_t* cr, const PlotFrame& f, const std::string& axis) {
  const double tick = f.duration >= 300 ? 60.0 : f.duration / 10;
  cairo_set_font_size(cr, 12);
  cairo_set_line_width(cr, 1);
  for (int percent = 0; percent <= 100; percent += 10) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, f.px(0), f.py(percent / 100.0));
    cairo_line_to(cr, f.px(f.duration), f.py(percent / 100.0));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, f.left - 34, f.py(percent / 100.0) + 4);
    cairo_show_text(cr, (std::to_string(percent) + " %").c_str());
  }
  for (double t = 0; t <= f.duration + 1e-9; t += tick) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, f.px(t), f.py(0));
    cairo_line_to(cr, f.px(t), f.py(1));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    char label[32];
    std::snprintf(label, sizeof label, "%.0f", t);
    cairo_move_to(cr, f.px(t) - 8, f.py(0) + 18);
    cairo_show_text(cr, label);
  }
  cairo_move_to(cr, f.left + f.width / 2 - 60, kPlotImageHeight - 18);
  cairo_show_text(cr, "simulated time [s]");
  cairo_save(cr);
  cairo_move_to(cr, 18, f.top + f.height / 2 + 80);
  cairo_rotate(cr, -kPi / 2);
  cairo_show_text(cr, axis.c_str());
  cairo_restore(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.5);
  cairo_rectangle(cr, f.px(0), f.py(1), f.width, f.height);
  cairo_stroke(cr);
}

/// One robot count's curve: the mean, and a band of ± one standard deviation around it.
void drawCurve(cairo_t* cr, const PlotFrame& f, const Band& band, const Rgb& colour) {
  const std::size_t points = band.mean.size();
  const auto t_of = [&](std::size_t p) { return std::min(f.duration, p * kCurveInterval); };
  // The band: up along mean + std, back along mean − std.
  setColour(cr, colour, 0.15);
  cairo_move_to(cr, f.px(t_of(0)), f.py(std::min(1.0, band.mean[0] + band.std[0])));
  for (std::size_t p = 1; p < points; ++p) {
    cairo_line_to(cr, f.px(t_of(p)), f.py(std::min(1.0, band.mean[p] + band.std[p])));
  }
  for (std::size_t p = points; p-- > 0;) {
    cairo_line_to(cr, f.px(t_of(p)), f.py(std::max(0.0, band.mean[p] - band.std[p])));
  }
  cairo_close_path(cr);
  cairo_fill(cr);
  setColour(cr, colour);
  cairo_set_line_width(cr, 2.2);
  cairo_move_to(cr, f.px(t_of(0)), f.py(band.mean[0]));
  for (std::size_t p = 1; p < points; ++p) cairo_line_to(cr, f.px(t_of(p)), f.py(band.mean[p]));
  cairo_stroke(cr);
}

/// The count's legend entry at height y (its colour, "N robots", the checkpoints' mean ± std);
/// returns the height of the next entry. The source colour is the count's on entry.
double drawCountLegend(cairo_t* cr, const PlotFrame& f, const FleetStatistics& fleet, double y) {
  cairo_set_line_width(cr, 3);
  const double x = f.left + f.width + 20;
  cairo_move_to(cr, x, y);
  cairo_line_to(cr, x + 24, y);
  cairo_stroke(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_font_size(cr, 13);
  cairo_move_to(cr, x + 32, y + 4);
  const std::string name = !fleet.label.empty() ? fleet.label
                                                : std::to_string(fleet.robots) +
                                                      (fleet.robots == 1 ? " robot" : " robots");
  cairo_show_text(cr, name.c_str());
  cairo_set_font_size(cr, 11);
  for (std::size_t c = 0; c < fleet.at.size(); ++c) {
    if (fleet.at[c].empty()) continue;
    y += 16;
    const std::string row = std::to_string(static_cast<int>(kCheckpoints[c])) +
                            " s: " + percentMeanStd(fleet.at[c]) + " %";
    cairo_move_to(cr, x + 32, y + 4);
    cairo_show_text(cr, row.c_str());
  }
  return y + 30;
}

}  // namespace

void drawRunPicture(const std::string& file, const sim::Simulator& simulator, const Run& run,
                    const std::string& title) {
  const world::World& world = simulator.world();
  const RoomCanvas c = roomCanvas(world);
  const double legend = 190.0;
  PngImage image(static_cast<int>(world.room.width * c.scale + 2 * c.margin + legend),
                 static_cast<int>(world.room.height * c.scale + 2 * c.margin + c.header));
  cairo_t* cr = image.cr();
  drawFloor(cr, world, c);
  drawCleanedFloor(cr, simulator.coverageGrid(), c);
  drawFurnitureAndWalls(cr, world, c);
  drawPath(cr, run.path, c);

  drawTitle(cr, title, c.margin, 26, 15);
  drawRunLegend(cr, c.px(world.room.origin.x + world.room.width) + 25,
                c.py(world.room.origin.y + world.room.height) + 10);
  image.write(file);
}

void drawCoveragePlot(const std::string& file, const std::vector<FleetStatistics>& fleets,
                      double duration, const std::string& title, const std::string& axis) {
  const PlotFrame frame{duration};
  PngImage image(kPlotImageWidth, kPlotImageHeight);
  cairo_t* cr = image.cr();
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  drawPlotAxes(cr, frame, axis);
  double legend_y = frame.top + 10;
  for (std::size_t f = 0; f < fleets.size(); ++f) {
    drawCurve(cr, frame, bandOf(fleets[f].curves), colourOfCount(f));
    legend_y = drawCountLegend(cr, frame, fleets[f], legend_y);
  }
  drawTitle(cr, title, frame.left, 30, 15);
  image.write(file);
}

}  // namespace roomba_rrt::tools
