// The adversary of every assignment's hidden checks (blind.hpp): for each assignment, the best blind
// controllers of several kinds, each the best of its kind on practice worlds, must earn at most a
// third of any hidden check's points under fresh secrets. The kinds: a fixed route by odometry, optimised
// over many practice worlds for clearance; bump-and-slide (drive at the target, slide off what it
// bumps); hugging the walls; a timetable (waiting and driving by the clock); events "reported" at
// fixed times. The reference solutions' full marks are each assignment's own test
// (SolutionGetsFullMarksOnEveryCheck). The shares found are printed, for the instructors' guide.
#include "blind.hpp"
#include "frob/worlds/free_space.hpp"
#include "grade_assignment.hpp"

#include <cstdio>

namespace frob::testing::blind {
namespace {

constexpr double kBody = 0.23;           // the Nomad's radius
constexpr double kMostHidden = 1.0 / 3;  // what a blind controller may earn of a hidden check's points, at most
constexpr int kPracticeWorlds = 3;       // per hidden check, to choose the best of a kind by simulation
constexpr int kSecrets = 6;              // fresh secrets to score the best of each kind under

course::Rubric rubricOf(const std::string& assignment) {
  Result<course::Rubric> r = course::loadRubric(assignmentFile(assignment, "rubric.toml"));
  EXPECT_TRUE(r.ok()) << r.error();
  return r.value();
}

// The worlds of the hidden checks' families a student can draw: `n` of each, from practice seeds.
std::vector<worlds::WorldDef> practiceWorlds(const course::Rubric& rubric, int n) {
  std::vector<worlds::WorldDef> all;
  for (const course::Check& c : course::practiceRubric(rubric, n, 2).checks) {
    for (std::uint64_t seed : c.generated->seeds) all.push_back(worlds::generateWorld(c.generated->kind, seed).value());
  }
  return all;
}

// The share of `ws` in which a body driving `route` (from each world's start) keeps `margin` clear of every wall.
double clearShare(const std::vector<Point2>& route, const std::vector<worlds::WorldDef>& ws, double margin) {
  int clear = 0;
  for (const worlds::WorldDef& w : ws) {
    std::vector<worlds::WallDef> walls = w.walls;
    if (w.enclosed) {
      const Point2 a(0, 0), b(w.size.x(), 0), c = w.size, d(0, w.size.y());
      for (auto [p, q] : {std::pair{a, b}, {b, c}, {c, d}, {d, a}}) walls.push_back(worlds::segmentWall(p, q));
    }
    const worlds::WallIndex index(walls, w.size, 1.0);
    Point2 from = w.robots.front().start.position;
    bool ok = true;
    for (std::size_t k = 0; k < route.size() && ok; from = route[k++]) {
      const int n = std::max(1, static_cast<int>((route[k] - from).norm() / 0.05));
      for (int s = 0; s <= n && ok; ++s) ok = index.distance(from + (route[k] - from) * (static_cast<double>(s) / n)) >= kBody + margin;
    }
    clear += ok;
  }
  return static_cast<double>(clear) / static_cast<double>(ws.size());
}

// A route through `targets` with a via point before each, chosen among `offsets` (m, square to the
// leg at its middle) one leg at a time, twice over, for the most practice worlds in which the whole
// route stays clear: the route a student would tune on the practice family.
std::vector<Point2> bestRoute(const Point2& start, const std::vector<Point2>& targets, const std::vector<worlds::WorldDef>& ws) {
  const std::vector<double> offsets = {-3, -2.5, -2, -1.5, -1, -0.5, 0, 0.5, 1, 1.5, 2, 2.5, 3};
  std::vector<double> chosen(targets.size(), 0.0);
  const auto routeWith = [&](const std::vector<double>& off) {
    std::vector<Point2> r;
    Point2 from = start;
    for (std::size_t k = 0; k < targets.size(); ++k) {
      const Vec2 leg = targets[k] - from, across = Vec2(-leg.y(), leg.x()).normalized();
      r.push_back(from + leg / 2 + across * off[k]);
      r.push_back(targets[k]);
      from = targets[k];
    }
    return r;
  };
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t k = 0; k < targets.size(); ++k) {
      double best = -1;
      for (double o : offsets) {
        std::vector<double> off = chosen;
        off[k] = o;
        const double s = clearShare(routeWith(off), ws, 0.1);
        if (s > best) best = s, chosen[k] = o;
      }
    }
  }
  return routeWith(chosen);
}

