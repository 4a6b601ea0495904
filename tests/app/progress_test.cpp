// The progress bar: drawn once per percent however often it is told, erased at the end, silent when off.
#include "../../app/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace frob::app {
namespace {

// What was written to `f`, which is then closed.
std::string readBack(std::FILE* f) {
  std::string text(static_cast<std::size_t>(std::ftell(f)), '\0');
  std::rewind(f);
  text.resize(std::fread(text.data(), 1, text.size(), f));
  std::fclose(f);
  return text;
}

std::string drawn(bool enabled, int updates) {
  std::FILE* f = std::tmpfile();
  {
    ProgressBar bar(f, enabled, "run");
    for (int i = 0; i <= updates; ++i) bar.show(static_cast<double>(i) / updates, "s");
  }
  return readBack(f);
}

// Before the first step there is no progress to show, yet the student sees what frob is doing.
TEST(ProgressBar, SaysWhatItIsDoingUntilTheBarReplacesIt) {
  std::FILE* f = std::tmpfile();
  {
    ProgressBar bar(f, true, "run");
    bar.say("frob: compiling my.cpp...");
    bar.show(0.0, "starting");
  }
  EXPECT_EQ(readBack(f), "\rfrob: compiling my.cpp...\033[K\rrun [..............................]   0% starting\033[K\r\033[K");
}

TEST(ProgressBar, OneDrawPerPercent) {
  const std::string text = drawn(true, 6000);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\r'), 101 + 1);  // 0..100 %, then the erase
  EXPECT_NE(text.find("\rrun [###############...............]  50% s"), std::string::npos);
  EXPECT_EQ(text.substr(text.size() - 4), "\r\033[K");
}

TEST(ProgressBar, SilentWhenOff) { EXPECT_EQ(drawn(false, 100), ""); }

}  // namespace
}  // namespace frob::app
