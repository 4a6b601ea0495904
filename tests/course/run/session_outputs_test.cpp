// The files of a run: the timeline's tracks nest tasks properly (so Perfetto draws them), CSV cells
// are quoted when they must be, and a frame folder made for a run goes away with its frames.
#include "session_outputs.hpp"

#include "frob/render/image.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

TaskRecord task(std::int64_t id, std::int64_t parent, std::string name, double start, double end) {
  return {.id = id, .parent = parent, .name = std::move(name), .start = start, .end = end, .how = TaskEnd::Returned};
}

TEST(Timeline, OverlappingTasksGetTracksOfTheirOwn) {
  const fs::path path = fs::path(::testing::TempDir()) / "timeline.json";
  // main holds drive then turn in sequence; watch runs beside them (withTask), overlapping both.
  const std::vector<TaskRecord> records{task(1, 0, "drive", 0, 4), task(3, 0, "watch", 2, 6), task(2, 0, "turn", 4, 10), task(0, -1, "main", 0, 10)};
  ASSERT_TRUE(writeTimeline(path.string(), {"bug"}, {records}).ok());
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(path));
  std::map<std::string, int> track;
  std::map<std::string, std::pair<long, long>> span;
  for (const nlohmann::json& e : doc["traceEvents"]) {
    if (e["ph"] == "M") {
      EXPECT_EQ(e["args"]["name"], "bug");
      continue;
    }
    track[e["name"]] = e["tid"];
    span[e["name"]] = {e["ts"], e["dur"]};
  }
  EXPECT_EQ(track, (std::map<std::string, int>{{"main", 0}, {"drive", 0}, {"turn", 0}, {"watch", 1}}));
  EXPECT_EQ(span["turn"], (std::pair<long, long>{4'000'000, 6'000'000}));  // microseconds of simulated time
}

// withPicture(curve) and the curve it wraps start and end together: the wrapper comes first, so that
// Perfetto (which nests equal spans in their order) draws it outside; a name that is not UTF-8 is
// written with U+FFFD, not refused.
TEST(Timeline, AWrapperWithTheSameSpanNestsOutsideWhatItWraps) {
  const fs::path path = fs::path(::testing::TempDir()) / "wrapped.json";
  TaskRecord inner = task(2, 1, "curve\xff", 1, 3), outer = task(1, 0, "withPicture(curve)", 1, 3), top = task(0, -1, "tour", 0, 5);
  inner.depth = 2, outer.depth = 1;
  ASSERT_TRUE(writeTimeline(path.string(), {"r"}, {{inner, outer, top}}).ok());
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(path));
  std::vector<std::string> order;
  for (const nlohmann::json& e : doc["traceEvents"]) {
    if (e["ph"] == "X") order.push_back(e["name"]);
  }
  EXPECT_EQ(order, (std::vector<std::string>{"tour", "withPicture(curve)", "curve\xEF\xBF\xBD"}));
}

TEST(Trace, TaskNamesWithCommasAreQuoted) {
  const fs::path path = fs::path(::testing::TempDir()) / "quoted.csv";
  fs::remove(path);
  Result<TraceFile> t = TraceFile::open(path.string(), 2);
  ASSERT_TRUE(t.ok()) << t.error();
  worlds::RobotRecord rec{.wheels = {0.25, -1.5}, .sonar = {1.0, 6.5}, .bumps = {{.bumper = 2, .angle = 0.5}}};
  t.value().row(0.01, 0, rec, "withB<\"a\", b>");
  EXPECT_FALSE(fs::exists(path));  // nothing under the name until complete
  ASSERT_TRUE(t.value().commit().ok());
  std::ifstream in(path);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header, "time,robot,true_x,true_y,true_heading,odom_x,odom_y,odom_heading,forward,turn,s0,s1,bumper,task");
  EXPECT_EQ(row, "0.01,0,0,0,0,0,0,0,0.25,-1.5,1,6.5,0.5,\"withB<\"\"a\"\", b>\"");
}

TEST(Trace, UncommittedFileLeavesNothing) {
  const fs::path path = fs::path(::testing::TempDir()) / "dropped.csv";
  fs::remove(path);
  {
    Result<TraceFile> t = TraceFile::open(path.string(), 16);
    ASSERT_TRUE(t.ok());
    t.value().row(0, 0, {}, "x");
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path.string() + ".partial"));
}

TEST(Frames, DiscardRemovesTheFolderItMade) {
  const fs::path dir = fs::path(::testing::TempDir()) / "frames_made";
  fs::remove_all(dir);
  Result<FrameFolder> f = FrameFolder::open(dir.string());
  ASSERT_TRUE(f.ok()) << f.error();
  render::Image image{.width = 2, .height = 2, .rgba = std::vector<std::uint8_t>(16, 255)};
  ASSERT_TRUE(f.value().write(image).ok());
  ASSERT_TRUE(f.value().write(image).ok());
  EXPECT_TRUE(fs::exists(dir / "frame_000001.png"));
  f.value().discard();
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace frob::course
