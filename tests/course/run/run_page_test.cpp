// The run viewer page (frob run --html), opened in Debian's headless Chromium: it loads without a
// console message, the slider's instant shows the recorded pose, wheels and task stack of that
// instant (read back from the page's DOM, checked against the trace CSV and the timeline JSON of the
// same run), text from the controller stays text, and a long run's page stays small.
#include "../../support/chromium.hpp"
#include "../../support/dom.hpp"
#include "frob/frob.hpp"
#include "frob/run/session.hpp"
#include "frob/worlds/world_file.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <tuple>

namespace frob::course {
namespace {

namespace fs = std::filesystem;
using support::chromium, support::Ran, support::requireChromium, support::select, support::one;

// Markup, a closing script tag and a broken UTF-8 byte, as a hostile controller would name things.
const std::string kMarkup = "<img src=x onerror=\"document.title='pwned'\"></script><script>document.title='pwned'</script>\xff";
// What the page shows of it: the same characters as text, the bad byte replaced.
const std::string kMarkupShown = "<img src=x onerror=\"document.title='pwned'\"></script><script>document.title='pwned'</script>\xEF\xBF\xBD";

worlds::WorldDef room() {
  return *worlds::parseWorld(R"(size = [8.0, 5.0]
seed = 9
[points]
goal = [6.0, 2.5]
[[wall]]
rect = [[4.0, 0.5], [4.6, 1.2]]
[[robot]]
name = "r"
start = [1.0, 2.5]
)",
                             "room.toml");
}

LoadedController inlineController(Controller make) { return {.entry = {.name = "inline", .make = std::move(make)}, .source = "test.cpp"}; }

Task<Wheels> leg(double forward, double turn, double seconds, std::string name) {
  return mkTask([=](const TaskState&) { return std::pair{wheels(forward, turn), after(seconds)}; }).named(std::move(name));
}

// Nested and sequenced tasks, a picture that follows the robot, a published value, and a task, a
// picture text and a value named with markup.
Task<Wheels> tour(const Robot& r) {
  co_await leg(0.4, 0.0, 2.0, "straight");
  co_await withPicture(paintAt(place(r), withColor(red, circle(0.4))) + constant(paintAt(Point2{2, 4}, text(kMarkup))),
                       withPlot("heading", orientation(r), leg(0.3, 0.5, 3.0, "curve")));
  co_await withPlot(kMarkup, distance(place(r), Point2{6.0, 2.5}), leg(0.2, -0.3, 2.5, kMarkup));
  co_await leg(0.0, 0.8, 1.5, "spin");
}

// The tour again and again, for a long run.
Task<Wheels> tours(const Robot& r) {
  for (;;) co_await tour(r);
}

struct Written {
  fs::path dir, html, trace, timeline;
  Summary summary;
};

Written runTour(const std::string& name, bool long120 = false, std::function<std::vector<Measured>(const RunRecord&)> measure = {}) {
  Written w{.dir = fs::path(::testing::TempDir()) / "run_page_test" / name, .html = {}, .trace = {}, .timeline = {}, .summary = {}};
  fs::remove_all(w.dir);
  fs::create_directories(w.dir);
  w.html = w.dir / "run.html", w.trace = w.dir / "run.csv", w.timeline = w.dir / "run.json";
  Result<Summary> s = runSession({.world = room(),
                                  .worldName = "room",
                                  .controllers = {inlineController(long120 ? makeController(tours) : makeController(tour))},
                                  .seconds = long120 ? 120.0 : 12.0,
                                  .settleSeconds = 1.0,
                                  .keepRecord = static_cast<bool>(measure),
                                  .measure = std::move(measure),
                                  .outputs = {.trace = w.trace.string(), .timeline = w.timeline.string(), .html = w.html.string()}});
  EXPECT_TRUE(s.ok()) << s.error();
  if (s.ok()) w.summary = std::move(s.value());
  return w;
}

// The trace row of the instant nearest `t`: time, true pose, wheels, innermost task.
struct TraceRow {
  double time = 0, x = 0, y = 0, heading = 0, forward = 0, turn = 0;
  std::string task;
};
// A CSV field as written: a quoted one unquoted.
std::string unquoted(const std::string& field) {
  if (field.size() < 2 || field.front() != '"') return field;
  std::string out;
  for (std::size_t i = 1; i + 1 < field.size(); ++i) {
    out += field[i];
    if (field[i] == '"') ++i;  // "" stands for "
  }
  return out;
}

TraceRow traceAt(const fs::path& csv, double t) {
  std::istringstream in(support::readText(csv.string()));
  std::string line;
  std::getline(in, line);  // header
  TraceRow best;
  double bestGap = 1e9;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::string field;
    std::istringstream cells(line);
    while (std::getline(cells, field, ',')) f.push_back(field);
    const double time = std::stod(f.at(0)), gap = std::abs(time - t);
    if (gap < bestGap) {
      bestGap = gap;
      best = {time, std::stod(f[2]), std::stod(f[3]), std::stod(f[4]), std::stod(f[8]), std::stod(f[9]), unquoted(f.back())};
    }
  }
  return best;
}

