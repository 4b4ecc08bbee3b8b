// What a user sees in rviz, for tests: a virtual X server (Xvfb), programs started on it, and
// screen grabs (ImageMagick's `import`) as pixels to look for colours in.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace roomba_rrt::test {

struct Rgb {
  int r, g, b;
};

/// Starts `args` in the background with extra environment settings (`NAME=value`), its stdout
/// sent to `stdout_fd` when given; returns its pid. The child is killed when the test dies.
pid_t spawn(const std::vector<std::string>& args, const std::vector<std::string>& env = {},
            int stdout_fd = -1);

/// Stops a child started by spawn() (SIGTERM) and waits for it; nothing for pid ≤ 0.
void stop(pid_t pid);

/// A rectangle of pixels, [x0, x1) × [y0, y1); empty when x1 ≤ x0 or y1 ≤ y0.
struct Box {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

/// The pixels of one colour: how many, their centroid and bounding box.
struct Blob {
  long pixels = 0;
  double x = 0, y = 0;  ///< centroid (pixel centres), 0 when there are none
  Box bounds;
};

/// A screenshot: packed 8-bit RGB, row by row from the top left.
struct Screenshot {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  ///< empty when the grab failed

  bool empty() const { return rgb.empty(); }
  Box all() const { return {0, 0, width, height}; }
  /// Whether the pixel at (x, y) is within `tolerance` of `colour` in each channel.
  bool isNear(int x, int y, Rgb colour, int tolerance) const;
  /// The pixels within `tolerance` of `colour` in each channel, inside `within`.
  Blob find(Rgb colour, int tolerance, Box within) const;
  /// Number of pixels within `tolerance` of `colour` in each channel.
  long countNear(Rgb colour, int tolerance = 10) const {
    return find(colour, tolerance, all()).pixels;
  }
  /// Writes the pixels to a PNG file (ImageMagick's `convert`), to look at what a test saw.
  bool savePng(const std::string& file) const;
};

/// A virtual X server (Xvfb) of width × height pixels on a free display; stopped when destroyed.
class VirtualScreen {
 public:
  VirtualScreen(int width, int height);
  ~VirtualScreen();
  VirtualScreen(const VirtualScreen&) = delete;
  VirtualScreen& operator=(const VirtualScreen&) = delete;

  /// ":N", or empty when Xvfb did not start (is the xvfb package installed?).
  const std::string& display() const { return display_; }

  /// Starts `args` on this screen with software OpenGL (rviz needs no GPU); see spawn().
  pid_t start(const std::vector<std::string>& args) const;

  /// The whole screen now; empty when the grab failed.
  Screenshot grab() const;

 private:
  int width_, height_;
  pid_t xvfb_ = -1;
  std::string display_;
};

}  // namespace roomba_rrt::test
