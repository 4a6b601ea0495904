// The grader's criteria, judged on hand-made runs whose answers are known exactly.
#include "frob/grade/judge.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace frob::course {
namespace {

using Kind = Criterion::Kind;

// A 6 x 3 m room, enclosed, with a goal and two waypoints; steps of 0.1 s.
RunRecord room() {
  RunRecord r{.size = {6.0, 3.0}, .dt = 0.1};
  const Point2 a(0, 0), b(6, 0), c(6, 3), d(0, 3);
  for (auto [p, q] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}}) r.walls.push_back(worlds::segmentWall(p, q));
  r.enclosureWalls = 4;
  r.points = {{"goal", {5.0, 1.5}}, {"a", {2.0, 1.5}}, {"b", {4.0, 1.5}}};
  return r;
}

// A robot driving from (x0, y) along +x at `speed` m/s for `seconds`, sampled every 0.1 s.
Track straight(double x0, double y, double speed, double seconds, const std::string& name = "ada") {
  Track t{.name = name};
  for (int k = 0; k <= static_cast<int>(std::lround(seconds * 10)); ++k) t.path.emplace_back(x0 + speed * 0.1 * k, y);
  return t;
}

Verdict run(const Criterion& c, Track t, RunRecord r = room()) {
  r.robots.push_back(std::move(t));
  return judge(c, r);
}

TEST(Judge, GoalReachedInTimeOrLateOrNever) {
  const Criterion goal{.kind = Kind::Goal, .distance = 0.2, .seconds = 10};
  // From x = 1 at 0.5 m/s: within 0.2 m of x = 5 at x = 4.8, after 7.6 s.
  EXPECT_TRUE(run(goal, straight(1, 1.5, 0.5, 9)).passed);
  const Criterion strict{.kind = Kind::Goal, .distance = 0.2, .seconds = 7};
  EXPECT_EQ(run(strict, straight(1, 1.5, 0.5, 9)).reason, "reached goal at 7.6 s; allowed 7 s");
  EXPECT_EQ(run(goal, straight(1, 1.5, 0.5, 4)).reason, "never came within 0.20 m of goal (closest 2.00 m, at 4.0 s)");
  const Criterion missing{.kind = Kind::Goal, .point = "exit", .distance = 0.2};
  EXPECT_EQ(run(missing, straight(1, 1.5, 0.5, 1)).reason, "the world has no point 'exit' to reach");
}

TEST(Judge, WaypointsInOrder) {
  const Criterion ab{.kind = Kind::Waypoints, .points = {"a", "b"}, .distance = 0.2};
  EXPECT_TRUE(run(ab, straight(1, 1.5, 0.5, 8)).passed);
  EXPECT_EQ(run(ab, straight(1, 2.5, 0.5, 8)).reason, "never came within 0.20 m of a (closest 1.00 m, at 2.0 s)");
  const Criterion ba{.kind = Kind::Waypoints, .points = {"b", "a"}, .distance = 0.2};
  EXPECT_EQ(run(ba, straight(1, 1.5, 0.5, 8)).reason, "reached b at 5.6 s, never came within 0.20 m of a after that (closest 1.80 m, at 5.6 s)");
}

TEST(Judge, StoppedAtTheEnd) {
  const Criterion stopped{.kind = Kind::Stopped, .speed = 0.05};
  EXPECT_TRUE(run(stopped, straight(1, 1.5, 0.0, 2)).passed);
  EXPECT_EQ(run(stopped, straight(1, 1.5, 0.3, 2)).reason, "was still moving at 0.30 m/s at the end; it should stop (below 0.05 m/s)");
}

// A robot driving along +x at 0.3 m/s until `stop` s, then standing, sampled every 0.1 s for `seconds`.
Track stopsAt(double stop, double seconds) {
  Track t{.name = "ada"};
  for (int k = 0; k <= static_cast<int>(std::lround(seconds * 10)); ++k) t.path.emplace_back(1 + 0.3 * std::min(0.1 * k, stop), 1.5);
  return t;
}

