// The messages a host sends: each comes back as it was written, and each cap of a step and of a
// run fails a reply that breaks it, naming the cap.
#include "frob/sandbox/wire.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace frob::sandbox {
namespace {

TaskRecord started(std::int64_t id, std::string name = "t") { return {.id = id, .name = std::move(name), .where = "here:1", .start = 0.5}; }

TaskRecord ended(std::int64_t id) { return {.id = id, .how = TaskEnd::Returned, .detail = "done"}; }

// Writes `reply` framed into an area of `bytes` and reads it back; the failure's reason, or "".
std::string roundTrip(const StepReply& reply, StepReply& back, std::size_t bytes = 1 << 20) {
  std::vector<std::byte> area(bytes), copy;
  writeFramed(area, reply);
  const Status s = readFramed(area, copy, back);
  return s ? "" : s.error();
}

TEST(Wire, EveryStateComesBack) {
  for (const auto state : {StepReply::State::Running, StepReply::State::FailedNow, StepReply::State::FailedBefore, StepReply::State::Done}) {
    StepReply back;
    ASSERT_EQ(roundTrip({.state = state}, back), "");
    EXPECT_EQ(back.state, state);
  }
}

TEST(Wire, AStepReplyComesBackAsItWasWritten) {
  StepReply reply{.state = StepReply::State::FailedNow,
                  .wheels = {0.25, -0.5},
                  .failure = "it threw",
                  .records = {started(0), ended(0)},
                  .hasPicture = true,
                  .picture = Picture({Shape{.kind = Shape::Kind::Value, .text = "left", .value = 0.4, .color = Color{1, 0, 0, 1}}})};
  StepReply back;
  ASSERT_EQ(roundTrip(reply, back), "");
  EXPECT_EQ(back.state, reply.state);
  EXPECT_EQ(back.wheels, reply.wheels);
  EXPECT_EQ(back.failure, "it threw");
  ASSERT_EQ(back.records.size(), 2u);
  EXPECT_EQ(back.records[0].name, "t");
  EXPECT_EQ(back.records[1].how, TaskEnd::Returned);
  EXPECT_EQ(back.records[1].detail, "done");
  EXPECT_EQ(back.picture, reply.picture);
}

TEST(Wire, ALoadReplyAndABuildRequestComeBackAsTheyWereWritten) {
  std::vector<std::byte> area(1 << 16);
  const LoadReply load{.seccomp = {"seccomp", true, true, "no sockets"},
                       .modules = {{.loaded = true, .name = "wander", .world = "lounge", .summary = "wanders", .seconds = 30}, {.error = "bad ELF"}}};
  ASSERT_TRUE(writeFramed(area, load));
  LoadReply loadBack;
  std::vector<std::byte> copy;
  const Status framed = readFramed(area, copy, loadBack);
  ASSERT_TRUE(framed) << framed.error();
  std::uint32_t length = 0;
  std::memcpy(&length, area.data(), sizeof length);
  EXPECT_EQ(copy.size(), length);  // only the answer is copied, not its whole area
  EXPECT_LT(length, 200u);
  EXPECT_EQ(loadBack.seccomp.note, "no sockets");
  ASSERT_EQ(loadBack.modules.size(), 2u);
  EXPECT_EQ(loadBack.modules[0].world, "lounge");
  EXPECT_EQ(loadBack.modules[0].seconds, 30.0);
  EXPECT_FALSE(loadBack.modules[1].loaded);
  EXPECT_EQ(loadBack.modules[1].error, "bad ELF");
  const std::uint32_t past = static_cast<std::uint32_t>(area.size()) - 3;  // a length the area cannot hold
  std::memcpy(area.data(), &past, sizeof past);
  EXPECT_EQ(readFramed(area, copy, loadBack).error(), "a reply longer than its area");

  BuildRequest build{.robots = {{.module = 1, .spec = {.radius = 0.25, .sonarAngles = {0.0, 1.0}}}}};
  Writer wb(area);
  write(wb, build);
  BuildRequest buildBack;
  Reader rb(area);
  ASSERT_TRUE(read(rb, buildBack)) << rb.why();
  ASSERT_EQ(buildBack.robots.size(), 1u);
  EXPECT_EQ(buildBack.robots[0].module, 1u);
  EXPECT_EQ(buildBack.robots[0].spec.sonarAngles, (std::vector<double>{0.0, 1.0}));
}

TEST(Wire, TheHostCutsLongStringsToTheirCapsAndTheReplyStillReads) {
  StepReply reply{.records = {started(0, std::string(10'000, 'n'))}};
  StepReply back;
  ASSERT_EQ(roundTrip(reply, back), "");
  EXPECT_EQ(back.records[0].name.size(), kNameBytes);
}

// Bytes a hostile host wrote: a reply whose strings and counts it chose.
std::vector<std::byte> forged(std::uint32_t records, std::uint32_t nameBytes) {
  std::vector<std::byte> area(1 << 20);
  Writer w(std::span(area).subspan(4));
  w.put(std::uint8_t{0}), w.put(0.1), w.put(0.0), w.put(records);
  for (std::uint32_t k = 0; k < std::min(records, 4u); ++k) {
    w.put(std::int64_t{k}), w.put(std::int64_t{-1}), w.put(0);
    w.put(nameBytes);
    for (std::uint32_t b = 0; b < nameBytes; ++b) w.put('x');
    w.put(std::string_view("here"), 64), w.put(0.5), w.put(0.0), w.put(std::uint8_t{0}), w.put(std::string_view(), 64);
  }
  w.put(std::uint8_t{0});
  const auto length = static_cast<std::uint32_t>(w.size());
  std::memcpy(area.data(), &length, 4);
  return area;
}

std::string readForged(const std::vector<std::byte>& area) {
  std::vector<std::byte> copy;
  StepReply reply;
  const Status s = readFramed(area, copy, reply);
  return s ? "" : s.error();
}

TEST(Wire, AReplyPastACapOfAStepFailsWithTheCapNamed) {
  EXPECT_EQ(readForged(forged(1, kNameBytes)), "");
  EXPECT_EQ(readForged(forged(1, kNameBytes + 1)), "a task's name longer than 256 bytes");
  EXPECT_EQ(readForged(forged(kRecordsPerStep + 1, 1)), "more than 4096 task starts and ends in one step");
  std::vector<std::byte> cut = forged(1, 100);
  const std::uint32_t shorter = 40;  // the name's length says 100 bytes; the reply ends before them
  std::memcpy(cut.data(), &shorter, 4);
  EXPECT_EQ(readForged(cut), "it ends too soon");
  std::vector<std::byte> tooLong = forged(1, 1);
  const std::uint32_t past = (1 << 20) - 3;
  std::memcpy(tooLong.data(), &past, 4);
  EXPECT_EQ(readForged(tooLong), "a reply longer than its area");
  std::vector<std::byte> badState = forged(1, 1);
  badState[4] = std::byte{4};  // one past Done, the last
  EXPECT_EQ(readForged(badState), "a controller state of no known kind");
}

TEST(Wire, ARunBudgetKeepsTasksInOrderAndBounded) {
  RunBudget budget;
  EXPECT_TRUE(budget.take({.records = {started(0), started(1), ended(0)}}).ok());
  EXPECT_EQ(budget.take({.records = {started(5)}}).error(), "started a task out of order");
  RunBudget other;
  EXPECT_EQ(other.take({.records = {ended(3)}}).error(), "ended a task that was not running");

  RunBudget open;
  std::int64_t id = 0;
  for (std::uint32_t step = 0; step < kOpenTasks / 1024; ++step) {
    StepReply reply;
    for (int k = 0; k < 1024; ++k) reply.records.push_back(started(id++));
    ASSERT_TRUE(open.take(reply).ok());
  }
  EXPECT_EQ(open.take({.records = {started(id)}}).error(), "more than 4096 tasks running at once");
  EXPECT_TRUE(open.take({.records = {ended(0)}}).ok());
  EXPECT_TRUE(open.take({.records = {started(id)}}).ok());  // room again once one ended
}

TEST(Wire, ARunBudgetBoundsPlottedNamesAndBytes) {
  RunBudget plots;
  for (std::uint32_t k = 0; k < kPlotNames; ++k) {
    const Picture p({Shape{.kind = Shape::Kind::Value, .text = "v" + std::to_string(k)}, Shape{.kind = Shape::Kind::Value, .text = "v0"}});
    ASSERT_TRUE(plots.take({.hasPicture = true, .picture = p}).ok()) << k;
  }
  EXPECT_EQ(plots.take({.hasPicture = true, .picture = Picture({Shape{.kind = Shape::Kind::Value, .text = "one more"}})}).error(),
            "more than 64 names of plotted values");

  RunBudget bytes;
  const Picture big({Shape{.kind = Shape::Kind::Polyline, .points = std::vector<Point2>(kPointsPerShape)}});
  Status s;
  std::uint64_t steps = 0;
  for (; s.ok() && steps < 100'000; ++steps) s = bytes.take({.hasPicture = true, .picture = big});
  EXPECT_EQ(s.error(), "more than 256 MB of task records and pictures in one run");
  EXPECT_EQ(steps, kRunBytes / (sizeof(Shape) + kPointsPerShape * sizeof(Point2)) + 1);
}

}  // namespace
}  // namespace frob::sandbox