// The best of each kind on practice worlds, scored on the hidden checks under fresh secrets: at most
// a third of any one's points. Prints each kind's practice share and its most of a hidden check.
void expectNoBlindKindEarnsHiddenPoints(const std::string& assignment, const std::vector<std::pair<std::string, std::vector<Candidate>>>& kinds) {
  const course::Rubric rubric = rubricOf(assignment);
  for (const auto& [kind, candidates] : kinds) {
    const auto [best, practice] = bestOnPractice(rubric, candidates, kPracticeWorlds);
    const double hidden = hiddenShare(rubric, best.strategy, kSecrets);
    std::printf("%s: %s: best %s: %.2f of the practice points, at most %.2f of a hidden check's\n", assignment.c_str(), kind.c_str(),
                best.name.c_str(), practice, hidden);
    EXPECT_LE(hidden, kMostHidden) << kind << ": " << best.name;
  }
}

// Drive at each target in turn; on a bump back off, turn and drive on a little, then at the target again.
std::vector<Candidate> bumpAndSlide(const std::vector<Point2>& targets) {
  std::vector<Candidate> all;
  for (double turn : {-1.6, -0.8, 0.8, 1.6}) {
    for (double ahead : {0.5, 1.2}) {
      all.push_back({"bump-and-slide turn " + std::to_string(turn) + " ahead " + std::to_string(ahead),
                     [=](std::size_t) { return std::make_unique<Route>(RouteDef{.points = targets, .slideTurn = turn, .slideAhead = ahead}); }});
    }
  }
  return all;
}

// The route tuned on many practice worlds, driven at a few speeds.
std::vector<Candidate> tunedRoute(const course::Rubric& rubric, const std::vector<Point2>& targets) {
  const std::vector<worlds::WorldDef> ws = practiceWorlds(rubric, 40);
  const std::vector<Point2> route = bestRoute(ws.front().robots.front().start.position, targets, ws);
  std::printf("tuned route clear in %.2f of %zu practice worlds\n", clearShare(route, ws, 0.1), ws.size());
  std::vector<Candidate> all;
  for (double speed : {0.4, 0.6}) {
    all.push_back({"tuned route at " + std::to_string(speed) + " m/s",
                   [=](std::size_t) { return std::make_unique<Route>(RouteDef{.points = route, .speed = speed}); }});
  }
  return all;
}

TEST(BlindAdversary, GoToGoal) {
  const std::vector<Point2> wps = {{3.0, 2.5}, {3.5, 7.5}, {9.0, 7.0}, {8.5, 2.5}};
  const course::Rubric rubric = rubricOf("go_to_goal");
  // Along the walls: round the room 0.6 to 1.2 m from them, visiting each waypoint from the nearest side.
  std::vector<Candidate> hug;
  for (double d : {0.6, 0.9, 1.2}) {
    const std::vector<Point2> lap = {{d, 2.5},      wps[0], {d, 2.5},      {d, 7.5},      wps[1], {3.5, 10 - d},
                                     {9.0, 10 - d}, wps[2], {12 - d, 7.0}, {12 - d, 2.5}, wps[3]};
    hug.push_back({"walls at " + std::to_string(d), [=](std::size_t) { return std::make_unique<Route>(RouteDef{.points = lap}); }});
  }
  expectNoBlindKindEarnsHiddenPoints("go_to_goal",
                                     {{"fixed route", tunedRoute(rubric, wps)}, {"bump-and-slide", bumpAndSlide(wps)}, {"wall hugging", hug}});
}

