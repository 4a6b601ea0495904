#include "frob/picture.hpp"

#include "frob/sampling.hpp"

#include <gtest/gtest.h>

namespace frob {
namespace {

using namespace literals;

TEST(Picture, PaintAtMovesEveryPoint) {
  Picture p = paintAt({2, 3}, circle(10_cm) + line({0, 0}, {1, 0}));
  ASSERT_EQ(p.shapes().size(), 2u);
  EXPECT_EQ(p.shapes()[0].points[0], Point2(2, 3));
  EXPECT_DOUBLE_EQ(p.shapes()[0].radius, 0.1);
  EXPECT_EQ(p.shapes()[1].points[1], Point2(3, 3));
}

TEST(Picture, InnerColourWins) {
  Picture p = withColor(blue, withColor(red, circle(1)) + text("goal"));
  ASSERT_EQ(p.shapes().size(), 2u);
  EXPECT_EQ(p.shapes()[0].color, red);
  EXPECT_EQ(p.shapes()[1].color, blue);
}

TEST(Picture, OverlayKeepsOrderBackToFront) {
  Picture p = disc(1) + arrow({0, 0}, {1, 1});
  p += polygon({{0, 0}, {1, 0}, {0, 1}});
  ASSERT_EQ(p.shapes().size(), 3u);
  EXPECT_EQ(p.shapes()[0].kind, Shape::Kind::Disc);
  EXPECT_EQ(p.shapes()[1].kind, Shape::Kind::Arrow);
  EXPECT_EQ(p.shapes()[2].kind, Shape::Kind::Polygon);
  EXPECT_TRUE(emptyPicture().empty());
}

// Issue 15: a picture that follows a moving point, such as the robot's place.
TEST(Picture, PaintAtABehaviorMovesThePictureWithIt) {
  Behavior<Point2> at = lift([](double t) { return Point2{t, 2 * t}; }, time());
  std::vector<Picture> p = sample(paintAt(at, circle(10_cm)), 0.5, 2);
  EXPECT_EQ(p[0].shapes()[0].points[0], Point2(0, 0));
  EXPECT_EQ(p[1].shapes()[0].points[0], Point2(0.5, 1.0));
}

}  // namespace
}  // namespace frob
