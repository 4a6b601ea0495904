#pragma once
// Golden-image comparison for render tests.
//
// llvmpipe's output can change a little between Mesa versions, so images are compared with a
// per-channel tolerance and a cap on the fraction of pixels allowed to differ. Goldens were made
// with Mesa 22.3 (llvmpipe, LP_NUM_THREADS=0), FreeType 2.12 and DejaVu 2.37 on Debian 12.
// To regenerate them: FROB_UPDATE_GOLDENS=1 ctest -R render_ (then look at them before committing).
// On a mismatch the actual image and a difference map are written to the build directory.

#include "frob/render/image.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace frob::render::testing {

inline constexpr int kChannelTolerance = 24;      // per colour channel, out of 255
inline constexpr double kMaxDifferingShare = 0.005;  // share of pixels allowed beyond the tolerance

inline ::testing::AssertionResult matchesGolden(const Image& actual, const std::string& name) {
  const std::string golden = std::string(FROB_GOLDEN_DIR) + "/" + name + ".png";
  const std::string actualPath = std::string(FROB_ACTUAL_DIR) + "/" + name + ".png";
  std::filesystem::create_directories(FROB_ACTUAL_DIR);
  if (const char* update = std::getenv("FROB_UPDATE_GOLDENS"); update != nullptr && update[0] != '\0' && update[0] != '0') {
    if (Status s = writePng(golden, actual); !s) return ::testing::AssertionFailure() << s.error();
    return ::testing::AssertionSuccess() << "golden regenerated: " << golden;
  }
  Result<Image> expected = readPng(golden);
  if (!expected) {
    (void)writePng(actualPath, actual);
    return ::testing::AssertionFailure() << expected.error() << "\n  actual image: " << actualPath
                                         << "\n  (run with FROB_UPDATE_GOLDENS=1 to create it)";
  }
  const Image& e = expected.value();
  if (e.width != actual.width || e.height != actual.height) {
    (void)writePng(actualPath, actual);
    return ::testing::AssertionFailure() << "size " << actual.width << "x" << actual.height << " differs from golden "
                                         << e.width << "x" << e.height << "\n  actual image: " << actualPath;
  }
  Image diff = actual;
  long differing = 0;
  int worst = 0;
  for (std::size_t i = 0; i < actual.rgba.size(); i += 4) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(actual.rgba[i + c]) - int(e.rgba[i + c])));
    worst = std::max(worst, d);
    const bool bad = d > kChannelTolerance;
    differing += bad ? 1 : 0;
    diff.rgba[i] = bad ? 255 : static_cast<std::uint8_t>(actual.rgba[i] / 4);
    diff.rgba[i + 1] = diff.rgba[i + 2] = static_cast<std::uint8_t>(actual.rgba[i + 1] / 4);
    diff.rgba[i + 3] = 255;
  }
  const double share = static_cast<double>(differing) / (actual.width * actual.height);
  if (share > kMaxDifferingShare) {
    (void)writePng(actualPath, actual);
    const std::string diffPath = std::string(FROB_ACTUAL_DIR) + "/" + name + ".diff.png";
    (void)writePng(diffPath, diff);
    return ::testing::AssertionFailure() << share * 100 << "% of pixels differ from " << golden << " by more than "
                                         << kChannelTolerance << " (limit " << kMaxDifferingShare * 100
                                         << "%, worst " << worst << ")\n  actual image: " << actualPath
                                         << "\n  difference (red): " << diffPath;
  }
  return ::testing::AssertionSuccess();
}

}  // namespace frob::render::testing