TEST(BlindAdversary, Bug) {
  const Point2 goal(13.5, 13.5);
  const course::Rubric rubric = rubricOf("bug");
  std::vector<Candidate> edges;  // along two walls to the goal's corner, either way round, some way off them
  for (double d : {0.5, 0.8, 1.1}) {
    for (bool eastFirst : {true, false}) {
      const std::vector<Point2> way = eastFirst ? std::vector<Point2>{{1.5, d}, {15 - d, d}, {15 - d, 13.5}, goal}
                                                : std::vector<Point2>{{d, 1.5}, {d, 15 - d}, {13.5, 15 - d}, goal};
      edges.push_back({std::string(eastFirst ? "east" : "north") + " edge at " + std::to_string(d), [=](std::size_t) {
                         return std::make_unique<Route>(RouteDef{.points = way, .slideTurn = eastFirst ? 0.8 : -0.8, .slideAhead = 0.5});
                       }});
    }
  }
  // Along a wall, over the tip of the spur beside the start (in the start's clear circle), then on
  // along that wall, or on over the tips of any further spurs, and up the far one.
  std::vector<Candidate> band;
  for (double d : {0.55, 0.8}) {
    for (double over : {2.4, 2.7, 3.0}) {
      for (bool eastFirst : {true, false}) {
        for (bool overAll : {false, true}) {
          std::vector<Point2> way = overAll ? std::vector<Point2>{{2.6, d}, {2.6, over}, {15 - d, over}, {15 - d, 13.5}, goal}
                                            : std::vector<Point2>{{2.6, d}, {2.6, over}, {4.6, over}, {4.6, d}, {15 - d, d}, {15 - d, 13.5}, goal};
          if (!eastFirst) std::transform(way.begin(), way.end(), way.begin(), [](const Point2& p) { return Point2(p.y(), p.x()); });
          band.push_back({std::string(eastFirst ? "east" : "north") + " band at " + std::to_string(d) + " over " +
                              (overAll ? "every spur" : "the first spur") + " at " + std::to_string(over),
                          [=](std::size_t) { return std::make_unique<Route>(RouteDef{.points = way}); }});
        }
      }
    }
  }
  expectNoBlindKindEarnsHiddenPoints("bug", {{"fixed route", tunedRoute(rubric, {goal})},
                                             {"bump-and-slide", bumpAndSlide({goal})},
                                             {"wall hugging", edges},
                                             {"the band by the walls, over the start's spurs", band}});
}

// Each robot's goal is opposite its start through the centre (5, 5).
Point2 opposite(const Pose2& start) { return Point2(10, 10) - start.position; }

TEST(BlindAdversary, MultiRobot) {
  std::vector<Candidate> timetable;  // straight across, each robot waiting a time set by the direction it starts in
  for (double spread : {0.0, 4.0, 8.0, 12.0}) {
    for (double speed : {0.4, 0.6}) {
      timetable.push_back(
          {"straight, waits up to " + std::to_string(spread) + " s at " + std::to_string(speed) + " m/s", fromStart([=](const Pose2& s, std::size_t) {
             const double angle = std::atan2(s.position.y() - 5, s.position.x() - 5) + pi;  // (0, 2 pi]
             return RouteDef{.points = {opposite(s)}, .speed = speed, .startAt = spread * angle / (2 * pi)};
           })});
    }
  }
  std::vector<Candidate> slide;
  for (double turn : {-1.6, 0.8, 1.6}) {
    slide.push_back({"bump-and-slide turn " + std::to_string(turn), fromStart([=](const Pose2& s, std::size_t) {
                       return RouteDef{.points = {opposite(s)}, .slideTurn = turn, .slideAhead = 0.8};
                     })});
  }
  expectNoBlindKindEarnsHiddenPoints("multi_robot", {{"timetable", timetable}, {"bump-and-slide", slide}});
}