TEST(Judge, StoppedWithinItsTimeOfAKeyAndStillAtTheEnd) {
  RunRecord r = room();
  r.keys = {{.time = 1.0, .key = 'x'}, {.time = 2.0, .key = 's'}};
  const Criterion c{.kind = Kind::Stopped, .speed = 0.05, .afterKey = 's', .within = 1.0};
  EXPECT_TRUE(run(c, stopsAt(2.8, 6), r).passed);
  EXPECT_EQ(run(c, stopsAt(3.5, 6), r).reason,
            "was moving at 0.30 m/s at 3.0 s, 1.0 s after the key s was pressed; it should stop within 1 s (below 0.05 m/s)");
  Track pauses = stopsAt(2.5, 6);  // stands at a corner, then drives on
  for (std::size_t k = 40; k < pauses.path.size(); ++k) pauses.path[k].x() += 0.03 * static_cast<double>(k - 39);
  EXPECT_EQ(run(c, pauses, r).reason,
            "was moving at 0.30 m/s at 4.0 s, 2.0 s after the key s was pressed; it should stop within 1 s (below 0.05 m/s)");
  r.keys = {{.time = 1.0, .key = 'x'}, {.time = 9.0, .key = 's'}};  // after the run
  EXPECT_EQ(run(c, stopsAt(2.8, 6), r).reason, "the key s was never pressed, so it had nothing to stop for");
}

// A robot that stopped at a time of its choosing, before the key came, did not stop for the key: it
// must be moving (a point of its body faster than `speed`; turning on the spot counts) until the
// event, all but 0.25 s of the `within` s before it.
TEST(Judge, StoppedForAnEventOnlyIfMovingUntilIt) {
  RunRecord r = room();
  r.keys = {{.time = 2.0, .key = 's'}};
  const Criterion c{.kind = Kind::Stopped, .speed = 0.05, .afterKey = 's', .within = 1.0};
  EXPECT_EQ(run(c, stopsAt(0.5, 6), r).reason,
            "stood still for 1.0 s of the 1 s before the key s was pressed (at 2.0 s); it must be moving until then");
  EXPECT_EQ(run(c, stopsAt(1.7, 6), r).reason,
            "stood still for 0.3 s of the 1 s before the key s was pressed (at 2.0 s); it must be moving until then");
  EXPECT_TRUE(run(c, stopsAt(1.8, 6), r).passed) << "0.2 s standing: a pause between driving and turning";
  Track turns = stopsAt(1.0, 6);  // stops at 1 s, then turns on the spot at 1 rad/s until 2.2 s: its rim moves at 0.23 m/s
  turns.heading.assign(turns.path.size(), 0.0);
  for (std::size_t k = 11; k < turns.heading.size(); ++k) turns.heading[k] = 0.1 * static_cast<double>(std::min<std::size_t>(k, 22) - 10);
  EXPECT_TRUE(run(c, turns, r).passed);
  turns.heading.back() += 0.5;  // a turn at the end is not stopped either
  EXPECT_EQ(run(c, turns, r).reason,
            "was moving at 1.15 m/s at 6.0 s, 4.0 s after the key s was pressed; it should stop within 1 s (below 0.05 m/s)");
}

TEST(Judge, StoppedWithinItsTimeOfTheFirstContact) {
  const Criterion c{.kind = Kind::Stopped, .speed = 0.05, .afterContact = true, .within = 0.5};
  Track t = stopsAt(2.0, 4);
  EXPECT_EQ(run(c, t).reason, "it never touched anything, so it had nothing to stop for");
  t.contacts = {{1.6, {1.5, 1.5}}, {1.7, {1.5, 1.5}}};
  EXPECT_TRUE(run(c, t).passed);
  t.contacts = {{1.4, {1.5, 1.5}}};
  EXPECT_EQ(run(c, t).reason, "was moving at 0.30 m/s at 1.9 s, 0.5 s after it touched something; it should stop within 0.5 s (below 0.05 m/s)");
}

// A reported event counts only once the simulator saw it happen (a step's grace: it is sensed a step later).
TEST(Judge, AReportedEventMustHaveHappenedFirst) {
  RunRecord r = room();
  r.keys = {{.time = 2.0, .key = 's'}};
  Track t = stopsAt(3.0, 5);
  t.returned = "key";
  const Criterion key{.kind = Kind::Returns, .value = "key", .afterKey = 's'};
  t.returnedAt = 1.0;
  EXPECT_EQ(run(key, t, r).reason, "its task returned key at 1.0 s, before the key s was pressed (at 2.0 s)");
  t.returnedAt = 1.9;
  EXPECT_TRUE(run(key, t, r).passed);
  EXPECT_EQ(run(key, t).reason, "its task returned key, but the key s was never pressed");
  t.returned = "bumped";
  const Criterion bumped{.kind = Kind::Returns, .value = "bumped", .afterContact = true};
  t.contacts = {{2.5, {1.5, 1.5}}};
  EXPECT_EQ(run(bumped, t).reason, "its task returned bumped at 1.9 s, before it touched something (at 2.5 s)");
  t.returned = "budget";
  const Criterion budget{.kind = Kind::Returns, .value = "budget", .afterDistance = 0.5};  // 0.3 m/s: 0.5 m at 1.7 s
  EXPECT_TRUE(run(budget, t).passed);
  t.returnedAt = 1.5;
  EXPECT_EQ(run(budget, t).reason, "its task returned budget at 1.5 s, before it had driven 0.5 m (at 1.7 s)");
}

