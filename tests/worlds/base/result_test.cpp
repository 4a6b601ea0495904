// Result and Status: a value or a readable message, and asking a failure for its value is a
// programmer's mistake caught in every build (FROB_ASSERT), not a read of an empty optional.
#include "frob/base/result.hpp"

#include "frob/errors.hpp"

#include <gmock/gmock.h>

#include <string>

namespace frob {
namespace {

using ::testing::HasSubstr;

Result<int> half(int n) {
  if (n % 2 != 0) return Status::failure(std::to_string(n) + " is odd");
  return n / 2;
}

TEST(Result, HoldsAValueOrTheMessageOfWhyNot) {
  const Result<int> good = half(8);
  ASSERT_TRUE(good.ok());
  EXPECT_EQ(good.value(), 4);
  EXPECT_EQ(*good, 4);
  EXPECT_EQ(good.error(), "");
  const Result<int> bad = half(7);
  EXPECT_FALSE(bad.ok());
  EXPECT_EQ(bad.error(), "7 is odd");
  EXPECT_EQ(bad.status().error(), "7 is odd");
}

TEST(Result, TheValueOfAFailureIsAProgrammersMistake) {
  Result<int> bad = half(7);
  const Result<int>& constBad = bad;
  EXPECT_THROW((void)bad.value(), UsageError);
  EXPECT_THROW((void)constBad.value(), UsageError);
  EXPECT_THROW((void)*constBad, UsageError);
  try {
    (void)bad.value();
  } catch (const UsageError& e) {
    EXPECT_THAT(e.what(), HasSubstr("the value of a failed Result was asked for"));
  }
}

TEST(Result, IsNeverMadeFromASuccess) { EXPECT_THROW(Result<int>{Status{}}, UsageError); }

TEST(Status, IsSuccessUnlessItFailed) {
  EXPECT_TRUE(Status{}.ok());
  EXPECT_EQ(Status{}.error(), "");
  const Status failed = Status::failure("no such file");
  EXPECT_FALSE(failed);
  EXPECT_EQ(failed.error(), "no such file");
  EXPECT_FALSE(Status::failure("").ok());  // a failure without words is still a failure
}

}  // namespace
}  // namespace frob
