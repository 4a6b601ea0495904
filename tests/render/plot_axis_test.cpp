// Plot axes read as numbers: the value range widened to two significant digits, noise round 0 as 0.
#include "draw.hpp"

#include <gtest/gtest.h>

namespace frob::render::detail {
namespace {

TEST(PlotAxis, RangesWidenToTwoSignificantDigits) {
  EXPECT_EQ(niceRange(0.0, 16.3), (std::pair{0.0, 17.0}));
  EXPECT_EQ(tick(niceRange(0.0, 0.915).second), "0.92");
  EXPECT_EQ(tick(niceRange(-1.0, 0.915).second), "1");
  EXPECT_EQ(tick(niceRange(0.31, 6.5).first), "0.3");
}

// A wheel speed that settles at rounding noise below 0 gave the label "-6.61e-07".
TEST(PlotAxis, NoiseRoundZeroIsZero) {
  const auto [lo, hi] = niceRange(-6.61e-07, 0.6);
  EXPECT_EQ(tick(lo), "0");
  EXPECT_EQ(tick(hi), "0.6");
}

TEST(PlotAxis, AFlatOrEmptyRangeIsLeftAlone) { EXPECT_EQ(niceRange(2.0, 2.0), (std::pair{2.0, 2.0})); }

}  // namespace
}  // namespace frob::render::detail