// ... and a report long after the event is a guess, not a report: at most `within` s late (1 s unless given).
TEST(Judge, AReportedEventMustComeSoonAfterIt) {
  RunRecord r = room();
  r.keys = {{.time = 2.0, .key = 's'}};
  Track t = stopsAt(3.0, 5);
  t.returned = "key";
  t.returnedAt = 3.0;
  Criterion key{.kind = Kind::Returns, .value = "key", .afterKey = 's'};
  EXPECT_TRUE(run(key, t, r).passed);
  t.returnedAt = 3.2;
  EXPECT_EQ(run(key, t, r).reason, "its task returned key at 3.2 s, 1.2 s after the key s was pressed; at most 1 s later allowed");
  key.within = 0.5;
  t.returnedAt = 2.6;
  EXPECT_EQ(run(key, t, r).reason, "its task returned key at 2.6 s, 0.6 s after the key s was pressed; at most 0.5 s later allowed");
  t.returned = "true";
  t.returnedAt = 4.0;
  EXPECT_TRUE(run({.kind = Kind::Returns, .value = "true"}, t, r).passed) << "no event: no latency";
}

TEST(Judge, CollisionsNameTheFirstOneOverTheLimit) {
  Track t = straight(1, 1.5, 0.5, 2);
  t.contacts = {{41.2, {3.1, 2.75}}, {50.0, {4.0, 2.75}}};
  EXPECT_EQ(run({.kind = Kind::Collisions, .count = 0}, t).reason, "touched the outer wall at 41.2 s at (3.1, 2.8) (2 collisions; 0 allowed)");
  EXPECT_EQ(run({.kind = Kind::Collisions, .count = 1}, t).reason, "touched the outer wall at 50.0 s at (4.0, 2.8) (2 collisions; 1 allowed)");
  EXPECT_TRUE(run({.kind = Kind::Collisions, .count = 2}, t).passed);
  t.contacts = {{3.0, {3.0, 1.5}}};  // in the middle of the room: it must have been another robot
  EXPECT_EQ(run({.kind = Kind::Collisions, .count = 0}, t).reason, "touched another robot at 3.0 s at (3.0, 1.5)");
}

// What was touched is named as what it is: a cupboard is a block and a table a round obstacle, not walls.
TEST(Judge, AnObstacleIsNamedAsWhatItIs) {
  RunRecord r = room();
  r.walls.insert(r.walls.begin(),
                 {worlds::rectangleWall({2.0, 0.5}, {2.6, 1.0}), worlds::circleWall({4.0, 2.0}, 0.2), worlds::segmentWall({5.0, 0.0}, {5.0, 1.0})});
  Track t = straight(1, 1.5, 0.5, 2);
  const Criterion none{.kind = Kind::Collisions, .count = 0};
  t.contacts = {{1.0, {2.3, 1.2}}};
  EXPECT_EQ(run(none, t, r).reason, "touched a block at 1.0 s at (2.3, 1.2)");
  t.contacts = {{1.0, {4.0, 1.65}}};
  EXPECT_EQ(run(none, t, r).reason, "touched a round obstacle at 1.0 s at (4.0, 1.6)");
  t.contacts = {{1.0, {4.8, 0.5}}};
  EXPECT_EQ(run(none, t, r).reason, "touched a wall at 1.0 s at (4.8, 0.5)");
}

// A robot commanded still after a bump keeps moving a little: it bounces off, or glances round the
// corner it hit onto the next face, and its bumpers close again. That is the same collision, as are
// two bumpers pressed in one step; a contact 0.5 s or more after the last touch ended is a new one.
TEST(Judge, ABounceOrAGlanceRoundACornerIsTheSameCollision) {
  Track t = straight(1, 1.5, 0.5, 2);
  t.contacts = {{18.81, {3.1, 2.75}}, {18.81, {3.1, 2.75}}, {19.11, {3.0, 2.75}}};
  t.touching = {{18.81, 18.90}, {19.11, 19.30}};
  const Criterion once{.kind = Kind::Collisions, .count = 1};
  EXPECT_TRUE(run(once, t).passed);
  t.contacts.push_back({20.0, {3.0, 2.75}});  // sensed a step (0.1 s here) after it began, 0.6 s after the last touch: a new one
  t.touching.push_back({19.9, 20.1});
  EXPECT_EQ(run(once, t).reason, "touched the outer wall at 20.0 s at (3.0, 2.8) (2 collisions; 1 allowed)");
  t.touching = {};  // contacts alone: each 0.5 s or more after the one before is new
  EXPECT_EQ(run(once, t).reason, "touched the outer wall at 20.0 s at (3.0, 2.8) (2 collisions; 1 allowed)");
  t.contacts.back().first = 19.6;
  EXPECT_TRUE(run(once, t).passed);
}

