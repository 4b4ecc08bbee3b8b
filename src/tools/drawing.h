// Drawing PNGs with cairo, shared by the tools that write them (rrt_plot, roomba_coverage,
// roomba_nav_eval): the white image and its file, colours, aligned text, and the simulator's room
// (floor, furniture, walls).
#pragma once

#include <cairo.h>

#include <functional>
#include <string>

#include "roomba_rrt/world/world.h"

namespace roomba_rrt::tools {

inline constexpr double kPi = 3.14159265358979323846;

struct Rgb {
  double r, g, b;
};

void setColour(cairo_t* cr, const Rgb& colour, double alpha = 1.0);

/// A white image of width × height pixels to draw on through cr(), then written to a PNG file.
class PngImage {
 public:
  PngImage(int width, int height, cairo_format_t format = CAIRO_FORMAT_ARGB32);
  ~PngImage();
  PngImage(const PngImage&) = delete;
  PngImage& operator=(const PngImage&) = delete;

  cairo_t* cr() const { return cr_; }

  /// Throws std::runtime_error "<file>: cannot write the PNG (<cairo's reason>)".
  void write(const std::string& file) const;

 private:
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

/// `text` placed by its ink box: (x, y) is its left/top edge at align 0, its centre at 0.5, its
/// right/bottom edge at 1.
void drawText(cairo_t* cr, const std::string& text, double x, double y, double align_x,
              double align_y);

/// A picture's title: black sans-serif of `size` points, its baseline starting at (x, baseline).
void drawTitle(cairo_t* cr, const std::string& title, double x, double baseline, double size);

/// Maps room metres to image pixels: x to the right, y up, the room's top-left corner at
/// (margin, header + margin).
struct RoomCanvas {
  double height;         ///< the room's height (m)
  double scale = 100.0;  ///< pixels per metre
  double margin = 20.0;
  double header = 30.0;
  geometry::Point2 origin;  ///< the room's lower-left corner (a map's origin), m
  double px(double x) const { return margin + (x - origin.x) * scale; }
  double py(double y) const { return header + margin + (origin.y + height - y) * scale; }
};

/// The canvas of a world's room: 100 pixels per metre, fewer for a room (a map) larger than
/// 12 m so that the picture stays within about 1200 pixels.
RoomCanvas roomCanvas(const world::World& world);

/// Fills the cells of a grid (`columns` × `rows` squares of `cell` m, cell (0, 0)'s lower-left
/// corner at `origin`) for which `filled(column, row)` holds, one rectangle per run of them in a
/// row, in the current colour.
void fillCells(cairo_t* cr, const RoomCanvas& c, const geometry::Point2& origin, double cell,
               int columns, int rows, const std::function<bool(int, int)>& filled);

/// The floor, light grey.
void drawFloor(cairo_t* cr, const world::World& world, const RoomCanvas& c);

/// Furniture (filled, brown), a map's blocked cells (dark grey) and the walls (black outline).
void drawFurnitureAndWalls(cairo_t* cr, const world::World& world, const RoomCanvas& c);

}  // namespace roomba_rrt::tools