// The tasks the timeline JSON has running at `t` (started, not yet ended), outermost first.
std::vector<std::string> timelineStackAt(const fs::path& json, double t) {
  const nlohmann::json doc = nlohmann::json::parse(support::readText(json.string()));
  std::vector<std::pair<std::tuple<long long, long long, int>, std::string>> open;  // (start, -end, depth), name
  const long long us = std::llround(t * 1e6);
  for (const nlohmann::json& e : doc["traceEvents"]) {
    if (e["ph"] != "X") continue;
    const long long ts = e["ts"], dur = e["dur"];
    if (ts <= us && us < ts + dur) open.push_back({{ts, -(ts + dur), e["args"]["depth"]}, e["name"]});
  }
  std::sort(open.begin(), open.end());
  std::vector<std::string> names;
  for (const auto& o : open) names.push_back(o.second);
  return names;
}

// The page's DOM after it has drawn the instant `t`, and Chromium's console messages.
struct Page {
  support::Doc dom;
  std::string console;
};
// The page opened at `t` (its address's #t=), or, with none, where the page itself says; `more`
// adds to the address ("&next=task:curve").
Page openAt(const Written& w, std::optional<double> t, const std::string& more = "") {
  const fs::path out = w.dir / "dom.html";
  std::ostringstream hash;
  if (t) hash << "#t=" << *t << more;
  // The page inflates its data asynchronously: a virtual time budget lets it finish before the dump.
  const Ran ran = chromium(w.dir, {"--dump-dom", "--virtual-time-budget=20000", "--enable-logging=stderr", "--v=0"}, w.html, out, hash.str());
  EXPECT_EQ(ran.status, 0) << ran.err;
  Page p{support::parseHtml(support::readText(out.string())), {}};
  std::istringstream lines(ran.err);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(":CONSOLE") != std::string::npos) p.console += line + "\n";
  }
  return p;
}

TEST(RunPage, TheSlidersInstantShowsTheRecordedPoseWheelsAndTaskStack) {
  requireChromium();
  const Written w = runTour("instants");
  ASSERT_TRUE(fs::exists(w.html));
  // In each task of the tour, in the settle time after it, and at the first and last instants.
  for (double t : {0.0, 1.37, 3.02, 4.99, 6.31, 8.2, 9.13, w.summary.simulatedSeconds}) {
    SCOPED_TRACE("t = " + std::to_string(t));
    const Page page = openAt(w, t);
    ASSERT_TRUE(page.dom);
    EXPECT_EQ(page.console, "") << "the page logged to the console";
    EXPECT_EQ(select(page.dom.get(), "//body/@data-ready"), std::vector<std::string>{"1"});
    const TraceRow row = traceAt(w.trace, t);
    EXPECT_EQ(one(page.dom.get(), "//output[@id='time']"), [&] {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.2f s", row.time);
      return std::string(buf);
    }());
    // Poses are kept to the millimetre (and the milliradian): half of one, and a little rounding.
    EXPECT_NEAR(std::stod(one(page.dom.get(), "//tr[@id='pose']/@data-x")), row.x, 0.0005 + 1e-9);
    EXPECT_NEAR(std::stod(one(page.dom.get(), "//tr[@id='pose']/@data-y")), row.y, 0.0005 + 1e-9);
    EXPECT_NEAR(std::stod(one(page.dom.get(), "//tr[@id='pose']/@data-heading")), row.heading, 0.0005 + 1e-9);
    EXPECT_NEAR(std::stod(one(page.dom.get(), "//tr[@id='wheels']/@data-forward")), row.forward, 0.0005 + 1e-9);
    EXPECT_NEAR(std::stod(one(page.dom.get(), "//tr[@id='wheels']/@data-turn")), row.turn, 0.0005 + 1e-9);
    const std::vector<std::string> stack = select(page.dom.get(), "//ol[@id='stack']/li");
    EXPECT_EQ(stack, timelineStackAt(w.timeline, row.time));
    EXPECT_EQ(stack.empty() ? std::string() : stack.back(), row.task == kMarkup ? kMarkupShown : row.task);  // the trace keeps the bytes
    // After the top task returned, the settle time: the page says so.
    EXPECT_EQ(one(page.dom.get(), "//p[@id='status']"), t > 9.0 ? "Its task returned at 9.00 s: the robot is commanded still." : "");
  }
}