// A bump at a corner the sonars cannot hear is brief; pushing along an obstacle is not.
TEST(Judge, CollisionsMayCapTheTimeSpentTouching) {
  Track t = straight(1, 1.5, 0.5, 2);
  t.contacts = {{10.0, {3.1, 2.75}}, {20.0, {4.0, 2.75}}};
  t.touching = {{10.0, 10.5}, {20.0, 22.0}};
  const Criterion brief{.kind = Kind::Collisions, .seconds = 2.5, .count = 2};
  EXPECT_TRUE(run(brief, t).passed);
  EXPECT_EQ(run({.kind = Kind::Collisions, .seconds = 2.0, .count = 2}, t).reason,
            "pressed its bumpers for 2.5 s in all, the longest touch from 20.0 s to 22.0 s; at most 2.0 s allowed");
  EXPECT_EQ(run({.kind = Kind::Collisions, .seconds = 2.5, .count = 1}, t).reason,
            "touched the outer wall at 20.0 s at (4.0, 2.8) (2 collisions; 1 allowed)");
  t.touching.back().second = 30.0;
  EXPECT_FALSE(run(brief, t).passed);
  EXPECT_TRUE(run({.kind = Kind::Collisions, .count = 2}, t).passed) << "no time cap unless one is given";
}

// Pushing along a wall is one collision per second (started) of driving while touching it; standing
// pressed against what it stopped at is one.
TEST(Judge, PushingAlongCountsOneCollisionPerSecondOfIt) {
  Track t = straight(1, 2.75, 0.5, 6);  // its body against the north wall
  t.contacts = {{1.0, {1.5, 2.75}}};
  t.touching = {{1.0, 3.55}};  // 26 steps of 0.1 s driving while touching: 2.6 s
  EXPECT_TRUE(run({.kind = Kind::Collisions, .count = 3}, t).passed);
  EXPECT_EQ(run({.kind = Kind::Collisions, .count = 2}, t).reason, "touched the outer wall at 3.0 s at (2.5, 2.8) (3 collisions; 2 allowed)");
  Track pressed = stopsAt(1.0, 20);
  pressed.contacts = {{1.0, {1.3, 1.5}}};
  pressed.touching = {{1.0, 20.0}};
  EXPECT_TRUE(run({.kind = Kind::Collisions, .count = 1}, pressed).passed);
}

TEST(Judge, ClearanceIsMeasuredFromTheBody) {
  // Centre 0.30 m from the bottom wall, body radius 0.23: 0.07 m of clearance.
  const Criterion c{.kind = Kind::Clearance, .distance = 0.1};
  EXPECT_EQ(run(c, straight(1, 0.30, 0.5, 1)).reason, "came within 0.07 m of the outer wall at 0.0 s at (1.0, 0.3); at least 0.10 m required");
  EXPECT_TRUE(run(c, straight(1, 0.34, 0.5, 1)).passed);
}

TEST(Judge, WallDistanceHeldForAFractionAfterSettling) {
  const Criterion c{.kind = Kind::WallDistance, .distance = 0.5, .tolerance = 0.05, .fraction = 0.8, .after = 1.0};
  // 0.73 m from the wall: 0.5 m from the body's surface, all the time.
  EXPECT_TRUE(run(c, straight(1, 0.73, 0.3, 10)).passed);
  // Drifting away: y = 0.73 + 0.02 t, within 0.05 m up to 2.5 s: 16 of the 91 steps from 1 s on.
  Track drift{.name = "ada"};
  for (int k = 0; k <= 100; ++k) drift.path.emplace_back(1 + 0.03 * k, 0.73 + 0.002 * k);
  EXPECT_EQ(run(c, drift).reason,
            "kept 0.50 ± 0.05 m from the wall for 18% of the time after 1.0 s; 80% required (at worst 0.20 m off the 0.50 m wanted, at 10.0 s at "
            "(4.0, 0.9))");
}

