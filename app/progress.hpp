#pragma once
// A progress bar for runs that take more than a moment (main shows it on stderr when that is a
// terminal): redrawn only when the shown percentage changes, erased when done.

#include <cstdio>
#include <string>

namespace frob::app {

class ProgressBar {
 public:
  // Drawn on `out` when `enabled`; `label` precedes the bar.
  ProgressBar(std::FILE* out, bool enabled, std::string label) : out_(out), on_(enabled), label_(std::move(label)) {}
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
    std::fprintf(out_, "\r%s [%s%s] %3d%% %s\033[K", label_.c_str(), std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(), percent, detail);
    std::fflush(out_);
  }
  // Says what is happening before there is progress to show, until the bar or finish() replaces it.
  void say(const std::string& what) {
    if (!on_) return;
    std::fprintf(out_, "\r%s\033[K", what.c_str());
    std::fflush(out_);
    shown_ = 101;  // drawn: the next show() redraws, finish() erases
  }
  // Erases the bar.
  void finish() {
    if (on_ && shown_ >= 0) std::fputs("\r\033[K", out_);
    shown_ = -1;
  }

 private:
  std::FILE* out_;
  bool on_;
  std::string label_;
  int shown_ = -1;
};

}  // namespace frob::app
