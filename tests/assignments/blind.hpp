#pragma once
// The adversary of the hidden checks: blind controllers, which know only what a robot knows without
// looking (the time, its odometry, and the bumper contacts and keys of the step; no sonar, but in a
// kind that says so the one straight ahead, to end a leg where something is in the way), run
// in this process and judged by the grader's criteria. They are searched for on practice worlds only
// (practiceRubric: never a secret), and the best of each kind is then scored on the hidden checks'
// worlds drawn from fresh secrets, unfiltered by the reference (it passes nearly all of them).
#include "frob/grade/judge.hpp"
#include "frob/grade/rubric.hpp"
#include "frob/run/run_record.hpp"
#include "frob/worlds/run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace frob::testing::blind {

/// One robot's blind program: from the time and what it senses without looking to its wheels.
class Program {
 public:
  virtual ~Program() = default;
  /// The wheels at time `t` (s), from the frame's odometry, bumps and keys.
  virtual Wheels step(double t, const SensorFrame& frame) = 0;
  std::optional<std::string> report;  ///< what its task returned, once it has (then its wheels stop)
};
/// A blind controller: a program for robot `i` of a run.
using Strategy = std::function<std::unique_ptr<Program>(std::size_t i)>;

/// Runs the programs of a world, as a controller host would: a report ends the robot's task.
class Driver final : public worlds::ControllerDriver {
 public:
  Driver(const worlds::Simulation& sim, const Strategy& strategy) : sim_(sim), timelines_(sim.robotCount()), reportedAt_(sim.robotCount(), 0.0) {
    for (std::size_t i = 0; i < sim.robotCount(); ++i) programs_.push_back(strategy(i));
  }
  void decide(const Instant& now, std::span<Wheels> wheels, std::span<Picture>, std::vector<std::pair<std::size_t, std::string>>&) override {
    for (std::size_t i = 0; i < programs_.size(); ++i) {
      Program& p = *programs_[i];
      if (p.report) {
        wheels[i] = Wheels{};
        continue;
      }
      wheels[i] = p.step(now.time, sim_.frame(i));
      if (p.report) wheels[i] = Wheels{}, reportedAt_[i] = now.time + now.dt;  // heard after the step, as a task's end
    }
  }
  Timeline& timeline(std::size_t i) override { return timelines_.at(i); }
  /// The programs' reports, into the record of their run.
  void reportInto(course::RunRecord& record) const {
    for (std::size_t i = 0; i < programs_.size(); ++i) {
      if (programs_[i]->report) record.robots[i].returned = programs_[i]->report, record.robots[i].returnedAt = reportedAt_[i];
    }
  }

 private:
  const worlds::Simulation& sim_;
  std::vector<std::unique_ptr<Program>> programs_;
  std::vector<Timeline> timelines_;
  std::vector<double> reportedAt_;
};

/// `strategy` run in `world` with simulation seed `seed` for `seconds`, recorded as the grader records a run.
inline course::RunRecord run(const worlds::WorldDef& world, std::uint64_t seed, double dt, double seconds, const Strategy& strategy) {
  Driver* driver = nullptr;
  const auto factory = [&](const worlds::Simulation& sim) -> std::unique_ptr<worlds::ControllerDriver> {
    auto d = std::make_unique<Driver>(sim, strategy);
    driver = d.get();
    return d;
  };
  worlds::Run r(world, {.dt = dt, .seed = seed}, factory, {.keepSteps = false});
  course::RunRecorder recorder(r.simulation(), world);
  for (long k = 0, steps = std::lround(seconds / dt); k < steps; ++k) {
    r.step();
    recorder.stepped(r.simulation());
  }
  course::RunRecord record = std::move(recorder).finish(r.failures());
  driver->reportInto(record);
  return record;
}

/// The share of the points of `checks` that `strategy` earns, each check scored as the grader
/// scores it (points × runs passed / runs) in its worlds and seeds under `secret`.
inline double share(const course::Rubric& rubric, const std::vector<course::Check>& checks, const std::string& secret, const Strategy& strategy) {
  double earned = 0, points = 0;
  for (const course::Check& check : checks) {
    int passed = 0, runs = 0;
    for (const course::WorldRef& ref : course::worldsOf(check, secret)) {
      const Result<worlds::WorldDef> world = course::loadWorldRef(ref);
      EXPECT_TRUE(world.ok()) << ref.name;
      if (!world) continue;
      for (std::uint64_t seed : course::seedsOf(check, secret)) {
        const course::RunRecord record = run(world.value(), seed, rubric.dt, check.seconds, strategy);
        ++runs;
        passed +=
            std::all_of(check.criteria.begin(), check.criteria.end(), [&](const course::Criterion& c) { return course::judge(c, record).passed; });
        for (const auto& c : check.criteria) {
          auto v = course::judge(c, record);
          if (!v.passed) {
            std::printf("  %s: %s\n", ref.name.c_str(), v.reason.c_str());
            break;
          }
        }
      }
    }
    earned += runs == 0 ? 0.0 : check.points * passed / runs;
    points += check.points;
  }
  return points == 0 ? 0.0 : earned / points;
}

/// The checks of `rubric` that are not visible.
inline std::vector<course::Check> hiddenChecks(const course::Rubric& rubric) {
  std::vector<course::Check> hidden;
  std::copy_if(rubric.checks.begin(), rubric.checks.end(), std::back_inserter(hidden),
               [](const course::Check& c) { return c.visibility != course::Visibility::Visible; });
  return hidden;
}