// What the judge measures along a run, step by step, is what it judges: the drift's wall distance
// keeps its band at 16 of the 91 steps from 1 s on (the 18% of its reason), the clearance's least is
// the reason's 0.07 m, the floor covered ends at the margin's 17%, the goal's distance is the path's.
TEST(Judge, MeasuresAlongTheRunWhatItJudges) {
  Track drift{.name = "ada"};
  for (int k = 0; k <= 100; ++k) drift.path.emplace_back(1 + 0.03 * k, 0.73 + 0.002 * k);
  RunRecord r = room();
  r.robots.push_back(drift);
  const Check check{.name = "c",
                    .criteria = {{.kind = Kind::WallDistance, .distance = 0.5, .tolerance = 0.05, .fraction = 0.8, .after = 1.0},
                                 {.kind = Kind::Goal, .distance = 0.2},
                                 {.kind = Kind::Goal, .distance = 0.5},     // the same measure again: one column
                                 {.kind = Kind::Collisions, .count = 0}}};  // a count: no column
  const std::vector<Measured> m = measuredAlong({check}, r);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].name, "wall_distance");
  EXPECT_EQ(m[0].values.size(), drift.path.size());
  EXPECT_EQ(m[0].from, 1.0);
  EXPECT_TRUE(m[0].everyInstant);
  EXPECT_NEAR(*m[0].low, 0.45, 1e-12);
  EXPECT_NEAR(*m[0].high, 0.55, 1e-12);
  int within = 0;
  for (std::size_t k = 10; k < m[0].values.size(); ++k) within += m[0].values[k] >= *m[0].low - 1e-9 && m[0].values[k] <= *m[0].high + 1e-9;
  EXPECT_EQ(within, 16);
  EXPECT_EQ(m[1].name, "goal_distance");
  EXPECT_EQ(m[1].high, 0.2) << "the first criterion that measures it gives its band";
  EXPECT_FALSE(m[1].everyInstant);
  EXPECT_NEAR(m[1].values[50], (drift.path[50] - Point2(5.0, 1.5)).norm(), 1e-12);

  RunRecord near = room();
  near.robots.push_back(straight(1, 0.30, 0.5, 1));
  const std::vector<Measured> clearance = measuredAlong({{.name = "c", .criteria = {{.kind = Kind::Clearance, .distance = 0.1}}}}, near);
  ASSERT_EQ(clearance.size(), 1u);
  EXPECT_NEAR(*std::min_element(clearance[0].values.begin(), clearance[0].values.end()), 0.07, 1e-9);
  EXPECT_EQ(clearance[0].low, 0.1);

  RunRecord swept = room();
  swept.robots.push_back(straight(0.25, 1.25, 0.5, 11));
  const std::vector<Measured> covered = measuredAlong({{.name = "c", .criteria = {{.kind = Kind::Coverage, .fraction = 0.16, .cell = 0.5}}}}, swept);
  ASSERT_EQ(covered.size(), 1u);
  EXPECT_EQ(covered[0].unit, "%");
  EXPECT_EQ(std::lround(covered[0].values.back()), 17);
  EXPECT_TRUE(std::is_sorted(covered[0].values.begin(), covered[0].values.end())) << "what is covered stays covered";
}

// With a side, only the wall on that side counts: in the 6 x 3 m room, 0.73 m from the south wall,
// a robot heading east has it on its right; heading west, on its left (and the north wall, 2.27 m
// away, on its right).
TEST(Judge, WallDistanceOnTheSideTheHandoutNames) {
  const Criterion right{.kind = Kind::WallDistance, .distance = 0.5, .tolerance = 0.05, .fraction = 0.8, .side = "right"};
  Track east = straight(1, 0.73, 0.3, 10);
  east.heading.assign(east.path.size(), 0.0);
  EXPECT_TRUE(run(right, east).passed);
  Track west = east;
  west.heading.assign(west.path.size(), pi);
  EXPECT_EQ(run(right, west).reason,
            "kept 0.50 ± 0.05 m from the wall on its right for 0% of the time after 0.0 s; 80% required (at worst 1.54 m off the 0.50 m wanted, at "
            "0.5 s at (1.1, 0.7))");
  Criterion left = right;
  left.side = "left";
  EXPECT_TRUE(run(left, west).passed);
  // Turned 20 degrees off the wall, the ray square to the heading is long, the one 20 degrees back is square to the wall.
  Track slanted = east;
  slanted.heading.assign(slanted.path.size(), 20 * pi / 180);
  EXPECT_TRUE(run(right, slanted).passed);
}

TEST(Judge, CoverageCountsTheFreeCellsItsCentreVisited) {
  // Cells of 0.5 m: the centre fits in cells whose centre is 0.23 m clear of the walls, every cell
  // of the 12 x 6 grid. A pass along y = 1.25 from x = 0.25 to 5.75 visits one row: 12 of 72.
  const Criterion c{.kind = Kind::Coverage, .fraction = 0.2, .cell = 0.5};
  EXPECT_EQ(run(c, straight(0.25, 1.25, 0.5, 11)).reason, "covered 17% of the floor it could reach (12 of 72 cells of 0.50 m); 20% required");
  EXPECT_TRUE(run({.kind = Kind::Coverage, .fraction = 0.16, .cell = 0.5}, straight(0.25, 1.25, 0.5, 11)).passed);
}

