// A controller using every public construct of frob, compiled as a student's file is with
// -Wall -Wextra -Werror: frob's own headers must not warn in any of them.
#include <frob/frob.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>

using namespace frob;
using namespace frob::literals;

Behavior<double> ahead(const Robot& r) { return min(frontSonar(r), sonar(r, 1), sonar(r, 15)); }

// Behaviors and events.
Behavior<double> signals(const Robot& r) {
  Behavior<double> t = time();
  Behavior<double> mixed = max(abs(sin(t)) * 2.0 + 1.0, clamp(ahead(r) - leftSonar(r), -1.0, 1.0));
  Behavior<double> calculus = integral(velocity(r)) + derivative(orientation(r)) + atMin(ahead(r), t) + atMax(rightSonar(r), t);
  Behavior<double> held = hold(0.0, keyboard(r).map([](char c) { return static_cast<double>(c); }));
  Behavior<double> switched = switcher(constant(1.0), bumper(r).as(constant(2.0)));
  Behavior<double> until = untilB(backSonar(r), after(1.0).as(constant(3.0)));
  Behavior<double> lifted = lift([](double a, double b) { return a * b; }, mixed, calculus);
  Behavior<double> geometry = norm(place(r) - Point2(1, 1)) + heading(place(r) - Point2(2, 2)) + wrapAngle(atan2(t, 1.0)) + pow(t, 2.0);
  return lifted + held + switched + until + geometry + distance(place(r), Point2(0, 0));
}

Event<Unit> events(const Robot& r) {
  Event<Unit> e = predicate(ahead(r) < 50_cm && !(velocity(r) > 1.0) || ahead(r) == 0.0);
  Event<std::int64_t> ticks = every(0.5).filter([](std::int64_t n) { return n % 2 == 0; });
  Event<std::pair<Unit, double>> snap = snapshot(once(after(2.0)), ahead(r));
  return e | ticks.as(Unit{}) | snap.as(Unit{}) | never() | atPlace(r, Point2(1, 1), 0.2);
}

// Tasks and their transformers.
Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(30_cm + 0.0 * signals(r), 0), events(r)};
  });
}
Task<Wheels, int> careful() {
  return mkTaskE([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::tuple{wheels(10_cm, 0), after(1.0).as(1), bumper(r).map([](const BumperHit&) { return RoboErr("bumped"); })};
  });
}
Task<Wheels, double> measured() {
  TaskState ts = co_await getTaskState();
  co_await setTaskState(ts);
  std::optional<int> r = co_await timeLimit(careful(), 2.0);
  if (!r) co_await taskError(RoboErr("too slow"));
  const bool inTime = co_await timeLimit(goAhead(), 1.0);
  auto [value, distanceDriven] = co_await withB([](const TaskState& s) { return norm(place(s.robot()) - s.initialPlace()); }, careful());
  const int stoppedWith = co_await withExit(after(3.0).as(4), goAhead());
  co_return distanceDriven + value + stoppedWith + (inTime ? 1 : 0);
}
Task<Wheels, double> caught() {
  return taskCatch(addError(after(5.0).as(RoboErr("late")), measured()), [](const RoboErr&) {
    return mkTask([](const TaskState&) { return std::pair{wheels(0, 0), after(0.1).as(0.0)}; });
  });
}
Task<Wheels> pictured() {
  return withPicture(paintAt(Point2(1, 1), withColor(red, circle(10_cm) + line({0, 0}, {1, 1}) + text("goal"))),
                     withPlot("ahead", Behavior<double>(0.5),
                              withFilter(
                                  [](const Wheels& w) {
                                    return Wheels{w.forward * 0.5, w.turn};
                                  },
                                  goAhead())));
}
Task<Wheels> fed() {
  return withMyResult([](Behavior<Wheels> mine) {
    return mkTask([mine](const TaskState&) { return std::pair{lift([](const Wheels& w) { return Wheels{w.forward + 0.1, 0}; }, mine), after(1.0)}; });
  });
}
Wheels add(const Wheels& a, const Wheels& b) { return {a.forward + b.forward, a.turn + b.turn}; }
Task<Wheels> together() {
  auto [a, b] = co_await parallel(careful(), Task<Wheels>(fed()), add);
  (void)a;
  (void)b;
  std::variant<int, Unit> first = co_await disable(careful(), pictured(), add);
  (void)first;
  co_await withTask(
      [](Behavior<Wheels>) {
        return Task<double>(mkTask([](const TaskState&) { return std::pair{Behavior<double>(1.0), after(1.0)}; }));
      },
      [](Behavior<double>, Event<Outcome<void>> end) { return withExit(end, goAhead()); });
}
Task<Wheels> everything() {
  (void)co_await caught();
  co_await together();
  co_await become(Task<Wheels>(syncLoop([] { return goAhead(); }, [] { return pictured(); })));
}
Task<Wheels> spawning() {
  co_await asyncLoop([] { return goAhead(); }, [] { return fed(); }, add);
}

FROB_CONTROLLER(everything, .world = "empty", .seconds = 10)