/// A strategy with a name, for messages.
struct Candidate {
  std::string name;
  Strategy strategy;
};

/// The candidate of a kind with the best share of the practice worlds (`worlds` of each hidden
/// check's family, from seed 1: never a secret), and that share.
inline std::pair<Candidate, double> bestOnPractice(const course::Rubric& rubric, const std::vector<Candidate>& kind, int worlds) {
  const course::Rubric practice = course::practiceRubric(rubric, worlds, 1);
  std::pair<Candidate, double> best{kind.front(), -1.0};
  for (const Candidate& c : kind) {
    const double s = share(practice, practice.checks, "", c.strategy);
    if (s > best.second) best = {c, s};
  }
  return best;
}

/// The most of any one hidden check's points `strategy` earns, on average under `secrets` fresh
/// secrets: a blind controller may pass no hidden check often, not merely all of them rarely.
inline double hiddenShare(const course::Rubric& rubric, const Strategy& strategy, int secrets) {
  double most = 0;
  for (const course::Check& check : hiddenChecks(rubric)) {
    double total = 0;
    for (int k = 0; k < secrets; ++k) total += share(rubric, {check}, "adversary secret " + std::to_string(k), strategy);
    most = std::max(most, total / secrets);
  }
  return most;
}

// ---- The building blocks of blind programs ----

/// The angle `a` wrapped into (-pi, pi].
inline double wrap(double a) { return std::remainder(a, 2 * pi); }

/// How a program goes through its points, and what it does on a bump and with time.
struct RouteDef {
  std::vector<Point2> points;         ///< in the world's frame (odometry's)
  double speed = 0.6;                 ///< m/s
  double within = 0.08;               ///< a point is reached this near, m
  double startAt = 0.0;               ///< waits until this time, s
  double stopAt = INFINITY;           ///< stands still from this time, s
  std::optional<std::string> report;  ///< reported at `reportAt` (or when the route ends)
  double reportAt = INFINITY;         ///< s
  bool loop = false;                  ///< round the points again and again
  double slideTurn = 0.0;             ///< on a bump: back off, turn this much (rad, + left), drive on `slideAhead` m, then on
  double slideAhead = 0.0;            ///< m
};

/// Drives through the points by odometry: turn towards the next, drive at it; optionally slide off what it bumps.
class Route final : public Program {
 public:
  explicit Route(RouteDef def) : def_(std::move(def)) {}
  Wheels step(double t, const SensorFrame& f) override {
    if (t >= def_.reportAt - 1e-9 && def_.report) report = def_.report;
    if (t < def_.startAt - 1e-9 || t >= def_.stopAt - 1e-9) return {};
    if (!f.bumps.empty() && def_.slideTurn != 0.0 && phase_ == 0) phase_ = 1, phaseStart_ = t, heading_ = f.odometry.heading + def_.slideTurn;
    if (phase_ == 1) {  // back off for half a second
      if (t - phaseStart_ < 0.5) return {-0.2, 0.0};
      phase_ = 2;
    }
    if (phase_ == 2) {  // turn to the new heading
      const double e = wrap(heading_ - f.odometry.heading);
      if (std::abs(e) > 0.05) return {0.0, std::clamp(2.0 * e, -1.0, 1.0)};
      phase_ = 3, from_ = f.odometry.position;
    }
    if (phase_ == 3) {  // and on along it
      if ((f.odometry.position - from_).norm() < def_.slideAhead) return {def_.speed, 0.0};
      phase_ = 0;
    }
    if (next_ >= def_.points.size()) {
      if (!def_.loop) {
        if (def_.report && def_.reportAt == INFINITY) report = def_.report;
        return {};
      }
      next_ = 0;
    }
    const Vec2 to = def_.points[next_] - f.odometry.position;
    if (to.norm() < def_.within) {
      ++next_;
      return step(t, f);
    }
    const double e = wrap(std::atan2(to.y(), to.x()) - f.odometry.heading);
    const double forward = std::abs(e) > 0.4 ? 0.0 : std::min(def_.speed, 1.5 * to.norm()) * std::cos(e);
    return {forward, std::clamp(2.0 * e, -1.0, 1.0)};
  }

 private:
  RouteDef def_;
  std::size_t next_ = 0;
  int phase_ = 0;  // 0 on the route; 1 backing off, 2 turning, 3 sliding on
  double phaseStart_ = 0.0, heading_ = 0.0;
  Point2 from_{0, 0};
};

/// A strategy whose program for every robot follows the route `make` gives from the robot's start (its odometry at t = 0).
inline Strategy fromStart(std::function<RouteDef(const Pose2& start, std::size_t i)> make) {
  class Deferred final : public Program {
   public:
    Deferred(std::function<RouteDef(const Pose2&, std::size_t)> make, std::size_t i) : make_(std::move(make)), i_(i) {}
    Wheels step(double t, const SensorFrame& f) override {
      if (!route_) route_.emplace(make_(f.odometry, i_));
      const Wheels w = route_->step(t, f);
      report = route_->report;
      return w;
    }

   private:
    std::function<RouteDef(const Pose2&, std::size_t)> make_;
    std::size_t i_;
    std::optional<Route> route_;
  };
  return [make](std::size_t i) { return std::make_unique<Deferred>(make, i); };
}

}  // namespace frob::testing::blind
