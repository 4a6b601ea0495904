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

namespace detail {
template <class A, class B>
class TaskPromise;
template <class A, class E>
class AtomicAwaiter;
struct GetState {};

// Raises a RoboErr where it is awaited, or stands for a task that fails at once.
struct Raise {
  RoboErr error;
  bool await_ready() noexcept { return true; }
  template <class P>
  void await_suspend(std::coroutine_handle<P>) noexcept {}
  [[noreturn]] void await_resume() { throw error; }
  template <class A, class B>
  operator Task<A, B>() const {  // NOLINT(google-explicit-constructor)
    return [](RoboErr e) -> Task<A, B> {
      (void)co_await GetState{};  // a coroutine needs an await; throwing from one is plain C++
      throw e;
    }(error);
  }
};

template <class A, class B>
struct SubtaskAwaiter;
template <class A, class B>
struct Become {
  Task<A, B> task;
};
struct GetContext {};
struct GetRecord {};
struct SetState {
  TaskState state;
};
template <class A, class B>
Task<A> discardResult(Task<A, B> t);
}  // namespace detail

/// A task driving a behavior of type A until it ends with a B (`Task<Wheels>` is the paper's
/// `Task WheelControlB ()`). A task is a recipe: it runs when awaited or passed to runTask, once.
template <class A, class B>
class [[nodiscard("a Task does nothing unless you co_await it")]] Task {
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
  explicit Task(std::coroutine_handle<promise_type> h) : handle_(h) {}
  void reset() {
    if (handle_) handle_.destroy();
    handle_ = {};
  }
  std::coroutine_handle<promise_type> handle_;
};

namespace detail {

template <class R, class P>
struct ReturnValue {
  void return_value(R v) { static_cast<P*>(this)->deliver(std::move(v)); }
};
template <class P>
struct ReturnVoid {
  void return_void() { static_cast<P*>(this)->deliver(Unit{}); }
};

template <class A, class B>
class TaskPromise : public PromiseBase<A>,
                    public std::conditional_t<std::is_void_v<B>, ReturnVoid<TaskPromise<A, B>>, ReturnValue<ResultOf<B>, TaskPromise<A, B>>> {
 public:
  using R = ResultOf<B>;
  explicit TaskPromise(std::source_location loc = std::source_location::current()) : PromiseBase<A>(loc) {}

  Task<A, B> get_return_object() { return Task<A, B>(std::coroutine_handle<TaskPromise>::from_promise(*this)); }
  std::suspend_always initial_suspend() noexcept { return {}; }
  FinalAwaiter final_suspend() noexcept { return {}; }
  void unhandled_exception() {
    slot->error = std::current_exception();
    this->noteException();
  }
  void deliver(R v) {
    this->end(TaskEnd::Returned, printable(v));
    slot->value.emplace(std::move(v));
  }

  // What a task may co_await: tasks driving the same A, its state, become, and taskError.
  template <class B2>
  SubtaskAwaiter<A, B2> await_transform(Task<A, B2>&& t) {
    return SubtaskAwaiter<A, B2>(std::move(t));
  }
  template <class B2>
  SubtaskAwaiter<A, B2> await_transform(Task<A, B2>& t) {
    return SubtaskAwaiter<A, B2>(std::move(t));
  }
  auto await_transform(GetState) {
    struct Awaiter : std::suspend_never {
      TaskState state;
      TaskState await_resume() { return state; }
    };
    return Awaiter{{}, this->ctx->state};
  }
  auto await_transform(GetContext) {  // the library's own access to the run (transformers)
    struct Awaiter : std::suspend_never {
      RunContext<A>* ctx;
      RunContext<A>* await_resume() { return ctx; }
    };
    return Awaiter{{}, this->ctx};
  }
  auto await_transform(GetRecord) {  // the timeline record subtasks hang under
    struct Awaiter : std::suspend_never {
      std::int64_t record;
      std::int64_t await_resume() { return record; }
    };
    return Awaiter{{}, this->recordForChildren()};
  }
  auto await_transform(SetState s) {
    this->ctx->state = std::move(s.state);
    return std::suspend_never{};
  }
  auto await_transform(Become<A, B>&& b);
  template <class E>
  auto await_transform(AtomicAwaiter<A, E>& atom) {  // an atomic task, which stays where it was made
    struct Ref {
      AtomicAwaiter<A, E>* atom;
      bool await_ready() noexcept { return false; }
      std::coroutine_handle<> await_suspend(std::coroutine_handle<TaskPromise> h) { return atom->await_suspend(h); }
      E await_resume() { return atom->await_resume(); }
    };
    return Ref{&atom};
  }
  template <class X>
  void await_transform(X&&) {
    static_assert(sizeof(X) == 0,
                  "a Task<A, B> can co_await only tasks that drive the same output type A, getTaskState(), "
                  "setTaskState(ts), become(task) and taskError(error)");
  }
  auto await_transform(Raise r) { return r; }

  ResultSlot<R>* slot = nullptr;
};

// Awaiting a subtask: runs it to completion, then yields its result or rethrows its error.
template <class A, class B>
struct SubtaskAwaiter {
  explicit SubtaskAwaiter(Task<A, B> t) : task(std::move(t)) {}
  SubtaskAwaiter(SubtaskAwaiter&&) noexcept = default;
  ~SubtaskAwaiter() {
    if (slot.frame) slot.frame.destroy();  // aborted while waiting: the subtask goes too
  }
  bool await_ready() noexcept { return false; }
  template <class P>
  std::coroutine_handle<> await_suspend(std::coroutine_handle<P> parent) {
    PromiseBase<A>& p = parent.promise();
    return task.startIn(slot, p.ctx, parent, p.recordForChildren(), &p);
  }
  B await_resume() {
    std::exchange(slot.frame, {}).destroy();
    if (slot.error) std::rethrow_exception(slot.error);
    if constexpr (!std::is_void_v<B>) return std::move(*slot.value);
  }

