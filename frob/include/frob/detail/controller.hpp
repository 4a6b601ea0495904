#pragma once
// The machinery behind controller.hpp: what a controller function's result becomes.

#include "frob/behavior.hpp"
#include "frob/robot.hpp"
#include "frob/run_task.hpp"
#include "frob/task.hpp"

#include <type_traits>
#include <utility>

namespace frob {
namespace detail {

template <class T>
struct IsTask : std::false_type {};
template <class A, class B>
struct IsTask<Task<A, B>> : std::true_type {};

// A controller's result as wheels: a task is run from where the robot stands, a behavior taken as it is.
template <class R>
Behavior<Wheels> controllerWheels(const Robot& r, R&& result) {
  if constexpr (IsTask<std::remove_cvref_t<R>>::value) {
    return runTask(r, std::forward<R>(result));
  } else {
    static_assert(BehaviorType<R> && std::is_same_v<frob::ValueOf<R>, Wheels>,
                  "FROB_CONTROLLER: the function must give a Behavior<Wheels> or a Task<Wheels, ...>");
    return toBehavior(result);
  }
}

}  // namespace detail
}  // namespace frob