// A roundabout: every robot onto one circle round the centre, round it either way to its goal's
// side, then out. It needs no clock, and robots whose ways cross at 60 degrees or more rarely meet
// on it: it earned 0.92 of the hidden points before the crossing family stood pillars round the
// middle (every circle of 1 to 3 m blocked); small circles crowd the robots into each other.
TEST(BlindAdversary, MultiRobotRoundabout) {
  std::vector<Candidate> roundabout;
  for (double way : {1.0, -1.0}) {  // counter-clockwise, clockwise
    for (double radius : {0.6, 1.0, 1.6, 2.2, 2.8, 3.4}) {
      for (double speed : {0.4, 0.6}) {
        roundabout.push_back({"roundabout of " + std::to_string(radius) + " m, " + (way > 0 ? "counter-clockwise" : "clockwise") + ", at " +
                                  std::to_string(speed) + " m/s",
                              fromStart([=](const Pose2& s, std::size_t) {
                                const double a = std::atan2(s.position.y() - 5, s.position.x() - 5);
                                RouteDef r{.speed = speed, .within = 0.15};
                                for (int k = 0; k <= 12; ++k) {
                                  const double at = a + way * k * pi / 12;
                                  r.points.push_back(Point2(5, 5) + radius * Vec2(std::cos(at), std::sin(at)));
                                }
                                r.points.push_back(opposite(s));
                                return r;
                              })});
      }
    }
  }
  expectNoBlindKindEarnsHiddenPoints("multi_robot", {{"roundabout", roundabout}});
}

TEST(BlindAdversary, Parallel) {
  const std::vector<Point2> patrol = {{1.5, 1.5}, {6.5, 1.5}, {6.5, 4.5}, {1.5, 4.5}};
  std::vector<Candidate> reported;  // the patrol, stopped and a reason reported at fixed times: no keyboard, no bumpers
  for (double stop = 14; stop <= 26; stop += 1) {
    for (const char* what : {"key", "bumped"}) {
      reported.push_back({std::string(what) + " at " + std::to_string(stop) + " s", [=](std::size_t) {
                            return std::make_unique<Route>(
                                RouteDef{.points = patrol, .stopAt = stop, .report = what, .reportAt = stop, .loop = true});
                          }});
    }
  }
  // The patrol, stopped at the first key after a set time, whichever key it is, that is at least the
  // `nth` key and comes within `gap` s of the one before: the keyboard read but never for s.
  class AnyKeyAfter final : public Program {
   public:
    AnyKeyAfter(std::vector<Point2> patrol, double after, int nth, double gap)
        : patrol_(RouteDef{.points = std::move(patrol), .loop = true}), after_(after), nth_(nth), gap_(gap) {}
    Wheels step(double t, const SensorFrame& f) override {
      if (!f.keys.empty()) {
        if (++seen_ >= nth_ && t >= after_ && t - last_ <= gap_) report = "key";
        last_ = t;
      }
      return patrol_.step(t, f);
    }

   private:
    Route patrol_;
    double after_;
    int nth_;
    double gap_;
    int seen_ = 0;
    double last_ = -INFINITY;
  };
  std::vector<Candidate> anyKey;
  for (double after = 10; after <= 23; after += 1) {
    anyKey.push_back(
        {"any key after " + std::to_string(after) + " s", [=](std::size_t) { return std::make_unique<AnyKeyAfter>(patrol, after, 1, INFINITY); }});
  }
  // Or at the first key after a set time that is at least the n-th and comes soon after the one
  // before: s as the keys' timing once gave it away (the one other key 0.5 to 3 s before it).
  for (int nth : {2, 3, 4}) {
    for (double after : {14.0, 16.0}) {
      anyKey.push_back({"key " + std::to_string(nth) + " or later, after " + std::to_string(after) + " s, within 3 s of the last",
                        [=](std::size_t) { return std::make_unique<AnyKeyAfter>(patrol, after, nth, 3.0); }});
    }
  }
  expectNoBlindKindEarnsHiddenPoints("parallel", {{"events reported at fixed times", reported}, {"any key after a set time", anyKey}});
}