  Task<A, B> task;
  ResultSlot<ResultOf<B>> slot;
};

template <class A, class B>
auto TaskPromise<A, B>::await_transform(Become<A, B>&& b) {
  // A tail call: the new task takes this frame's place (its slot, parent and owner) and this
  // frame is destroyed, so recursion such as runAround calling itself runs in bounded memory.
  struct Awaiter {
    Task<A, B> next;
    bool await_ready() noexcept { return false; }
    std::coroutine_handle<> await_suspend(std::coroutine_handle<TaskPromise> self) {
      TaskPromise& p = self.promise();
      p.end(TaskEnd::Replaced, "became " + next.name());
      ResultSlot<R>& mine = *p.slot;
      std::coroutine_handle<> h = next.startIn(mine, p.ctx, p.continuation, p.parentRecord, p.caller);
      self.destroy();  // destroys this awaiter too: nothing of it is touched after this line
      return h;
    }
    void await_resume() noexcept {}
  };
  return Awaiter{std::move(b.task)};
}

template <class A, class B>
Task<A> discardResult(Task<A, B> t) {
  co_await std::move(t);
}

// An atomic task: a behavior until its exit event (result), its error event, or an enclosing
// scope's interrupt occurs. Lives in the awaiting frame while the runner watches it.
template <class A, class E>
class AtomicAwaiter final : public AtomicBase<A> {
 public:
  AtomicAwaiter(Behavior<A> b, Event<E> exit, std::optional<Event<RoboErr>> error)
      : behavior_(std::move(b)),
        exit_(std::move(exit)),
        error_(std::move(error)),
        exitNever_(dynamic_cast<NeverNode<E>*>(exit_.node().get()) != nullptr) {}

  bool await_ready() noexcept { return false; }
  template <class P>
  std::coroutine_handle<> await_suspend(std::coroutine_handle<P> h) {
    ctx_ = h.promise().ctx;
    this->name = &h.promise().name;
    this->output = ctx_->filtered(behavior_);
    this->waiter = h;
    ctx_->current = this;
    return std::noop_coroutine();  // back to the runner, which checks the events this instant
  }
  E await_resume() {
    if (failure_) std::rethrow_exception(failure_);
    return std::move(*result_);
  }

  const A* step(const Instant& now) override {
    if (!error_ && ctx_->interrupts.empty()) {  // the common case, kept short: it runs every step
      if (!exitNever_) {
        if (const std::optional<E>& exit = exit_.at(now)) {
          result_ = *exit;
          return nullptr;
        }
      }
      return &this->output.at(now);
    }
    return check(now) ? nullptr : &this->output.at(now);
  }
  void fail(std::exception_ptr e) override { failure_ = std::move(e); }

 private:
  bool check(const Instant& now) {
    const std::optional<E>& exit = exit_.at(now);
    // Every event is sampled each instant so stateful ones stay current; the exit wins ties, then
    // the task's own error, then the innermost scope.
    const std::optional<RoboErr>* error = error_ ? &error_->at(now) : nullptr;
    const std::optional<std::exception_ptr>* interrupt = nullptr;
    for (auto it = ctx_->interrupts.rbegin(); it != ctx_->interrupts.rend(); ++it) {
      const std::optional<std::exception_ptr>& o = it->at(now);
      if (o && interrupt == nullptr) interrupt = &o;
    }
    if (exit) {
      result_ = *exit;
    } else if (error && *error) {
      failure_ = std::make_exception_ptr(**error);
    } else if (interrupt) {
      failure_ = **interrupt;
    } else {
      return false;
    }
    return true;
  }

