#pragma once
/// Tasks (the paper's section 3): a behavior of type A that runs until an event ends it with a
/// value of type B. Tasks are C++20 coroutines: `co_await` sequences them, `co_return` ends one.

#include "frob/detail/task_machinery.hpp"

// GCC 12 constructs a lambda with captures written inside a co_await expression in one place and
// destroys it from another (a double free), which corrupts ordinary controllers such as
// `co_await mkTask([goal](const TaskState& ts) { ... })`. Clang 15 or later compiles them correctly.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 13
#error "Frob tasks need clang++-16 (Debian: apt-get install clang-16); GCC 12 miscompiles lambdas inside co_await"
#endif

namespace frob {

/// The number of task coroutine frames alive in the process (to prove cancellation frees them).
[[nodiscard]] long liveTaskFrames();

/// A task driving a behavior of type A until it ends with a B (`Task<Wheels>` is the paper's
/// `Task WheelControlB ()`). A task is a recipe: it runs when awaited or passed to runTask, once.
template <class A, class B>
class [[nodiscard("a Task does nothing unless you co_await it")]] Task {
  static_assert(!EventType<A>,
                "Task<Event<T>>: a task drives a behavior, a value at every instant, not an event; to give an "
                "occurrence, end the task with it (mkTask with that event makes a Task<Wheels, T> that returns its "
                "value), or drive a Behavior<std::optional<T>>");

 public:
  using promise_type = detail::TaskPromise<A, B>;
  using output_type = A;
  using result_type = B;

  Task(Task&& other) noexcept : handle_(std::exchange(other.handle_, {})) {}
  Task& operator=(Task&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, {});
    }
    return *this;
  }
  Task(const Task&) = delete;
  Task& operator=(const Task&) = delete;
  ~Task() { reset(); }

  /// A task whose result is dropped: any Task<A, B2> can stand where a Task<A> is expected.
  template <class B2>
    requires(std::is_void_v<B> && !std::is_void_v<B2>)
  Task(Task<A, B2>&& other) : Task(detail::discardResult(std::move(other)).quiet()) {}  // NOLINT(google-explicit-constructor)

  /// This task, shown under `name` in the timeline.
  Task&& named(std::string name) && {
    handle_.promise().name = std::move(name);
    return std::move(*this);
  }
  /// This task, named in the timeline after the function and line of `loc`.
  Task&& at(const std::source_location& loc) && {
    handle_.promise().name = detail::taskName(loc.function_name());
    handle_.promise().where = detail::taskWhere(loc);
    return std::move(*this);
  }
  /// The name the timeline shows.
  [[nodiscard]] const std::string& name() const { return handle_.promise().name; }
  /// Internal frames (adapters) stay off the timeline.
  Task&& quiet() && {
    handle_.promise().quiet = true;
    return std::move(*this);
  }

  /// Starts this task inside run `ctx`, awaited by `caller` (null at the run's top), reporting
  /// into `slot`; returns the frame to resume.
  std::coroutine_handle<> startIn(detail::ResultSlot<ResultOf<B>>& slot, detail::RunContext<A>* ctx, std::coroutine_handle<> continuation,
                                  std::int64_t parentRecord, const detail::PromiseBase<A>* caller) {
    FROB_ASSERT(handle_, "a Task can run only once (it was already awaited or moved from)");
    auto h = std::exchange(handle_, {});
    slot.frame = h;
    h.promise().slot = &slot;
    h.promise().begin(ctx, continuation, parentRecord, caller);
    return h;
  }

 private:
  friend promise_type;
  friend detail::Catcher<A, B>;
  explicit Task(std::coroutine_handle<promise_type> h) : handle_(h) {}
  void reset() {
    if (handle_) handle_.destroy();
    handle_ = {};
  }
  std::coroutine_handle<promise_type> handle_;
};

/// The paper's mkTask: `f(ts)` gives a behavior and the event that ends it, as a std::pair.
/// The task drives the behavior until the event occurs and returns the event's value (nothing
/// for an Event<Unit>). Its timeline name is the function that calls mkTask.
template <class F>
  requires std::invocable<F&, const TaskState&>
[[nodiscard]] auto mkTask(F f, std::source_location loc = detail::callSite()) {
  if constexpr (detail::checkTaskParts<detail::MkTaskParts<F>>()) {
    using A = detail::MkTaskOutput<F>;
    using E = detail::MkTaskExit<F>;
    using Make = detail::Erased<detail::AtomicParts<A, E>, const TaskState&>;
    detail::Closure closure(new F(std::move(f)), &detail::deleteClosure<F>);
    return detail::atomicTask<A, detail::MkTaskResult<F>, E>(Make(&detail::makeAtomicParts<A, E, F>, std::move(closure))).at(loc);
  }
}

/// The paper's mkTaskE: as mkTask, with a third element, an Event<RoboErr> that fails the task.
template <class F>
  requires std::invocable<F&, const TaskState&>
[[nodiscard]] auto mkTaskE(F f, std::source_location loc = detail::callSite()) {
  static_assert(std::tuple_size_v<detail::MkTaskParts<F>> == 3, "mkTaskE's function returns std::tuple{behavior, exit event, error event}");
  return mkTask(std::move(f), loc);
}

/// The paper's taskError: `co_await taskError(RoboErr("..."))` inside a task, or return it as a
/// task that fails at once.
[[nodiscard]] inline detail::Raise taskError(RoboErr e) { return {std::move(e)}; }

/// The task's state: its robot and where the robot was when the task began (`co_await getTaskState()`).
[[nodiscard]] inline detail::GetState getTaskState() { return {}; }
/// Replaces the task's state for the tasks that follow (`co_await setTaskState(ts)`).
[[nodiscard]] inline detail::SetState setTaskState(TaskState ts) { return {std::move(ts)}; }
/// Ends this task by becoming `t`: `co_await become(runAround());` is the paper's recursive
/// call, in constant memory. Nothing after it runs.
template <class A, class B>
[[nodiscard]] detail::Become<A, B> become(Task<A, B> t) {
  return {std::move(t)};
}

}  // namespace frob
