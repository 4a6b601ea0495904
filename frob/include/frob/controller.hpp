#pragma once
/// A controller file's one line: `FROB_CONTROLLER(runAround)` names the function that drives the
/// robot (the paper's `runController` argument) and is what `frob run my_controller.cpp` loads.
///
///   Task<Wheels> runAround() { for (;;) { co_await goAhead(); co_await turnRight(); } }
///   FROB_CONTROLLER(runAround)                                        // defaults: empty room, 60 s
///   FROB_CONTROLLER(bug, .world = "obstacles", .seconds = 120)        // or with options

#include "frob/behavior.hpp"
#include "frob/detail/controller.hpp"
#include "frob/robot.hpp"
#include "frob/run_task.hpp"
#include "frob/task.hpp"

#include <functional>
#include <optional>
#include <string>
#include <type_traits>

namespace frob {

/// A controller: from a robot's sensors to its wheels.
using Controller = std::function<Behavior<Wheels>(const Robot&)>;

/// Where and how long `frob run` runs a controller when the command line does not say.
struct ControllerOptions {
  std::string world = "empty";  ///< reference world name or world file
  double seconds = 60.0;        ///< simulated seconds (a controller whose task returns ends the run sooner)
  std::string summary;          ///< one line saying what the controller does, for `frob list`
};

/// What FROB_CONTROLLER declares.
struct ControllerEntry {
  std::string name;           ///< the function's name
  Controller make;            ///< builds the controller for one robot
  ControllerOptions options;  ///< defaults for `frob run`
};

/// `f` as a Controller: f(const Robot&) or f() giving a Behavior<Wheels> or a Task<Wheels, B>.
template <class F>
[[nodiscard]] Controller makeController(F f) {
  if constexpr (std::is_invocable_v<F, const Robot&>) {
    return [f](const Robot& r) { return detail::controllerWheels(r, f(r)); };
  } else {
    static_assert(std::is_invocable_v<F>, "FROB_CONTROLLER: the function must take a const Robot& or nothing");
    return [f](const Robot& r) { return detail::controllerWheels(r, f()); };
  }
}

/// One robot's controller as a host samples it, instant by instant. A controller that throws
/// (building it or sampling it) or commands non-finite wheels fails: it keeps the reason, and its
/// robot is stopped from then on. The simulator's run and the sandboxed controller host share it.
class RunningController {
 public:
  /// Builds `make`'s controller for `robot`; a throw makes it failed at once.
  RunningController(const Controller& make, const Robot& robot);
  /// The wheels at `now`: the controller's command, or a stop once it has failed. With `picture`,
  /// also the overlay of the pictures its tasks publish now (empty once failed).
  Wheels step(const Instant& now, Picture* picture = nullptr);
  /// True once it has failed.
  [[nodiscard]] bool failed() const { return !behavior_; }
  /// True once it is done: its behavior is runTask(robot, task) (a controller function that gives
  /// a Task) and the task has returned, so it commands a stop from then on, whatever the frames.
  [[nodiscard]] bool finished() const { return behavior_ && behavior_->node()->stoppedForGood(); }
  /// Why it failed, e.g. "the controller commanded non-finite wheels ... at t = 1.000 s"; "" while it runs.
  [[nodiscard]] const std::string& failure() const { return failure_; }
  /// The robot it drives (its debug channel holds the task timeline).
  [[nodiscard]] const Robot& robot() const { return robot_; }

 private:
  Robot robot_;
  std::optional<Behavior<Wheels>> behavior_;  // empty once failed
  std::string failure_;
};

}  // namespace frob

/// The symbol `frob run` looks up in a compiled controller file (a build may rename it).
#ifndef FROB_CONTROLLER_SYMBOL
#define FROB_CONTROLLER_SYMBOL frob_controller_v1
#endif

/// Names this file's controller function, optionally with ControllerOptions fields.
#define FROB_CONTROLLER(function, ...)                                                                                               \
  extern "C" const ::frob::ControllerEntry* FROB_CONTROLLER_SYMBOL() {                                                               \
    static const ::frob::ControllerEntry entry{#function, ::frob::makeController(function), ::frob::ControllerOptions{__VA_ARGS__}}; \
    return &entry;                                                                                                                   \
  }
