#pragma once
// Golden-image comparison for render tests.
//
// Goldens were made on Debian 12 with FreeType 2.12 and DejaVu 2.37: the top-down and plot goldens
// by the CPU rasterizer, the chase golden by Mesa 22.3 (llvmpipe, LP_NUM_THREADS=0). How far an
// image may stray from its golden depends on what drew it (see Tolerance); the goldens see a whole
// image, the probes in features_test.cpp see each drawn feature.
// To regenerate them: FROB_UPDATE_GOLDENS=1 ctest -R 'Match(es)?Golden'; every rewritten golden fails
// its test with "golden rewritten, review and commit it", then look at them before committing.
// On a mismatch the actual image and a difference map are written to the build directory.

#include "frob/render/image.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace frob::render::testing {

// How far an image may differ from its golden: pixels differing by more than `channel` (in any
// colour channel, out of 255) count as differing, and at most `pixels` of them may.
struct Tolerance {
  int channel;
  long pixels;
};

// The top-down view and plots: our own CPU rasterizer draws every triangle (no antialiasing,
// -ffp-contract=off), so the same build gives the same pixels. 4 levels absorb a blend rounding
// its other way; 8 pixels a few glyph-edge pixels. That is far below what any drawn feature
// covers (the smallest, a heading tick, is about 35 pixels in a 320 x 240 frame) and below the
// faintest one's contrast (a sonar cone with no echo: 5% of the robot's colour, about 10 levels).
// A FreeType or DejaVu update moves text more than that: regenerate, and look.
inline constexpr Tolerance kCpuRaster{.channel = 4, .pixels = 8};
// The chase view: llvmpipe's rasterization rules and interpolation can move an edge by a pixel
// between Mesa versions. 80 pixels (0.1% of a 320 x 240 frame) is one pixel along the edges of a
// wall or two; the robot model alone covers thousands.
inline constexpr Tolerance kLlvmpipe{.channel = 24, .pixels = 80};

// `actual` compared with the PNG `golden`; on a mismatch the actual image and a difference map go
// to `actualDir`. With FROB_UPDATE_GOLDENS set (and not "0") the golden is rewritten and the
// comparison fails, so that a stray variable can never turn a run green.
inline ::testing::AssertionResult matchesGoldenFile(const Image& actual, const std::string& golden, const std::string& actualDir, Tolerance tol) {
  namespace fs = std::filesystem;
  const std::string stem = fs::path(golden).stem().string();
  const std::string actualPath = actualDir + "/" + stem + ".png";
  fs::create_directories(actualDir);
  if (const char* update = std::getenv("FROB_UPDATE_GOLDENS"); update != nullptr && update[0] != '\0' && update[0] != '0') {
    if (Status s = writePng(golden, actual); !s) return ::testing::AssertionFailure() << s.error();
    return ::testing::AssertionFailure() << "golden rewritten, review and commit it: " << golden;
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
    return ::testing::AssertionFailure() << "size " << actual.width << "x" << actual.height << " differs from golden " << e.width << "x" << e.height
                                         << "\n  actual image: " << actualPath;
  }
  Image diff = actual;
  long differing = 0;
  int worst = 0;
  for (std::size_t i = 0; i < actual.rgba.size(); i += 4) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(actual.rgba[i + c]) - int(e.rgba[i + c])));
    worst = std::max(worst, d);
    const bool bad = d > tol.channel;
    differing += bad ? 1 : 0;
    diff.rgba[i] = bad ? 255 : static_cast<std::uint8_t>(actual.rgba[i] / 4);
    diff.rgba[i + 1] = diff.rgba[i + 2] = static_cast<std::uint8_t>(actual.rgba[i + 1] / 4);
    diff.rgba[i + 3] = 255;
  }
  if (differing > tol.pixels) {
    (void)writePng(actualPath, actual);
    const std::string diffPath = actualDir + "/" + stem + ".diff.png";
    (void)writePng(diffPath, diff);
    return ::testing::AssertionFailure() << differing << " pixels differ from " << golden << " by more than " << tol.channel << " (limit "
                                         << tol.pixels << ", worst " << worst << ")\n  actual image: " << actualPath
                                         << "\n  difference (red): " << diffPath;
  }
  return ::testing::AssertionSuccess();
}

// `actual` compared with tests/render/golden/`name`.png.
inline ::testing::AssertionResult matchesGolden(const Image& actual, const std::string& name, Tolerance tol = kCpuRaster) {
  return matchesGoldenFile(actual, std::string(FROB_GOLDEN_DIR) + "/" + name + ".png", FROB_ACTUAL_DIR, tol);
}

}  // namespace frob::render::testing
