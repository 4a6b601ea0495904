#pragma once
// What `frob run` precompiles for controller files: frob.hpp, and the templates most controllers
// instantiate (the task machinery of Task<Wheels, B> for the usual B, events, behaviors of numbers,
// points and pictures). The precompiled header is built with -fpch-codegen: their code is compiled
// once, into an object the controller host links and exports, and a student's compile only refers
// to it. A controller never includes this file. The functions below are never called.

#include "frob/frob.hpp"

#include <string>
#include <utility>
#include <vector>

namespace frob::detail::precompiled {

inline Task<Wheels> plain() { co_return; }
inline Task<Wheels, bool> answer() { co_return true; }
inline Task<Wheels, double> number() { co_return 1.0; }
inline Task<Wheels, int> count() { co_return 1; }
inline Task<Wheels, char> key() { co_return 'k'; }
inline Task<Wheels, std::string> text() { co_return std::string(); }
inline Task<Wheels, Point2> point() { co_return Point2::Zero(); }

// Atomic tasks ending on the usual events, as mkTask and mkTaskE build them.
inline Task<Wheels> drive(const Behavior<double>& d) {
  return mkTask([d](const TaskState&) { return std::pair{wheels(d, 0.0), predicate(d < 1.0) | after(1.0)}; });
}
inline Task<Wheels, bool> choose(const Behavior<double>& d) {
  return mkTask([d](const TaskState&) { return std::pair{wheels(d, d), predicate(d > 1.0).as(true) | after(1.0).as(false)}; });
}
inline Task<Wheels, char> pressed(const Robot& r) {
  return mkTask([r](const TaskState&) { return std::pair{wheels(0.0, 0.0), keyboard(r)}; });
}
inline Task<Wheels, BumperHit> bumped(const Robot& r) {
  return mkTask([r](const TaskState&) { return std::pair{wheels(0.0, 0.0), bumper(r)}; });
}
inline Task<Wheels> failing(const Robot& r) {
  return mkTaskE([r](const TaskState&) {
    return std::tuple{wheels(0.0, 0.0), after(1.0), bumper(r).map([](const BumperHit&) { return RoboErr("hit"); })};
  });
}

// Lifted functions of the usual signatures (one node type each, whatever the lambda).
inline void lifts(const Behavior<double>& d, const Behavior<bool>& b, const Behavior<Point2>& p, const Behavior<std::vector<double>>& v) {
  (void)lift([](double) { return 0.0; }, d), (void)lift([](double, double) { return 0.0; }, d, d);
  (void)lift([](double, double, double) { return 0.0; }, d, d, d), (void)lift([](double) { return true; }, d);
  (void)lift([](double, double) { return true; }, d, d), (void)lift([](bool) { return true; }, b);
  (void)lift([](double, double) { return Wheels{}; }, d, d), (void)lift([](double) { return Wheels{}; }, d);
  (void)lift([](const std::vector<double>&) { return 0.0; }, v), (void)lift([](const std::vector<double>&) { return true; }, v);
  (void)lift([](const Point2&) { return 0.0; }, p), (void)lift([](const Point2&, double) { return 0.0; }, p, d);
  (void)lift([](const Point2&) { return Point2(); }, p), (void)lift([](const Point2&, double) { return Point2(); }, p, d);
  (void)lift([](const Point2&, double) { return Wheels{}; }, p, d), (void)lift([](const Point2&, double) { return true; }, p, d);
  (void)lift([](const Point2&) { return Picture{}; }, p), (void)lift([](double) { return Picture{}; }, d);
  (void)lift([](const Point2&, double) { return Picture{}; }, p, d);
}

// A sequence of them, with the transformers controllers use most.
inline Task<Wheels> sequence() {
  const TaskState ts = co_await getTaskState();
  const Robot& r = ts.robot();
  co_await plain();
  if (co_await answer()) co_await become(plain());
  (void)co_await number(), (void)co_await count(), (void)co_await key(), (void)co_await text(), (void)co_await point();
  co_await drive(sonar(r, 0));
  (void)co_await choose(orientation(r));
  (void)co_await timeLimit(drive(velocity(r)), 1.0);
  (void)co_await timeLimit(choose(sonar(r, 1)), 1.0);
  (void)co_await withExit(keyboard(r), plain());
  (void)co_await withExit(predicate(sonar(r, 2) < 1.0), plain());
  (void)co_await pressed(r), (void)co_await bumped(r);
  co_await taskCatch(failing(r), [](const RoboErr&) { return plain(); });
  co_await withPicture(constant(Picture{}), plain());
  co_await withPlot("value", sonar(r, 3), plain());
  co_await taskError(RoboErr("none"));
}

inline Controller controller() { return makeController(sequence); }

}  // namespace frob::detail::precompiled