// With `away`, only the floor where the body keeps that far from every wall counts: here cells whose
// centre is 0.73 m clear of the walls, 10 x 4 of them. A pass down the middle visits a row of them;
// one along a wall, none.
TEST(Judge, CoverageAwayFromTheWallsCountsOnlyTheMiddle) {
  const Criterion middle{.kind = Kind::Coverage, .distance = 0.5, .fraction = 0.2, .cell = 0.5};
  EXPECT_TRUE(run(middle, straight(0.25, 1.25, 0.5, 11)).passed);
  EXPECT_EQ(run(middle, straight(0.25, 0.25, 0.5, 11)).reason,
            "covered 0% of the floor it could reach 0.50 m or more from walls (0 of 40 cells of 0.50 m); 20% required");
  EXPECT_TRUE(run({.kind = Kind::Coverage, .fraction = 0.16, .cell = 0.5}, straight(0.25, 0.25, 0.5, 11)).passed);  // all the floor: 12 of 72
}

TEST(Judge, RobotsApart) {
  RunRecord r = room();
  r.robots = {straight(1, 1.5, 0.5, 4, "ada"), straight(5, 1.5, -0.5, 4, "bob")};
  // Their bodies touch when the centres are 0.46 m apart (after 3.54 s); 3.6 s is the first step
  // at which they are less than the centimetre Box2D lets touching bodies overlap.
  EXPECT_EQ(judge({.kind = Kind::RobotsApart}, r).reason, "ada and bob touched at 3.6 s at (3.0, 1.5)");
  r.robots[1] = straight(5, 2.5, -0.5, 4, "bob");  // a metre apart sideways
  EXPECT_TRUE(judge({.kind = Kind::RobotsApart}, r).passed);
}

TEST(Judge, PathRatioAgainstTheShortestPathAroundAWall) {
  RunRecord r = room();
  // A wall from the floor to y = 2 at x = 3 between the start (1, 1) and the goal (5, 1).
  r.walls.insert(r.walls.begin(), worlds::segmentWall({3, 0}, {3, 2}));
  r.points = {{"goal", {5.0, 1.0}}};
  // The long way: up to y = 2.7, across, and down: 1.7 + 4 + 1.7 = 7.4 m (7.17 m until 0.23 m short).
  Track t{.name = "ada"};
  for (int k = 0; k <= 34; ++k) t.path.emplace_back(1, 1 + 0.05 * k);
  for (int k = 1; k <= 80; ++k) t.path.emplace_back(1 + 0.05 * k, 2.7);
  for (int k = 1; k <= 34; ++k) t.path.emplace_back(5, 2.7 - 0.05 * k);
  const Verdict tight = run({.kind = Kind::PathRatio, .ratio = 1.2}, t, r);
  ASSERT_FALSE(tight.passed);
  // Round the wall's end with the body 0.23 m clear: 2 × |(2, 1.23)| = 4.70 m; the grader's path
  // is straightened to within a few centimetres of it.
  double travelled = 0, shortest = 0;
  ASSERT_EQ(std::sscanf(tight.reason.c_str(), "drove %lf m to goal; the shortest path is %lf m", &travelled, &shortest), 2) << tight.reason;
  EXPECT_NEAR(travelled, 7.2, 1e-9);  // stops at the first step within 0.23 m: (5, 1.2)
  EXPECT_GE(shortest, 4.69);
  EXPECT_LE(shortest, 4.76);
  EXPECT_TRUE(run({.kind = Kind::PathRatio, .ratio = 1.6}, t, r).passed);
}