  Behavior<A> behavior_;
  Event<E> exit_;
  std::optional<Event<RoboErr>> error_;
  bool exitNever_;  // never() as the exit: nothing to sample
  RunContext<A>* ctx_ = nullptr;
  std::optional<E> result_;
  std::exception_ptr failure_;
};

template <class T>
struct EventValue;
template <class T>
struct EventValue<Event<T>> {
  using type = T;
};

// The coroutine behind mkTask and mkTaskE; an exit event of Unit makes a Task<A> (no result).
template <class A, class B, class E, class F>
Task<A, B> atomicTask(F f) {
  TaskState ts = co_await GetState{};
  auto parts = std::invoke(f, static_cast<const TaskState&>(ts));
  std::optional<Event<RoboErr>> error;
  if constexpr (std::tuple_size_v<decltype(parts)> == 3) error = std::get<2>(parts);
  AtomicAwaiter<A, E> atom(toBehavior(std::get<0>(parts)), std::get<1>(parts), std::move(error));
  if constexpr (std::is_void_v<B>) {
    co_await atom;
  } else {
    co_return co_await atom;
  }
}

template <class F>
using MkTaskParts = std::invoke_result_t<F&, const TaskState&>;
template <class F>
using MkTaskOutput = frob::ValueOf<std::tuple_element_t<0, MkTaskParts<F>>>;
template <class F>
using MkTaskExit = typename EventValue<std::remove_cvref_t<std::tuple_element_t<1, MkTaskParts<F>>>>::type;
template <class F>
using MkTaskResult = std::conditional_t<std::is_same_v<MkTaskExit<F>, Unit>, void, MkTaskExit<F>>;

template <class T>
inline constexpr bool kNever = false;

// Whether mkTask's function returns {behavior, event[, error event]}; if not, a compile error that
// says what is wrong in the student's words, instead of one from deep inside the library.
template <class Parts>
consteval bool checkTaskParts() {
  if constexpr (!requires { std::tuple_size<Parts>::value; }) {
    static_assert(kNever<Parts>,
                  "mkTask: the function must return std::pair{behavior, event} "
                  "(or std::tuple{behavior, event, error event} for mkTaskE)");
    return false;
  } else {
    using Drives = std::remove_cvref_t<std::tuple_element_t<0, Parts>>;
    using Ends = std::remove_cvref_t<std::tuple_element_t<1, Parts>>;
    if constexpr (!BehaviorType<Drives>) {
      static_assert(kNever<Parts>,
                    "mkTask: the pair's first element must be a behavior, what the task drives "
                    "(e.g. wheels(0.1, 0))");
      return false;
    } else if constexpr (BehaviorType<Ends> && std::is_same_v<frob::ValueOf<Ends>, bool>) {
      static_assert(kNever<Parts>,
                    "mkTask: the pair's second element is a Behavior<bool>, a condition, but a task "
                    "ends on an event: did you forget predicate(...)?");
      return false;
    } else if constexpr (!EventType<Ends>) {
      static_assert(kNever<Parts>,
                    "mkTask: the pair's second element must be the event that ends the task "
                    "(e.g. predicate(frontSonar(r) < 0.5) or after(2.0))");
      return false;
    } else {
      return true;
    }
  }
}

}  // namespace detail

/// The paper's mkTask: `f(ts)` gives a behavior and the event that ends it, as a std::pair.
/// The task drives the behavior until the event occurs and returns the event's value (nothing
/// for an Event<Unit>). Its timeline name is the function that calls mkTask.
template <class F>
  requires std::invocable<F&, const TaskState&>
[[nodiscard]] auto mkTask(F f, std::source_location loc = std::source_location::current()) {
  if constexpr (detail::checkTaskParts<detail::MkTaskParts<F>>()) {
    using A = detail::MkTaskOutput<F>;
    using E = detail::MkTaskExit<F>;
    return detail::atomicTask<A, detail::MkTaskResult<F>, E>(std::move(f)).at(loc);
  }
}

/// The paper's mkTaskE: as mkTask, with a third element, an Event<RoboErr> that fails the task.
template <class F>
  requires std::invocable<F&, const TaskState&>
[[nodiscard]] auto mkTaskE(F f, std::source_location loc = std::source_location::current()) {
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
