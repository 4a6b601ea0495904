// runSession: the run loop behind `frob run`: when a run ends, what the summary says, and that the
// trace holds exactly the recorded values. (The files' atomicity is tested end to end in tests/app.)
#include "frob/run/session.hpp"

#include "frob/frob.hpp"
#include "frob/render/image.hpp"
#include "frob/run/summary.hpp"
#include "frob/worlds/world_file.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace frob::course {
namespace {

namespace fs = std::filesystem;
using namespace frob::literals;

// A 6 x 3 m room with a goal 2 m ahead of the robot; its wheels do not slip and it starts exactly
// at its start, so that distances and times are the commanded ones.
worlds::WorldDef room() {
  return *worlds::parseWorld(R"(size = [6.0, 3.0]
seed = 5
[points]
goal = [3.0, 1.5]
[[robot]]
name = "r"
start = [1.0, 1.5]
drive = { slip = 0 }
start_spread = { position = 0, heading_deg = 0 }
)",
                             "room.toml");
}

LoadedController inlineController(Controller make) { return {.entry = {.name = "inline", .make = std::move(make)}, .source = "test"}; }

// Forward at 0.5 m/s until `seconds` have passed, then the task returns.
Task<Wheels> forwardFor(double seconds) {
  return mkTask([seconds](const TaskState&) { return std::pair{wheels(0.5, 0.0), after(seconds)}; });
}

// A file's whole text.
std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A path in the temp folder with nothing there (left over from an earlier run).
fs::path tempPath(const std::string& name) {
  const fs::path path = fs::path(::testing::TempDir()) / name;
  fs::remove(path);
  return path;
}

TEST(Session, EndsWhenTheControllerTaskReturns) {
  Result<Summary> s = runSession(
      {.world = room(), .worldName = "room", .controllers = {inlineController(makeController([] { return forwardFor(1.5); }))}, .seconds = 10});
  ASSERT_TRUE(s.ok()) << s.error();
  const RobotSummary& r = s.value().robots.at(0);
  ASSERT_TRUE(r.finishedAt.has_value());
  EXPECT_DOUBLE_EQ(*r.finishedAt, 1.5);
  EXPECT_EQ(s.value().steps, 151);  // steps 0..150: the task returns at the instant of step 150
  ASSERT_EQ(r.lastTasks.size(), 1u);
  EXPECT_EQ(r.lastTasks[0].how, TaskEnd::Returned);
}

// A behavior that runs a task and drives on after it is never done: its run goes the whole time.
TEST(Session, ABehaviorThatGoesOnAfterItsTaskRunsTheWholeTime) {
  const auto goesOn = [](const Robot& r) { return runTask(TaskState(r), forwardFor(1.5), Behavior<Wheels>(Wheels{0.2, 0.0})); };
  Result<Summary> s = runSession({.world = room(), .worldName = "room", .controllers = {inlineController(goesOn)}, .seconds = 3});
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(s.value().steps, 300);
  EXPECT_FALSE(s.value().robots.at(0).finishedAt.has_value());
}