// A grade report opens its run where the check was decided: the body's data-open-at, when the
// address names no instant.
TEST(RunPage, ThePageOpensAtTheInstantItsBodyNames) {
  requireChromium();
  Written w = runTour("open_at");
  std::string page = support::readText(w.html.string());
  const std::size_t body = page.find("<body>");
  ASSERT_NE(body, std::string::npos);
  page.replace(body, 6, "<body data-open-at=\"6.310\">");
  w.html = w.dir / "opens_at.html";
  std::ofstream(w.html) << page;
  const TraceRow row = traceAt(w.trace, 6.31);
  char shown[32];
  std::snprintf(shown, sizeof shown, "%.2f s", row.time);
  const Page opened = openAt(w, std::nullopt);
  ASSERT_TRUE(opened.dom);
  EXPECT_EQ(opened.console, "");
  EXPECT_EQ(one(opened.dom.get(), "//output[@id='time']"), shown);
  const Page asked = openAt(w, 1.37);  // an address's #t still wins
  ASSERT_TRUE(asked.dom);
  std::snprintf(shown, sizeof shown, "%.2f s", traceAt(w.trace, 1.37).time);
  EXPECT_EQ(one(asked.dom.get(), "//output[@id='time']"), shown);
}

// Jumps, as the address asks them (the buttons and [ ] call the same): to the next or previous start
// of a named task, and to where a plotted value crosses a level, found in the trace; none past the
// last leaves the instant as it was; the page's link to its instant says where it now is.
TEST(RunPage, JumpsToTheStartOfATaskOrWhereAValueCrossesALevel) {
  requireChromium();
  const Written w = runTour("jumps");
  const auto shown = [](double t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", t);
    return std::string(text);
  };
  const auto opened = [&](double t, const std::string& more) {
    const Page page = openAt(w, t, more);
    EXPECT_EQ(page.console, "");
    return std::pair{one(page.dom.get(), "//output[@id='time']"), one(page.dom.get(), "//a[@id='place']/@href")};
  };
  EXPECT_EQ(opened(0.5, "&next=task:curve"), std::pair(shown(2.0), std::string("#t=2.000")));
  EXPECT_EQ(opened(8.0, "&prev=task:straight").first, shown(0.0));
  EXPECT_EQ(opened(3.0, "&next=task:curve").first, shown(3.0)) << "the curve starts once";
  // The forward command drops from 0.4 to 0.3 m/s where the curve begins: the first trace row below 0.35.
  std::istringstream trace(support::readText(w.trace.string()));
  std::string line;
  std::getline(trace, line);
  double below = -1;
  while (below < 0 && std::getline(trace, line)) {
    std::vector<std::string> f;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) f.push_back(cell);
    if (std::stod(f.at(8)) < 0.35) below = std::stod(f.at(0));
  }
  ASSERT_GT(below, 0.0);
  EXPECT_EQ(opened(0.0, "&next=cross:forward%20(m%2Fs)@0.35").first, shown(below));
  EXPECT_EQ(opened(0.0, "&next=cross:forward%20(m%2Fs)@0.45").first, shown(0.0)) << "it never reaches 0.45";
}

// A measure an assignment judges (here: the distance to the goal, wanted within 3 m) is a column of
// the trace and a row of the page with its band, the same value at each instant; off the band, the
// row says so.
TEST(RunPage, WhatTheAssignmentMeasuresIsShownWithItsBand) {
  requireChromium();
  const Written w = runTour("measured", false, [](const RunRecord& r) {
    Measured m{.name = "goal_distance", .unit = "m", .robot = 0, .dt = r.dt, .values = {}, .low = std::nullopt, .high = 3.0, .everyInstant = false};
    for (const Point2& p : r.robots[0].path) m.values.push_back((p - Point2(6.0, 2.5)).norm());
    Measured each = m;  // the same band held at every instant
    each.name = "goal_distance_each", each.everyInstant = true;
    return std::vector<Measured>{m, each};
  });
  std::istringstream trace(support::readText(w.trace.string()));
  std::string line;
  std::getline(trace, line);
  ASSERT_TRUE(line.ends_with(",task,goal_distance,goal_distance_each")) << line;
  for (double t : {1.0, 6.31}) {
    SCOPED_TRACE("t = " + std::to_string(t));
    const Page page = openAt(w, t);
    ASSERT_TRUE(page.dom);
    EXPECT_EQ(page.console, "");
    const TraceRow row = traceAt(w.trace, t);
    const double wanted = std::hypot(row.x - 6.0, row.y - 2.5);
    EXPECT_NEAR(std::stod(one(page.dom.get(), "//tr[td='goal_distance']/@data-value")), wanted, 0.0005 + 1e-9);
    const std::string shown = one(page.dom.get(), "//tr[td='goal_distance']/td[2]");
    EXPECT_TRUE(shown.ends_with(" m (wanted at most 3.00 once)")) << shown;
    EXPECT_EQ(one(page.dom.get(), "//tr[td='goal_distance']/@class"), "judged") << "a reach is judged once, not at each instant";
    EXPECT_EQ(one(page.dom.get(), "//tr[td='goal_distance_each']/@class"), wanted > 3.0 ? "judged off" : "judged");
  }
}

