// A progress bar for the command-line tools' long runs, "[########........] 12/40 runs" on
// stderr. Drawn only when stderr is a terminal, so pipes, logs and tests get no control
// characters; redrawn at most ten times a second, so a tight loop may call update() often.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>

namespace roomba_rrt::tools {

class ProgressBar {
 public:
  /// `total` items, counted in `unit` ("runs", "seeds").
  ProgressBar(int total, std::string unit)
      : total_(total), unit_(std::move(unit)), shown_(isatty(STDERR_FILENO) == 1) {}

  /// Whether the bar is drawn (stderr is a terminal).
  bool shown() const { return shown_; }

  /// `done` of the total are finished.
  void update(int done) {
    if (!shown_) return;
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    draw(done);
    last_draw_ = now;
    drawn_ = true;
  }

  /// Draws the final count and ends the line.
  void finish(int done) {
    if (!shown_) return;
    draw(done);
    std::fputc('\n', stderr);
  }

 private:
  void draw(int done) const {
    constexpr int kWidth = 40;
    const int filled = total_ > 0 ? done * kWidth / total_ : kWidth;
    std::fprintf(stderr, "\r[%s%s] %d/%d %s", std::string(filled, '#').c_str(),
                 std::string(kWidth - filled, '.').c_str(), done, total_, unit_.c_str());
  }

  int total_;
  std::string unit_;
  bool shown_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace roomba_rrt::tools