// After the last task returns, a settle time: the run goes on with the robot commanded still, so that
// "stands still 2 s after" can be seen; the summary says when the tasks had all returned.
TEST(Session, ASettleTimeKeepsTheRunGoingWithTheRobotStill) {
  Result<Summary> s = runSession({.world = room(),
                                  .worldName = "room",
                                  .controllers = {inlineController(makeController([] { return forwardFor(1.5); }))},
                                  .seconds = 10,
                                  .settleSeconds = 2.0,
                                  .keepRecord = true});
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(s.value().steps, 350);  // its task returned at the instant of step 150; then 2 s
  EXPECT_NEAR(s.value().settledSeconds, 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(s.value().robots.at(0).finishedAt.value(), 1.5);
  const std::vector<Point2>& path = s.value().record->robots.at(0).path;
  ASSERT_EQ(path.size(), 351u);
  EXPECT_GT((path[200] - path[151]).norm(), 0.01);  // it coasts to a stop (the drive's deceleration)
  EXPECT_LT((path[350] - path[250]).norm(), 1e-6);  // and stands still for the last second
  EXPECT_NE(formatSummary(s.value(), 0.0).find("every task had returned at 1.50 s: the robots were commanded still for the last 2.00 s\n"),
            std::string::npos)
      << formatSummary(s.value(), 0.0);
}

// The settle time is shown in the frames too: a line under the time in the HUD, whose dark box
// is one text line taller once every task has returned.
TEST(Session, TheFramesSayWhenTheRobotsAreCommandedStill) {
  const fs::path frames = fs::path(::testing::TempDir()) / "settle_frames";
  fs::remove_all(frames);
  Result<Summary> s = runSession({.world = room(),
                                  .worldName = "room",
                                  .controllers = {inlineController(makeController([] { return forwardFor(1.0); }))},
                                  .seconds = 10,
                                  .settleSeconds = 1.0,
                                  .outputs = {.frames = frames.string()},
                                  .fps = 10});
  ASSERT_TRUE(s.ok()) << s.error();
  // Rows of the HUD's box down its left edge (black at 62% over the world: every channel dark).
  const auto hudRows = [&](int frame) {
    const Result<render::Image> img =
        render::readPng((frames / ("frame_" + std::string(6 - std::to_string(frame).size(), '0') + std::to_string(frame) + ".png")).string());
    EXPECT_TRUE(img.ok()) << img.error();
    int rows = 0;
    for (int y = 8; img.ok() && y < img.value().height; ++y, ++rows) {
      const std::uint8_t* p = img.value().pixel(8, y);
      if (p[0] > 120 || p[1] > 120 || p[2] > 120) break;
    }
    return rows;
  };
  const int before = hudRows(5), settling = hudRows(15);  // at 0.5 s, driving; at 1.5 s, settling
  EXPECT_GT(before, 20);
  EXPECT_GE(settling - before, 10) << "no line was added for the settle time";
  EXPECT_LE(settling - before, 30);
}

// Frames are drawn after the last step, never between steps: a filmed run paces its controllers as
// an unfilmed (graded) one does, so that a controller cannot tell the two apart by the time between
// its steps. Every frame is still drawn, and said as drawn.
TEST(Session, FramesAreDrawnOnlyOnceTheRunIsOver) {
  const fs::path frames = fs::path(::testing::TempDir()) / "frames_after_the_run";
  fs::remove_all(frames);
  std::size_t filesDuringRun = 0, steps = 0, drawn = 0, total = 0;
  bool drawingBeforeStep = false;
  Result<Summary> s = runSession({.world = room(),
                                  .worldName = "room",
                                  .controllers = {inlineController(makeController([] { return forwardFor(1.0); }))},
                                  .seconds = 2,
                                  .wholeTime = true,
                                  .outputs = {.frames = frames.string()},
                                  .fps = 10,
                                  .progress =
                                      [&](double) {
                                        ++steps;
                                        drawingBeforeStep = drawingBeforeStep || drawn > 0;
                                        std::error_code ec;
                                        for (auto it = fs::directory_iterator(frames, ec); !ec && it != fs::directory_iterator(); ++it)
                                          ++filesDuringRun;
                                      },
                                  .drawing =
                                      [&](std::size_t k, std::size_t n) {
                                        EXPECT_EQ(k, drawn + 1);
                                        drawn = k, total = n;
                                      }});
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(steps, 200u);
  EXPECT_EQ(filesDuringRun, 0u) << "frames were written while the controller was still stepping";
  EXPECT_FALSE(drawingBeforeStep);
  EXPECT_EQ(drawn, 20u);  // 2 s at 10 frames a second
  EXPECT_EQ(total, 20u);
  EXPECT_EQ(static_cast<std::size_t>(std::distance(fs::directory_iterator(frames), fs::directory_iterator())), 20u);
}

// A video with a budget fits in it whatever the run's length: the bitrate is capped for the run's
// seconds (a grade report's film). Without one the same run takes several times as much.
TEST(Session, AVideoWithABudgetFitsInIt) {
  std::uintmax_t bytes[2] = {};
  for (std::uint64_t budget : {std::uint64_t{0}, std::uint64_t{60'000}}) {
    const fs::path video = tempPath(budget == 0 ? "free.mp4" : "budget.mp4");
    Result<Summary> s = runSession({.world = room(),
                                    .worldName = "room",
                                    .controllers = {inlineController(makeController([] { return forwardFor(20.0); }))},
                                    .seconds = 8,
                                    .wholeTime = true,
                                    .outputs = {.video = video.string(), .videoBytes = budget}});
    ASSERT_TRUE(s.ok()) << s.error();
    bytes[budget == 0 ? 0 : 1] = fs::file_size(video);
  }
  EXPECT_LE(bytes[1], 60'000u);
  EXPECT_GT(bytes[0], 2 * bytes[1]);
}

// The plot's time axis ends where the run ended (1.5 s), not at the run's limit (10 s): the forward
// speed, drawn in blue, reaches the right end of its chart.
TEST(Session, ThePlotEndsWhereTheRunEnded) {
  const fs::path plot = tempPath("session_plot_end.png");
  Result<Summary> s = runSession({.world = room(),
                                  .worldName = "room",
                                  .controllers = {inlineController(makeController([] { return forwardFor(1.5); }))},
                                  .seconds = 10,
                                  .outputs = {.plot = plot.string()}});
  ASSERT_TRUE(s.ok()) << s.error();
  Result<render::Image> img = render::readPng(plot.string());
  ASSERT_TRUE(img.ok()) << img.error();
  const render::Image& im = img.value();
  int rightmostBlue = 0;
  for (int y = im.height / 2; y < im.height; ++y) {  // the lower chart: wheels
    for (int x = 0; x < im.width; ++x) {
      const std::uint8_t* p = im.pixel(x, y);
      if (p[2] > p[0] + 80 && p[2] > p[1] + 40) rightmostBlue = std::max(rightmostBlue, x);
    }
  }
  EXPECT_GT(rightmostBlue, im.width * 9 / 10);
}

// Drives forward for 1 s publishing "left" (sonar 4) in orange: a colour no default chart uses, so
// orange pixels in the plot are the published value's chart.
Task<Wheels> publishesLeftInOrange() {
  TaskState ts = co_await getTaskState();
  co_await withPicture(lift([](double v) { return withColor(orange, plotValue("left", v)); }, sonar(ts.robot(), 4)), forwardFor(1.0));
}

// Drives forward for 1 s plotting its sonar 4 as "left".
Task<Wheels> plotsLeft() {
  TaskState ts = co_await getTaskState();
  co_await withPlot("left", sonar(ts.robot(), 4), forwardFor(1.0));
}

int orangePixels(const fs::path& png) {
  Result<render::Image> img = render::readPng(png.string());
  EXPECT_TRUE(img.ok()) << img.error();
  int n = 0;
  for (int y = 0; y < img.value().height; ++y) {
    for (int x = 0; x < img.value().width; ++x) {
      const std::uint8_t* p = img.value().pixel(x, y);
      n += p[0] > 200 && p[1] > 100 && p[1] < 170 && p[2] < 80 ? 1 : 0;
    }
  }
  return n;
}

TEST(Session, ThePlotChartsTheValuesTasksPublish) {
  const fs::path all = tempPath("session_plot_published.png"), others = tempPath("session_plot_not_published.png");
  for (const auto& [png, signals] : {std::pair{all, std::vector<std::string>{}}, {others, std::vector<std::string>{"s4"}}}) {
    Result<Summary> s = runSession({.world = room(),
                                    .worldName = "room",
                                    .controllers = {inlineController(makeController([] { return publishesLeftInOrange(); }))},
                                    .seconds = 10,
                                    .outputs = {.plot = png.string(), .plotSignals = signals}});
    ASSERT_TRUE(s.ok()) << s.error();
  }
  EXPECT_GT(orangePixels(all), 200);   // the chart of "left": a line across it and its legend
  EXPECT_EQ(orangePixels(others), 0);  // not asked for: --plot-signals s4 names sonar 4 only
}

TEST(Session, PlotSignalsNameSonarsInTheRingAndValuesThatWerePublished) {
  RunDef def{.world = room(), .worldName = "room", .controllers = {inlineController(nullptr)}, .seconds = 1, .outputs = {.plotSignals = {"s16"}}};
  EXPECT_EQ(validate(def).error(), "--plot-signals: there is no sonar s16: the ring has 16 (s0 to s15)");

  Result<Summary> s = runSession({.world = room(),
                                  .worldName = "room",
                                  .controllers = {inlineController(makeController([] { return plotsLeft(); }))},
                                  .seconds = 10,
                                  .outputs = {.plot = tempPath("session_plot_names.png").string(), .plotSignals = {"s4", "left", "right"}}});
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(s.value().notes, std::vector<std::string>{"--plot-signals: no task published 'right' (withPlot(\"right\", behavior, task))"});
}

TEST(Session, DistanceAndGoal) {
  Result<Summary> s = runSession(
      {.world = room(), .worldName = "room", .controllers = {inlineController([](const Robot&) { return wheels(0.5, 0.0); })}, .seconds = 4});
  ASSERT_TRUE(s.ok()) << s.error();
  const RobotSummary& r = s.value().robots.at(0);
  // 0.5 m/s reached after 0.5 s at 1 m/s^2: 0.125 m then 0.5 m/s for the remaining 3.49 s.
  EXPECT_NEAR(r.distance, 0.125 + 0.5 * 3.49, 0.01);
  // Within kGoalRadius once 1.5 m are covered: at 0.25 + 1.5 / 0.5 = 3.25 s.
  ASSERT_TRUE(r.goalTime.has_value());
  EXPECT_NEAR(*r.goalTime, 3.25, 0.02);
  EXPECT_NEAR(*r.goalDistance, 2.0 - r.distance, 0.01);
  EXPECT_EQ(r.collisions, 0);
  EXPECT_FALSE(s.value().failed());
}

// Parses the CSV written by a run into rows of numbers (empty cells and the task name dropped).
std::vector<std::vector<double>> numbers(const fs::path& csv, std::string& header, std::vector<std::string>& tasks) {
  std::ifstream in(csv);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    for (int column = 0; std::getline(cells, cell, ','); ++column) {
      double x = 0;
      if (std::from_chars(cell.data(), cell.data() + cell.size(), x).ec == std::errc() && !cell.empty())
        row.push_back(x);
      else if (column > 10 && !cell.empty())
        tasks.push_back(cell);
    }
    rows.push_back(row);
  }
  return rows;
}

TEST(Session, TraceHoldsTheRecordedValuesExactly) {
  const fs::path csv = tempPath("session_trace.csv");
  Controller c = makeController([] { return forwardFor(0.5); });
  Result<Summary> s =
      runSession({.world = room(), .worldName = "room", .controllers = {inlineController(c)}, .seconds = 1, .outputs = {.trace = csv.string()}});
  ASSERT_TRUE(s.ok()) << s.error();
  worlds::Run run(room(), {}, {c});
  run.runUntil(0.51);
  std::string header;
  std::vector<std::string> tasks;
  const auto rows = numbers(csv, header, tasks);
  EXPECT_EQ(header.substr(0, 49), "time,robot,true_x,true_y,true_heading,odom_x,odom");
  EXPECT_EQ(header.substr(header.size() - 20), ",s14,s15,bumper,task");
  ASSERT_EQ(rows.size(), run.recorder().steps().size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const worlds::StepRecord& rec = run.recorder().steps()[k];
    const worlds::RobotRecord& r = rec.robots[0];
    const std::vector<double> expected{rec.time,
                                       0,
                                       r.truePose.position.x(),
                                       r.truePose.position.y(),
                                       r.truePose.heading,
                                       r.odometry.position.x(),
                                       r.odometry.position.y(),
                                       r.odometry.heading,
                                       r.wheels.forward,
                                       r.wheels.turn};
    ASSERT_GE(rows[k].size(), 26u);
    EXPECT_EQ(std::vector<double>(rows[k].begin(), rows[k].begin() + 10), expected) << "row " << k;
    EXPECT_EQ(std::vector<double>(rows[k].begin() + 10, rows[k].begin() + 26), r.sonar) << "row " << k;
  }
  ASSERT_EQ(tasks.size(), rows.size() - 1);  // the task runs until the last instant, which has none
  EXPECT_EQ(tasks.front(), "forwardFor");

  // The run above gives the bits; these say, independently of the recorder, that each column holds
  // the quantity it names. The room: robot at (1, 1.5) heading 0, 0.23 m radius, the far wall at
  // x = 6; forwardFor(0.5) commands 0.5 m/s straight, reached at 1 m/s^2.
  ASSERT_EQ(rows.size(), 51u);  // instants 0, 0.01, ..., 0.5
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::vector<double>& row = rows[k];
    const double t = 0.01 * static_cast<double>(k);
    EXPECT_NEAR(row[0], t, 1e-12) << "time, row " << k;
    EXPECT_EQ(row[1], 0) << "robot, row " << k;
    // Accelerating for the whole half second (it reaches 0.5 m/s just as the task ends): x = t^2 / 2,
    // give or take a step of lag (0.01 m at most).
    EXPECT_NEAR(row[2], 1.0 + 0.5 * t * t, 0.01) << "true x, row " << k;
    EXPECT_NEAR(row[3], 1.5, 1e-9) << "true y, row " << k;
    EXPECT_NEAR(row[4], 0.0, 1e-9) << "true heading, row " << k;
    EXPECT_NEAR(row[5], row[2], 0.01) << "odometry x, row " << k;  // odometry drifts, but not in half a second
    EXPECT_NEAR(row[6], 1.5, 0.01) << "odometry y, row " << k;
    if (k < 50) EXPECT_EQ(std::vector<double>(row.begin() + 8, row.begin() + 10), (std::vector<double>{0.5, 0.0})) << "wheels, row " << k;
    // The sonar's noise is 1% of the range, about 0.05 m here: 0.25 m is five standard deviations.
    EXPECT_NEAR(row[10], 6.0 - row[2] - 0.23, 0.25) << "front sonar, row " << k;
  }
}

// frob run --assignment judges a check of S seconds on the first S seconds of a longer run: that cut
// must be the record of a run of S seconds, exactly. This robot meets the wall at about 2.5 s, pushes
// on until its task returns at 4 s, and stands there.
TEST(Session, ARecordCutToAChecksTimeIsTheRecordOfARunThatLong) {
  worlds::WorldDef world = room();
  world.robots.at(0).start.position = {4.5, 1.5};
  const auto record = [&](double seconds) {
    Result<Summary> s = runSession({.world = world,
                                    .worldName = "room",
                                    .controllers = {inlineController(makeController([] { return forwardFor(4.0); }))},
                                    .seconds = seconds,
                                    .wholeTime = true,
                                    .keepRecord = true});
    EXPECT_TRUE(s.ok()) << s.error();
    return s.value().record.value();
  };
  const RunRecord whole = record(6.0);
  const Track& all = whole.robots.at(0);
  ASSERT_FALSE(all.contacts.empty());
  ASSERT_FALSE(all.touching.empty());
  EXPECT_EQ(all.returned, "");             // a task of no value returned, and was heard of
  EXPECT_DOUBLE_EQ(all.returnedAt, 4.01);  // after the step that followed its instant
  EXPECT_EQ(all.path.size(), 601u);
  for (double seconds : {2.0, 3.0, 4.0, 5.0}) {
    SCOPED_TRACE(seconds);
    const Track cut = whole.upTo(seconds).robots.at(0);
    const Track ran = record(seconds).robots.at(0);
    EXPECT_EQ(cut.path, ran.path);
    EXPECT_EQ(cut.heading, ran.heading);
    EXPECT_EQ(cut.contacts, ran.contacts);
    EXPECT_EQ(cut.touching, ran.touching);
    EXPECT_EQ(cut.returned, ran.returned);
    EXPECT_EQ(cut.returnedAt, ran.returnedAt);
  }
  EXPECT_TRUE(whole.upTo(2.0).robots.at(0).touching.empty());  // the wall is met later
}

TEST(Session, FailingControllerWritesNothing) {
  const fs::path csv = tempPath("session_fail.csv"), json = tempPath("session_fail.json");
  Controller c = [](const Robot&) { return lift([](double t) { return t < 0.3 ? Wheels{0.1, 0} : throw RoboErr("gave up"); }, time()); };
  Result<Summary> s = runSession({.world = room(),
                                  .worldName = "room",
                                  .controllers = {inlineController(c)},
                                  .seconds = 2,
                                  .outputs = {.trace = csv.string(), .timeline = json.string()}});
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_TRUE(s.value().failed());
  EXPECT_NE(s.value().robots[0].failure.find("gave up"), std::string::npos) << s.value().robots[0].failure;
  EXPECT_NEAR(s.value().simulatedSeconds, 0.31, 1e-9);  // stopped after the failing step
  EXPECT_TRUE(s.value().written.empty());
  EXPECT_FALSE(fs::exists(csv));
  EXPECT_FALSE(fs::exists(csv.string() + ".partial"));
  EXPECT_FALSE(fs::exists(json));
}

// On amd64, whose bits the graders' are, nothing is said; on another machine, that its runs are not
// the grader's to the last bit, why, and what gives the grader's.
TEST(Session, OffAmd64ARunSaysItIsNotTheGradersToTheLastBit) {
  EXPECT_EQ(determinismNote("x86_64"), "");
  const std::string arm = determinismNote("aarch64");
  EXPECT_EQ(arm.rfind("frob: note: on aarch64 the simulator's floating point is not amd64's", 0), 0u) << arm;
  EXPECT_NE(arm.find("fused multiply-adds"), std::string::npos);
  EXPECT_NE(arm.find("run the amd64 image"), std::string::npos);
}

// A compile's time said truly: on a busy machine the wait is named as a wait, not the compile's cost.
TEST(Session, ACompileOnABusyMachineSaysWhatWasWaiting) {
  EXPECT_EQ(compiledNote("mine.cpp", false, 1.2, 1.1), "frob: compiled mine.cpp in 1.2 s\n");
  EXPECT_EQ(compiledNote("mine.cpp", true, 3.0, 1.0), "frob: compiled mine.cpp with checks in 3.0 s\n");
  EXPECT_EQ(compiledNote("mine.cpp", true, 43.2, 6.3),
            "frob: compiled mine.cpp with checks in 43.2 s (the compiler worked 6.3 s of it; the rest it waited for a busy machine)\n");
}

TEST(Session, ValidateNamesTheProblem) {
  RunDef def{.world = room(), .worldName = "room", .controllers = {}, .seconds = 1};
  EXPECT_EQ(validate(def).error(), "no controller given");
  def.controllers = {inlineController(nullptr), inlineController(nullptr)};
  EXPECT_EQ(validate(def).error(), "the world 'room' has 1 robots: give one controller for all of them or one per robot (2 given)");
  def.controllers.pop_back();
  def.seconds = -1;
  EXPECT_EQ(validate(def).error(), "--seconds must be a positive number of seconds");
}

// A world with no robot would run for one step and say nothing: it is refused, saying how to add one.
TEST(Session, AWorldWithNoRobotIsRefused) {
  RunDef def{.world = *worlds::parseWorld("size = [6.0, 3.0]\n", "empty.toml"),
             .worldName = "empty.toml",
             .controllers = {inlineController(nullptr)},
             .seconds = 1};
  EXPECT_EQ(validate(def).error(),
            "empty.toml: the world has no robot to drive: add one, e.g. a [[robot]] table with start = [1, 1] "
            "(the world format: worlds/data/README.md)");
}

// A run forked from an instant of another (frob run --from RUN#t=T): up to T it is the earlier run
// to the last bit (true pose, odometry: the wheels' slip and the start drawn from the seed, played
// again), each step checked against the trace; from T on the new controller drives, its clock at T.
// The same fork twice is the same run; a fork in a world run with another seed is refused.
TEST(Session, AForkIsTheEarlierRunUpToItsInstantThenTheNewControllers) {
  const worlds::WorldDef world = *worlds::parseWorld("size = [6.0, 4.0]\nseed = 5\n[[robot]]\nstart = [1.5, 2.0]\n", "noisy.toml");
  const auto driving = [](double forward, double turn) {
    return inlineController(makeController([=] { return mkTask([=](const TaskState&) { return std::pair{wheels(forward, turn), after(100.0)}; }); }));
  };
  const fs::path original = tempPath("fork_original.csv"), forked = tempPath("fork_forked.csv"), again = tempPath("fork_again.csv");
  const auto run = [&](LoadedController c, const fs::path& trace, std::optional<ForkPoint> fork, std::uint64_t seed = 5) {
    return runSession({.world = world,
                       .worldName = "noisy",
                       .options = {.seed = seed},
                       .controllers = {std::move(c)},
                       .seconds = 6,
                       .fork = std::move(fork),
                       .outputs = {.trace = trace.string()}});
  };
  ASSERT_TRUE(run(driving(0.4123457, 0.3012345), original, std::nullopt).ok());
  Result<ForkPoint> at3 = readForkPoint(original.string() + "#t=3", 0.01);
  ASSERT_TRUE(at3.ok()) << at3.error();
  EXPECT_EQ(at3.value().poses.size(), 301u);
  EXPECT_EQ(at3.value().wheels.size(), 300u) << "the new controller decides at 3 s itself";
  Result<Summary> f = run(driving(0.2, -0.5), forked, at3.value());
  ASSERT_TRUE(f.ok()) << f.error();
  ASSERT_FALSE(f.value().failed()) << f.value().robots[0].failure;
  ASSERT_FALSE(f.value().robots[0].lastTasks.empty());
  EXPECT_EQ(f.value().robots[0].lastTasks.front().start, 3.0) << "the controller's clock reads the instant it took over at";
  // Rows: time, robot, true pose, odometry, wheels, ...: up to 2.99 s all of these the earlier run's, at 3 s its poses.
  const auto rows = [](const fs::path& file) {
    std::vector<std::vector<std::string>> out;
    std::istringstream in(readText(file));
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      std::vector<std::string> cells;
      std::istringstream c(line);
      for (std::string cell; cells.size() < 10 && std::getline(c, cell, ',');) cells.push_back(cell);
      out.push_back(cells);
    }
    return out;
  };
  const auto before = rows(original), after = rows(forked);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t k = 0; k < 300; ++k) EXPECT_EQ(after[k], before[k]) << k;
  EXPECT_EQ(std::vector(after[300].begin(), after[300].begin() + 8), std::vector(before[300].begin(), before[300].begin() + 8));
  EXPECT_EQ(after[300][8], "0.2") << "the new controller's wheels from 3 s on";
  EXPECT_NE(after[400][2], before[400][2]);
  // The same fork again: the same run.
  Result<Summary> g = run(driving(0.2, -0.5), again, at3.value());
  ASSERT_TRUE(g.ok()) << g.error();
  EXPECT_EQ(g.value().trajectoryHash, f.value().trajectoryHash);
  EXPECT_EQ(readText(again), readText(forked));
  // Another seed draws another start: not the earlier run, said at once.
  Result<Summary> other = run(driving(0.2, -0.5), tempPath("fork_other.csv"), at3.value(), 6);
  ASSERT_TRUE(other.ok()) << other.error();
  EXPECT_EQ(other.value().robots[0].failure,
            "robot0: the run strays from " + original.string() +
                " at 0.00 s: it is not a run of this world and seed (give frob run that run's --world, --seed and --dt)");
  EXPECT_EQ(readForkPoint(original.string() + "#t=7", 0.01).error(), "--from: " + original.string() + " has its run up to 5.99 s, not to 7.00 s");
  // The earlier run's viewer page keeps its wheels to the bit: a fork from it is the fork from the trace.
  const fs::path page = tempPath("fork_original.html"), fromPage = tempPath("fork_from_page.csv");
  ASSERT_TRUE(runSession({.world = world,
                          .worldName = "noisy",
                          .options = {.seed = 5},
                          .controllers = {driving(0.4123457, 0.3012345)},
                          .seconds = 6,
                          .outputs = {.html = page.string()}})
                  .ok());
  Result<ForkPoint> pageAt3 = readForkPoint(page.string() + "#t=3", 0.01);
  ASSERT_TRUE(pageAt3.ok()) << pageAt3.error();
  EXPECT_EQ(pageAt3.value().wheels, at3.value().wheels);
  ASSERT_TRUE(run(driving(0.2, -0.5), fromPage, pageAt3.value()).ok());
  EXPECT_EQ(readText(fromPage), readText(forked));
  EXPECT_EQ(readForkPoint(page.string() + "#t=3", 0.02).error(), "--from: " + page.string() + " is a run with steps of 0.01 s: give --dt 0.01");
  EXPECT_EQ(readForkPoint(original.string(), 0.01).error(),
            "--from " + original.string() + ": give an earlier run's page or trace and an instant of it, e.g. run.html#t=12.5");
}

}  // namespace
}  // namespace frob::course
