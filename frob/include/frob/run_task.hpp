#pragma once
/// Running a task: runTask turns a Task into the Behavior a controller returns.

#include "frob/detail/runner.hpp"
#include "frob/task.hpp"

namespace frob {

/// The paper's runTask: the behavior of task `t` run from state `ts`, then `final` once it ends.
/// An error no task catches, an exception, a non-finite output or an endless chain of tasks at
/// one instant makes sampling it throw FrobError naming the task and the simulated time.
template <class A, class B>
[[nodiscard]] Behavior<A> runTask(TaskState ts, Task<A, B> t, std::type_identity_t<Behavior<A>> final) {
  return Behavior<A>(detail::makeNode<detail::RunnerNode<A, B>>(std::move(ts), std::move(t), std::move(final)));
}

/// runTask for robot `r` from where it stands; after the task returns the output is zero for good
/// (a stop: a controller that gives it is then done).
template <class A, class B>
[[nodiscard]] Behavior<A> runTask(const Robot& r, Task<A, B> t) {
  return Behavior<A>(detail::makeNode<detail::RunnerNode<A, B>>(TaskState(r), std::move(t), Behavior<A>(zeroOf<A>()), -1, false, true));
}

}  // namespace frob