TEST(BlindAdversary, Wander) {
  std::vector<Candidate> laps;  // round the room along its walls, or up and down it, sized for the family's rooms
  std::vector<Candidate> rows;
  for (double d : {0.5, 0.8, 1.1}) {
    for (double width : {5.5, 6.5}) {
      laps.push_back(
          {"lap " + std::to_string(d) + " from walls of a " + std::to_string(width) + " m room", fromStart([=](const Pose2& s, std::size_t) {
             const double top = 2.0 + 4.5 - d;
             return RouteDef{.points = {{s.position.x(), 2.0 + d}, {width - d, 2.0 + d}, {width - d, top}, {d, top}, {d, 2.0 + d}}, .loop = true};
           })});
      rows.push_back({"rows " + std::to_string(d) + " apart in a " + std::to_string(width) + " m room", fromStart([=](const Pose2& s, std::size_t) {
                        RouteDef r{.points = {{s.position.x(), 2.6}}};
                        bool east = false;
                        for (double y = 2.6; y <= 6.0; y += d, east = !east) {
                          r.points.push_back({east ? 0.6 : width - 0.6, y});
                          r.points.push_back({east ? width - 0.6 : 0.6, y});
                        }
                        return r;
                      })});
    }
  }
  // Almost blind: out of the hall, then legs in a fixed cycle of compass headings, each ended by the
  // sonar straight ahead (the one sonar read) and nothing else: round the room by its walls, again
  // and again, never turning towards room (it covered the outer metre of every room, and with it
  // most of the floor, before the floor counted was the middle).
  class LegsByTheSonarAhead final : public Program {
   public:
    LegsByTheSonarAhead(std::vector<double> headings, double stop) : headings_(std::move(headings)), stop_(stop) {}
    Wheels step(double t, const SensorFrame& f) override {
      const auto steer = [&](double heading, double forward) {
        const double e = wrap(heading - f.odometry.heading);
        return Wheels{std::abs(e) > 0.05 ? 0.0 : forward, std::clamp(3.0 * e, -1.0, 1.0)};
      };
      if (!leftHall_ && f.odometry.position.y() < 2.53) return steer(pi / 2, 0.5);  // out of the hall, straight on
      leftHall_ = true;
      const double ahead = f.sonar.at(0);
      if (ahead < stop_ + 0.03 && t - legStart_ > 1.0) ++leg_, legStart_ = t;  // a leg ends where something is ahead
      return steer(headings_[leg_ % headings_.size()], std::clamp((ahead - stop_) * 1.2, 0.0, 0.5));
    }

   private:
    std::vector<double> headings_;
    double stop_;
    std::size_t leg_ = 0;
    double legStart_ = 0.0;
    bool leftHall_ = false;
  };
  std::vector<Candidate> legs;
  for (const std::vector<double>& cycle :
       {std::vector<double>{pi, pi / 2, 0, -pi / 2}, std::vector<double>{pi, pi / 2, -pi / 2, 0, pi / 2, -pi / 2}}) {
    for (double stop : {0.3, 0.45}) {
      legs.push_back({std::to_string(cycle.size()) + " headings, legs ended " + std::to_string(stop) + " m from what is ahead",
                      [=](std::size_t) { return std::make_unique<LegsByTheSonarAhead>(cycle, stop); }});
    }
  }
  expectNoBlindKindEarnsHiddenPoints("wander", {{"wall hugging", laps}, {"fixed route", rows}, {"legs by the sonar ahead", legs}});
}

TEST(BlindAdversary, WallFollow) {
  std::vector<Candidate> laps;  // round a rectangle 0.63 m inside the walls, from the start (1.2-1.8 m, 0.78-0.88 m from the south-west corner)
  for (double width : {6.0, 6.75, 7.5}) {
    for (double height : {5.0, 5.5, 6.0}) {
      laps.push_back({"lap of a " + std::to_string(width) + " x " + std::to_string(height) + " m room", fromStart([=](const Pose2& s, std::size_t) {
                        const Point2 o = s.position - Vec2(1.5, 0.83);
                        const double in = 0.63;
                        return RouteDef{.points = {o + Vec2(width - in, in), o + Vec2(width - in, height - in), o + Vec2(in, height - in),
                                                   o + Vec2(in, in), o + Vec2(width - in, in)},
                                        .speed = 0.4};
                      })});
    }
  }
  expectNoBlindKindEarnsHiddenPoints("wall_follow", {{"wall hugging", laps}});
}

}  // namespace
}  // namespace frob::testing::blind
