// The course target brings the whole stack and nlohmann::json for result files.
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace {

TEST(CourseDependencies, JsonRoundTripsAResult) {
  nlohmann::json result = {{"score", 7.5}, {"max_score", 10}, {"name", "reaches goal"}};
  auto back = nlohmann::json::parse(result.dump());
  EXPECT_DOUBLE_EQ(back["score"].get<double>(), 7.5);
  EXPECT_EQ(back["name"], "reaches goal");
}

}  // namespace
