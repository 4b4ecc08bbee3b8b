#include "drawing.h"

#include <algorithm>
#include <stdexcept>

namespace roomba_rrt::tools {

void setColour(cairo_t* cr, const Rgb& colour, double alpha) {
  cairo_set_source_rgba(cr, colour.r, colour.g, colour.b, alpha);
}

PngImage::PngImage(int width, int height, cairo_format_t format)
    : surface_(cairo_image_surface_create(format, width, height)), cr_(cairo_create(surface_)) {
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
}

PngImage::~PngImage() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

void PngImage::write(const std::string& file) const {
  const cairo_status_t status = cairo_surface_write_to_png(surface_, file.c_str());
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(file + ": cannot write the PNG (" + cairo_status_to_string(status) +
                             ")");
  }
}

void drawText(cairo_t* cr, const std::string& text, double x, double y, double align_x,
              double align_y) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - e.x_bearing - align_x * e.width, y - e.y_bearing - align_y * e.height);
  cairo_show_text(cr, text.c_str());
}

void drawTitle(cairo_t* cr, const std::string& title, double x, double baseline, double size) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_move_to(cr, x, baseline);
  cairo_show_text(cr, title.c_str());
}

RoomCanvas roomCanvas(const world::World& world) {
  RoomCanvas c{world.room.height};
  c.scale = std::min(100.0, 1200.0 / std::max(world.room.width, world.room.height));
  c.origin = world.room.origin;
  return c;
}

void drawFloor(cairo_t* cr, const world::World& world, const RoomCanvas& c) {
  cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
  cairo_rectangle(cr, c.px(world.room.origin.x), c.py(world.room.origin.y + world.room.height),
                  world.room.width * c.scale, world.room.height * c.scale);
  cairo_fill(cr);
}

void fillCells(cairo_t* cr, const RoomCanvas& c, const geometry::Point2& origin, double cell,
               int columns, int rows, const std::function<bool(int, int)>& filled) {
  for (int row = 0; row < rows; ++row) {
    for (int col = 0; col < columns;) {
      if (!filled(col, row)) {
        ++col;
        continue;
      }
      int end = col;
      while (end < columns && filled(end, row)) ++end;
      cairo_rectangle(cr, c.px(origin.x + col * cell), c.py(origin.y + (row + 1) * cell),
                      (end - col) * cell * c.scale, cell * c.scale);
      col = end;
    }
  }
  cairo_fill(cr);
}

void drawFurnitureAndWalls(cairo_t* cr, const world::World& world, const RoomCanvas& c) {
  cairo_set_source_rgb(cr, 0.45, 0.40, 0.35);
  for (const geometry::Circle& circle : world.room.circles) {
    cairo_new_sub_path(cr);
    cairo_arc(cr, c.px(circle.center.x), c.py(circle.center.y), circle.radius * c.scale, 0,
              2 * kPi);
  }
  for (const geometry::Rectangle& r : world.room.rectangles) {
    cairo_rectangle(cr, c.px(r.min_x), c.py(r.max_y), (r.max_x - r.min_x) * c.scale,
                    (r.max_y - r.min_y) * c.scale);
  }
  cairo_fill(cr);
  if (world.room.map) {  // its blocked cells, dark grey
    const geometry::OccupancyGrid& map = *world.room.map;
    cairo_set_source_rgb(cr, 0.30, 0.30, 0.30);
    fillCells(cr, c, map.origin, map.resolution, map.width, map.height,
              [&map](int i, int j) { return map.blocked(i, j); });
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 3);
  cairo_rectangle(cr, c.px(world.room.origin.x), c.py(world.room.origin.y + world.room.height),
                  world.room.width * c.scale, world.room.height * c.scale);
  cairo_stroke(cr);
}

}  // namespace roomba_rrt::tools