TEST(Judge, Bug1BoundCountsThePerimetersOfTheObstaclesMet) {
  RunRecord r = room();
  r.walls.insert(r.walls.begin(), worlds::rectangleWall({2.5, 0.5}, {3.5, 2.5}));  // 1 x 2 m block: perimeter 6 m
  r.walls.insert(r.walls.begin(), worlds::circleWall({5.5, 2.5}, 0.2));            // far from the path: not met
  r.points = {{"goal", {5.0, 1.5}}};
  Track t{.name = "ada"};
  for (int k = 0; k <= 40; ++k) t.path.emplace_back(1 + 0.05 * k, 1.5);  // to the block
  t.path.emplace_back(5.0, 1.5);                                         // and a jump to the goal
  // Drove 2 + 2 = 4 m (the jump included); the bound is 4 m direct + 1.5 × 6 m = 13 m.
  EXPECT_TRUE(run({.kind = Kind::Bug1Bound}, t, r).passed);
  EXPECT_EQ(run({.kind = Kind::Bug1Bound}, t, r).margin->said(true), "passed by 9.00 m (drove 4.00 m to goal; the BUG1 bound is 13.00 m)");
  // Dithering below the block: 1.20 m there, 399 jumps of 0.9 m, 3.23 m to the goal: 365.54 m.
  for (int k = 0; k < 400; ++k) t.path.insert(t.path.end() - 1, k % 2 == 0 ? Point2(2.9, 0.3) : Point2(2.0, 0.3));
  EXPECT_EQ(run({.kind = Kind::Bug1Bound}, t, r).reason,
            "drove 365.54 m to goal; the BUG1 bound is 13.00 m (4.00 m direct + 1.5 × 6.00 m of perimeter of the 1 obstacles met)");
}

// How near the edge: a margin for every criterion, in its unit, passed or failed, with the instant
// that decided it; none where nothing was measured.
std::string margin(const Verdict& v) { return v.margin ? v.margin->said(v.passed) : "none"; }

TEST(Judge, MarginsSayHowNearTheEdgeARunWas) {
  const Verdict reached = run({.kind = Kind::Goal, .distance = 0.2, .seconds = 10}, straight(1, 1.5, 0.5, 9));
  EXPECT_EQ(margin(reached), "passed by 2.4 s (reached goal at 7.6 s of 10 s)");
  EXPECT_NEAR(reached.margin->value, 2.4, 1e-9);
  EXPECT_EQ(reached.margin->unit, "s");
  EXPECT_NEAR(*reached.margin->at, 7.6, 1e-9);
  EXPECT_EQ(margin(run({.kind = Kind::Goal, .distance = 0.2, .seconds = 7}, straight(1, 1.5, 0.5, 9))),
            "failed by 0.6 s (reached goal at 7.6 s of 7 s)");
  const Verdict never = run({.kind = Kind::Goal, .distance = 0.2}, straight(1, 1.5, 0.5, 4));
  EXPECT_EQ(margin(never), "failed by 1.80 m (closest 2.00 m to goal; 0.20 m needed)");
  EXPECT_NEAR(*never.margin->at, 4.0, 1e-9);
  EXPECT_EQ(margin(run({.kind = Kind::Goal, .distance = 0.2}, straight(1, 1.6, 0.5, 9))), "passed by 0.10 m (closest 0.10 m to goal; 0.20 m needed)");
  EXPECT_EQ(margin(run({.kind = Kind::Goal, .point = "exit", .distance = 0.2}, straight(1, 1.5, 0.5, 1))), "none");
  // Waypoints with a time bound: the last one's time; without, the one passed nearest the edge.
  EXPECT_EQ(margin(run({.kind = Kind::Waypoints, .points = {"a", "b"}, .distance = 0.2, .seconds = 10}, straight(1, 1.5, 0.5, 8))),
            "passed by 4.4 s (reached b at 5.6 s of 10 s)");
  Track bends = straight(1, 1.6, 0.5, 8);  // 0.10 m from a, then 0.15 m from b
  for (Point2& p : bends.path) p.y() += p.x() > 3 ? 0.05 : 0.0;
  EXPECT_EQ(margin(run({.kind = Kind::Waypoints, .points = {"a", "b"}, .distance = 0.2}, bends)),
            "passed by 0.05 m (closest 0.15 m to b; 0.20 m needed)");
  EXPECT_EQ(margin(run({.kind = Kind::Waypoints, .points = {"b", "a"}, .distance = 0.2}, bends)),
            "failed by 1.71 m (closest 1.91 m to a; 0.20 m needed)");

  Track bumps = straight(1, 1.5, 0.5, 2);
  bumps.contacts = {{41.2, {3.1, 2.75}}, {50.0, {4.0, 2.75}}};
  const Verdict over = run({.kind = Kind::Collisions, .count = 1}, bumps);
  EXPECT_EQ(margin(over), "failed by 1 collision (2 collisions; at most 1)");
  EXPECT_NEAR(*over.margin->at, 50.0, 1e-9);
  EXPECT_EQ(margin(run({.kind = Kind::Collisions, .count = 2}, bumps)), "passed by 0 collisions (2 collisions; at most 2)");
  EXPECT_EQ(margin(run({.kind = Kind::Collisions, .count = 0}, straight(1, 1.5, 0.5, 2))), "passed by 0 collisions (no collision; at most 0)");

  EXPECT_EQ(margin(run({.kind = Kind::Clearance, .distance = 0.1}, straight(1, 0.34, 0.5, 1))),
            "passed by 0.01 m (came within 0.11 m of a wall; at least 0.10 m required)");
  Track drift{.name = "ada"};
  for (int k = 0; k <= 100; ++k) drift.path.emplace_back(1 + 0.03 * k, 0.73 + 0.002 * k);
  EXPECT_EQ(margin(run({.kind = Kind::WallDistance, .distance = 0.5, .tolerance = 0.05, .fraction = 0.8, .after = 1.0}, drift)),
            "failed by 62 percentage points (kept 0.50 ± 0.05 m from the wall 18% of the time; 80% required)");
  EXPECT_EQ(margin(run({.kind = Kind::Coverage, .fraction = 0.16, .cell = 0.5}, straight(0.25, 1.25, 0.5, 11))),
            "passed by 1 percentage point (covered 17% of the floor it could reach; 16% required)");

  RunRecord keyed = room();
  keyed.keys = {{.time = 2.0, .key = 's'}};
  const Criterion stop{.kind = Kind::Stopped, .speed = 0.05, .afterKey = 's', .within = 1.0};
  EXPECT_EQ(margin(run(stop, stopsAt(2.8, 6), keyed)), "passed by 0.2 s (moved until 0.8 s after the key s was pressed; 1 s allowed)");
  EXPECT_EQ(margin(run(stop, stopsAt(3.5, 6), keyed)), "failed by 0.5 s (moved until 1.5 s after the key s was pressed; 1 s allowed)");
  EXPECT_EQ(margin(run({.kind = Kind::Stopped, .speed = 0.05}, straight(1, 1.5, 0.3, 2))),
            "failed by 0.25 m/s (moving at 0.30 m/s at the end; below 0.05 m/s needed)");
  Track reports = stopsAt(3.0, 5);
  reports.returned = "key";
  reports.returnedAt = 2.6;
  EXPECT_EQ(margin(run({.kind = Kind::Returns, .value = "key", .afterKey = 's'}, reports, keyed)),
            "passed by 0.4 s (returned 0.6 s after the key s was pressed; at most 1 s)");
  EXPECT_EQ(margin(run({.kind = Kind::Returns, .value = "key"}, reports, keyed)), "none") << "a value alone has no edge to be near";

  RunRecord pair = room();
  pair.robots = {straight(1, 1.5, 0.5, 4, "ada"), straight(5, 2.5, -0.5, 4, "bob")};
  EXPECT_EQ(margin(judge({.kind = Kind::RobotsApart}, pair)), "passed by 0.53 m (ada and bob came within 0.54 m of each other; 0.01 m required)");
  // Several robots: the one nearest the edge, named.
  pair.robots[1] = straight(1, 1.6, 0.5, 9, "bob");
  pair.robots[0] = straight(1, 1.5, 0.5, 9, "ada");
  EXPECT_EQ(margin(judge({.kind = Kind::Goal, .distance = 0.2}, pair)), "passed by 0.10 m (bob closest 0.10 m to goal; 0.20 m needed)");
}

