#include "screen_capture.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>

namespace roomba_rrt::test {

pid_t spawn(const std::vector<std::string>& args, const std::vector<std::string>& env,
            int stdout_fd) {
  const pid_t pid = fork();
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGTERM);  // no orphaned rviz or Xvfb when the test crashes
    for (const std::string& e : env) putenv(const_cast<char*>(e.c_str()));
    if (stdout_fd >= 0) dup2(stdout_fd, STDOUT_FILENO);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

void stop(pid_t pid) {
  if (pid <= 0) return;
  kill(pid, SIGTERM);
  waitpid(pid, nullptr, 0);
}

bool Screenshot::isNear(int x, int y, Rgb colour, int tolerance) const {
  const unsigned char* p = &rgb[3 * (static_cast<std::size_t>(y) * width + x)];
  return std::abs(p[0] - colour.r) <= tolerance && std::abs(p[1] - colour.g) <= tolerance &&
         std::abs(p[2] - colour.b) <= tolerance;
}

Blob Screenshot::find(Rgb colour, int tolerance, Box within) const {
  Blob blob;
  if (empty()) return blob;
  blob.bounds = {within.x1, within.y1, within.x0, within.y0};  // grows from empty
  double sum_x = 0, sum_y = 0;
  for (int y = std::max(0, within.y0); y < std::min(height, within.y1); ++y) {
    for (int x = std::max(0, within.x0); x < std::min(width, within.x1); ++x) {
      if (!isNear(x, y, colour, tolerance)) continue;
      ++blob.pixels;
      sum_x += x + 0.5;
      sum_y += y + 0.5;
      blob.bounds = {std::min(blob.bounds.x0, x), std::min(blob.bounds.y0, y),
                     std::max(blob.bounds.x1, x + 1), std::max(blob.bounds.y1, y + 1)};
    }
  }
  if (blob.pixels > 0) {
    blob.x = sum_x / blob.pixels;
    blob.y = sum_y / blob.pixels;
  }
  return blob;
}

bool Screenshot::savePng(const std::string& file) const {
  if (empty()) return false;
  const std::string command = "convert -size " + std::to_string(width) + "x" +
                              std::to_string(height) + " -depth 8 rgb:- '" + file + "'";
  FILE* pipe = popen(command.c_str(), "w");
  if (!pipe) return false;
  const bool written = fwrite(rgb.data(), 1, rgb.size(), pipe) == rgb.size();
  return pclose(pipe) == 0 && written;
}

VirtualScreen::VirtualScreen(int width, int height) : width_(width), height_(height) {
  // Xvfb picks a free display number and writes it to the pipe (-displayfd).
  int fds[2];
  if (pipe(fds) != 0) return;
  const std::string screen = std::to_string(width) + "x" + std::to_string(height) + "x24";
  xvfb_ = spawn(
      {"Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0", screen, "-nolisten", "tcp"});
  close(fds[1]);
  char number[16] = {0};
  const ssize_t got = read(fds[0], number, sizeof(number) - 1);
  close(fds[0]);
  if (got > 0) display_ = ":" + std::string(number, number + got - (number[got - 1] == '\n'));
}

VirtualScreen::~VirtualScreen() { stop(xvfb_); }

pid_t VirtualScreen::start(const std::vector<std::string>& args) const {
  return spawn(args, {"DISPLAY=" + display_, "LIBGL_ALWAYS_SOFTWARE=1"});
}

Screenshot VirtualScreen::grab() const {
  Screenshot shot;
  const std::string command =
      "DISPLAY=" + display_ + " import -window root -depth 8 rgb:- 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return shot;
  std::array<unsigned char, 65536> buffer;
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    shot.rgb.insert(shot.rgb.end(), buffer.begin(), buffer.begin() + n);
  }
  pclose(pipe);
  if (shot.rgb.size() != std::size_t{3} * width_ * height_) shot.rgb.clear();
  shot.width = width_;
  shot.height = height_;
  return shot;
}

}  // namespace roomba_rrt::test
