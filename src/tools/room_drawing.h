// Drawing the simulator's room with cairo, shared by the tools that write PNGs
// (roomba_coverage, roomba_nav_eval).
#pragma once

#include <cairo.h>

#include "roomba_rrt/sim/world.h"

namespace roomba_rrt::tools {

/// Maps room metres to image pixels: x to the right, y up, the room's top-left corner at
/// (margin, header + margin).
struct RoomCanvas {
  double height;         ///< the room's height (m)
  double scale = 100.0;  ///< pixels per metre
  double margin = 20.0;
  double header = 30.0;
  double px(double x) const { return margin + x * scale; }
  double py(double y) const { return header + margin + (height - y) * scale; }
};

/// Furniture (filled, brown) and the walls (black outline).
inline void drawFurnitureAndWalls(cairo_t* cr, const sim::World& world, const RoomCanvas& c) {
  constexpr double kPi = 3.14159265358979323846;
  cairo_set_source_rgb(cr, 0.45, 0.40, 0.35);
  for (const sim::Circle& circle : world.circles) {
    cairo_new_sub_path(cr);
    cairo_arc(cr, c.px(circle.center.x), c.py(circle.center.y), circle.radius * c.scale, 0,
              2 * kPi);
  }
  for (const sim::Rectangle& r : world.rectangles) {
    cairo_rectangle(cr, c.px(r.min_x), c.py(r.max_y), (r.max_x - r.min_x) * c.scale,
                    (r.max_y - r.min_y) * c.scale);
  }
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 3);
  cairo_rectangle(cr, c.px(0), c.py(world.height), world.width * c.scale, world.height * c.scale);
  cairo_stroke(cr);
}

}  // namespace roomba_rrt::tools