TEST(Judge, TheReturnedValueIsTheControllers) {
  Track t = straight(1, 1.5, 0, 1);
  EXPECT_EQ(run({.kind = Kind::Returns, .value = "true"}, t).reason, "its task never returned a value (reported by the controller)");
  t.returned = "false";
  EXPECT_EQ(run({.kind = Kind::Returns, .value = "true"}, t).reason, "its task returned false, not true (reported by the controller)");
  t.returned = "";
  EXPECT_EQ(run({.kind = Kind::Returns, .value = "true"}, t).reason, "its task returned no value, not true (reported by the controller)");
  t.returned = "true";
  EXPECT_TRUE(run({.kind = Kind::Returns, .value = "true"}, t).passed);
}

TEST(Judge, EveryRobotMustMeetItAndTheOneThatFailsIsNamed) {
  RunRecord r = room();
  r.points = {{"goal_ada", {5.0, 1.5}}, {"goal_bob", {1.0, 2.5}}};
  r.robots = {straight(1, 1.5, 0.5, 9, "ada"), straight(5, 2.5, -0.5, 9, "bob")};
  const Criterion own{.kind = Kind::Goal, .point = "goal_{robot}", .distance = 0.2};
  EXPECT_TRUE(judge(own, r).passed);
  r.robots[1] = straight(5, 2.5, -0.5, 2, "bob");
  EXPECT_EQ(judge(own, r).reason, "bob never came within 0.20 m of goal_bob (closest 3.00 m, at 2.0 s)");
}

}  // namespace
}  // namespace frob::course
