#pragma once
// What `frob run` precompiles for controller files: frob.hpp, and the templates most controllers
// instantiate (the task machinery of Task<Wheels, B> for the usual B, events, behaviors of numbers,
// points and pictures, the operators on them, lists of numbers). The precompiled header is built
// with -fpch-codegen: their code is compiled once, into an object the controller host links and
// exports, and a student's compile only refers to it. Each function here also costs every compile
// a little (clang reads it, some 8 us), against about a millisecond to compile it in a controller:
// only what most controllers use belongs here. A controller never includes this file. The
// functions below are never called.

#include "frob/frob.hpp"

#include <optional>
#include <string>
#include <type_traits>
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

// Operators and functions on the usual operands: numbers (double, int, Behavior<double>, a sonar's
// Reading<double>), truths and points, in either order (each pair is an instantiation of its own).
template <class A, class C>
void numbers(const A& a, const C& c) {
  (void)(a + c), (void)(a - c), (void)(a * c), (void)(a / c), (void)(a < c), (void)(a <= c), (void)(a > c), (void)(a >= c);
  (void)(a == c), (void)(a != c), (void)max(a, c), (void)min(a, c), (void)atan2(a, c), (void)pow(a, c), (void)wheels(a, c);
}
template <class A>
void number(const A& a) {
  (void)-a, (void)sin(a), (void)cos(a), (void)tan(a), (void)asin(a), (void)acos(a), (void)atan(a), (void)sqrt(a), (void)exp(a);
  (void)log(a), (void)abs(a), (void)floor(a), (void)ceil(a), (void)wrapAngle(a), (void)max(a, a, a), (void)min(a, a, a);
  (void)clamp(a, a, a), (void)clamp(a, -1.0, 1.0), (void)clamp(a, -1, 1), (void)wheels(a, 0), (void)wheels(0, a);
}
template <class A, class C>
void points(const A& a, const C& c) {
  (void)(a + c), (void)(a - c), (void)distance(a, c);
}
inline void operands(const Robot& r, const Behavior<double>& d, const Behavior<bool>& b, const Behavior<Point2>& p) {
  const Reading<double> s = sonar(r, 0);
  const Reading<Point2> at = place(r);
  numbers(d, d), numbers(d, s), numbers(s, d), numbers(s, s);
  numbers(d, 1.0), numbers(1.0, d), numbers(d, 1), numbers(1, d), numbers(s, 1.0), numbers(1.0, s), numbers(s, 1), numbers(1, s);
  number(d), number(s);
  (void)(b && b), (void)(b || b), (void)!b, (void)(b && true), (void)(true && b), (void)(b || true), (void)(true || b);
  (void)(b == b), (void)(b != b);
  points(p, p), points(p, at), points(at, p), points(at, at), points(p, Point2()), points(Point2(), p), points(at, Point2()), points(Point2(), at);
  (void)(p * d), (void)(d * p), (void)(p * 1.0), (void)(1.0 * p), (void)(p / d), (void)(p / 1.0), (void)(at * 1.0), (void)(1.0 * at);
  (void)norm(p), (void)norm(at), (void)heading(p), (void)heading(at), (void)(-p), (void)Behavior<Point2>(p);
  (void)toBehavior(at), (void)toBehavior(s), (void)toBehavior(p), (void)toBehavior(b), (void)toBehavior(d);
}

// Tasks of the usual result types awaited by the usual tasks, and the usual transformers.
template <class B>
Task<Wheels, B> made() {
  if constexpr (std::is_void_v<B>) {
    co_return;
  } else {
    co_return B{};
  }
}
template <class B>
Task<Wheels, B> awaiting() {
  co_await made<void>(), (void)co_await made<bool>(), (void)co_await made<double>(), (void)co_await made<int>();
  (void)co_await made<char>(), (void)co_await made<std::string>(), (void)co_await made<Point2>(), (void)co_await made<BumperHit>();
  (void)co_await made<std::optional<bool>>(), (void)co_await timeLimit(made<B>(), 1.0);
  if constexpr (std::is_void_v<B>) {
    co_await taskCatch(made<B>(), [](const RoboErr&) { return made<B>(); });
  } else {
    co_return co_await taskCatch(made<B>(), [](const RoboErr&) { return made<B>(); });
  }
}
inline Task<Wheels> transformed(const Robot& r) {
  (void)awaiting<bool>();
  co_await awaiting<void>();
  (void)co_await withExit(bumper(r), made<void>()), (void)co_await withExit(after(1.0).as(true), made<void>());
  (void)co_await withB([r](const TaskState&) { return place(r); }, made<void>());
  (void)co_await withB([r](const TaskState&) { return sonar(r, 0); }, made<void>());
  (void)co_await addError(bumper(r).map([](const BumperHit&) { return RoboErr("hit"); }), made<void>());
}

// The standard library as controllers use it beside frob: lists of numbers and points, text.
inline void library(std::vector<double> v, std::vector<int> n, std::vector<Point2> p, std::string t) {
  std::vector<double> w = v;
  w = std::move(v), w.push_back(1.0), w.emplace_back(2.0), w.resize(w.size() + 1), w = {1.0, 2.0};
  for (double& x : w) x += w[0];
  for (const double& x : std::as_const(w)) (void)x;
  n = {1, 2}, n.push_back(3), n.emplace_back(4), (void)n.size(), (void)n[0];
  for (int& i : n) i += n.front() + n.back() + static_cast<int>(n.at(0));
  for (const int& i : std::as_const(n)) (void)i;
  std::vector<Point2> q = {Point2(0.0, 0.0)};
  q.push_back(Point2(1.0, 1.0)), q.emplace_back(2.0, 2.0), q = p, (void)q.size(), (void)q[0], (void)q.front(), (void)q.back();
  for (const Point2& x : q) (void)x;
  t += "x", t = t + std::to_string(1.0) + std::to_string(1), (void)(t == "x");
}

}  // namespace frob::detail::precompiled