TEST(RunPage, TextFromTheControllerIsShownAsTextNeverAsMarkup) {
  requireChromium();
  const Written w = runTour("markup");
  // While the task named with markup runs, its picture text and value are shown too.
  const Page page = openAt(w, 6.0);
  ASSERT_TRUE(page.dom);
  EXPECT_EQ(page.console, "");
  const std::vector<std::string> stack = select(page.dom.get(), "//ol[@id='stack']/li");
  ASSERT_FALSE(stack.empty());
  EXPECT_EQ(stack.back(), kMarkupShown);
  EXPECT_EQ(select(page.dom.get(), "//tr[@class='published']/td[1]"), (std::vector<std::string>{"heading", kMarkupShown}));
  // The browser made no element of it, and no script of it ran.
  EXPECT_TRUE(select(page.dom.get(), "//img").empty());
  EXPECT_TRUE(select(page.dom.get(), "//b").empty());
  EXPECT_EQ(select(page.dom.get(), "//script").size(), 2u) << "the page's data and its own script, no more";
  EXPECT_EQ(one(page.dom.get(), "//title"), "test.cpp in room");
}

TEST(RunPage, ARunOf120SecondsAt100HzFitsIn2MBAndTheSameRunWritesTheSamePage) {
  const Written a = runTour("long_a", true), b = runTour("long_b", true);
  EXPECT_EQ(a.summary.steps, 12000);
  const std::uintmax_t bytes = fs::file_size(a.html);
  EXPECT_LE(bytes, 2'000'000u);
  std::printf("a 120 s run at 100 Hz: the page is %ju bytes\n", bytes);
  EXPECT_TRUE(support::readText(a.html.string()) == support::readText(b.html.string()));
}

// A controller that sends more than a page can show: a task of a 3 kB name every step, and a picture
// of 400 shapes that changes every step. The page keeps what it can, says what it left out, and
// stays a few megabytes.
Task<Wheels> flood(const Robot& r) {
  for (int i = 0;; ++i) {
    std::vector<Shape> shapes;
    for (int k = 0; k < 400; ++k) {
      shapes.push_back({.kind = Shape::Kind::Polyline, .points = {Point2(i % 97 * 0.01, k * 0.01), Point2(k * 0.013, i % 89 * 0.01), Point2(1, 1)}});
    }
    co_await withPicture(constant(Picture(std::move(shapes))), leg(0.1, 0.2, 0.01, std::to_string(i) + std::string(3000, 'n')));
  }
}

TEST(RunPage, WhatAControllerFloodsItWithIsCutAndSaidSo) {
  requireChromium();
  Written w{.dir = fs::path(::testing::TempDir()) / "run_page_test" / "flood", .html = {}, .trace = {}, .timeline = {}, .summary = {}};
  fs::remove_all(w.dir);
  fs::create_directories(w.dir);
  w.html = w.dir / "run.html";
  Result<Summary> s = runSession({.world = room(),
                                  .worldName = "room",
                                  .controllers = {inlineController(makeController(flood))},
                                  .seconds = 30,
                                  .outputs = {.html = w.html.string()}});
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_LE(fs::file_size(w.html), 6'000'000u);
  const Page page = openAt(w, 29.0);
  EXPECT_EQ(page.console, "");
  const std::string subtitle = one(page.dom.get(), "//p[@id='subtitle']");
  EXPECT_NE(subtitle.find("Pictures were kept at most every 10 steps once they grew large, and then no more."), std::string::npos) << subtitle;
  EXPECT_NE(subtitle.find(" tasks of r are shown."), std::string::npos) << subtitle;
}

TEST(RunPage, APageThatCannotBeWrittenIsAnErrorBeforeTheRun) {
  Result<Summary> s = runSession({.world = room(),
                                  .worldName = "room",
                                  .controllers = {inlineController(makeController(tour))},
                                  .seconds = 1,
                                  .outputs = {.html = "/nonexistent/run.html"}});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "html: cannot write '/nonexistent/run.html': directory '/nonexistent' does not exist");
}

}  // namespace
}  // namespace frob::course
