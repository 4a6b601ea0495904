#pragma once
// A progress bar on stderr for runs that take more than a moment: only on a terminal, redrawn
// only when the shown percentage changes, erased when done.

#include <unistd.h>

#include <cstdio>
#include <string>

namespace frob::app {

class ProgressBar {
 public:
  // Shown only when `enabled` and stderr is a terminal; `label` precedes the bar.
  ProgressBar(bool enabled, std::string label) : on_(enabled && ::isatty(STDERR_FILENO) == 1), label_(std::move(label)) {}
  ~ProgressBar() { finish(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Shows `done` (0 to 1) with `detail` after the percentage.
  void show(double done, const char* detail = "") {
    const int percent = static_cast<int>(done * 100.0);
    if (!on_ || percent == shown_) return;
    shown_ = percent;
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\r%s [%s%s] %3d%% %s", label_.c_str(), std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(), percent, detail);
    std::fflush(stderr);
  }
  // Erases the bar.
  void finish() {
    if (on_ && shown_ >= 0) std::fputs("\r\033[K", stderr);
    shown_ = -1;
  }

 private:
  bool on_;
  std::string label_;
  int shown_ = -1;
};

}  // namespace frob::app
