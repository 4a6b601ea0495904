// Helpers on FrameScene values.
#include "frob/render/scene.hpp"

#include <gtest/gtest.h>

namespace frob::render {
namespace {

TEST(Scene, FrontSonarIsTheOneClosestToStraightAhead) {
  RobotSpec spec;
  EXPECT_EQ(frontSonarIndex(spec), -1);
  spec.sonarAngles = {pi / 2, -0.1, 0.3, pi};
  EXPECT_EQ(frontSonarIndex(spec), 1);
  spec.sonarAngles = {2 * pi - 0.05, 0.2};  // angles are wrapped
  EXPECT_EQ(frontSonarIndex(spec), 0);
}

}  // namespace
}  // namespace frob::render
