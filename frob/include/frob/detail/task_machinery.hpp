#pragma once
// The machinery behind task.hpp: promises, awaiters and the per-run context (the runner node is in
// runner.hpp).
// Every frame of one runTask shares a RunContext; an atomic task parks itself in the context and
// suspends back to the runner, which checks its events each instant and resumes it when one occurs.

#include "frob/debug.hpp"
#include "frob/detail/call_site.hpp"
#include "frob/detail/printable.hpp"
#include "frob/errors.hpp"
#include "frob/event.hpp"
#include "frob/task_state.hpp"

#include <atomic>
#include <concepts>
#include <coroutine>
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <source_location>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace frob {

template <class A, class B = void>
class Task;

/// A task's result type with `void` as Unit.
template <class B>
using ResultOf = std::conditional_t<std::is_void_v<B>, Unit, B>;

namespace detail {

extern std::atomic<long> liveFrames;

// False for every T: a static_assert that fires only when the template holding it is instantiated.
template <class T>
inline constexpr bool kNever = false;

// "frob::Task<frob::Wheels> goAhead()" -> "goAhead"; file and line as "file.cpp:12".
[[nodiscard]] std::string taskName(const char* functionName);
[[nodiscard]] std::string taskWhere(const std::source_location& loc);
// A readable message for an exception in flight; `why` gives its kind for the timeline.
[[nodiscard]] std::string describe(const std::exception_ptr& e, TaskEnd* why = nullptr);
// How deep tasks may await one another in one run; only a recursion that never unwinds gets there.
inline constexpr int kMaxTaskDepth = 1000;
// Why a run stopped with tasks nested deeper than `limit`: `chain`, innermost first, names the
// tasks and where each was made, and the one most often in it is the recursion, shown with its fix
// (become; for a taskCatch, a handler that stays the same).
[[nodiscard]] std::string tooDeepMessage(const std::vector<std::pair<std::string, std::string>>& chain, int limit);
// The robot error `e` holds, if it is one (only a RoboErr is; a std::logic_error is a bug).
[[nodiscard]] std::optional<RoboErr> roboErrIn(const std::exception_ptr& e);

// Thrown into the running atomic task to unwind to the scope with id `scope` (withExit, timeLimit).
// Not a std::exception, so students' catch (const std::exception&) does not swallow aborts.
struct ScopeSignal {
  std::int64_t scope = 0;
  std::string reason;
};
template <class X>
struct ScopeExit : ScopeSignal {
  X value;
};

// The latest output of a runner, readable one instant late (withMyResult, withTask).
template <class A>
struct OutputCell {
  std::uint64_t id = 0;
  A current = zeroOf<A>();
  A previous = zeroOf<A>();
  void write(const Instant& now, const A& v) {
    if (id != now.id) {
      previous = current;
      id = now.id;
    }
    current = v;
  }
  const A& delayed(const Instant& now) const { return id == now.id ? previous : current; }
};

template <class A>
class DelayedNode final : public BehaviorNode<A> {
 public:
  explicit DelayedNode(std::shared_ptr<OutputCell<A>> cell) : cell_(std::move(cell)) {}

 protected:
  A compute(const Instant& now) override { return cell_->delayed(now); }

 private:
  std::shared_ptr<OutputCell<A>> cell_;
};

// An atomic task waiting in its runner for one of its events.
template <class A>
struct AtomicBase {
  Behavior<A> output;              // its behavior, with the enclosing filters applied
  std::coroutine_handle<> waiter;  // resumed when it ends
  const std::string* name = nullptr;
  double endLag = 0.0;  // how long before the sample the occurrence that ended it happened (its Origin's lag)
  // Its output at `now`, or null when it ended at `now` (its result or error is then stored).
  virtual const A* step(const Instant& now) = 0;
  virtual void fail(std::exception_ptr e) = 0;  // ends it with an error
  AtomicBase() = default;
  AtomicBase(const AtomicBase&) = delete;
  AtomicBase& operator=(const AtomicBase&) = delete;
  virtual ~AtomicBase() = default;
};

// One occurrence is delivered once: an occurrence that ended or failed a task of a run (its exit,
// its error or a scope's) is not seen again by a task started in the same instant, whichever event
// carries it (its Origin's source: an error event rebuilt by the next task from the same sensor
// carries the same occurrence). Compiled once in libfrob, so that no controller instantiates it.
class UsedOccurrences {
 public:
  // Whether the occurrence from `source` at `at` has not ended or failed a task yet.
  [[nodiscard]] bool fresh(const NodeBase* source, const Instant& at) const;
  // Marks it used; holds `carrier`, the event it came by, which holds its source, so that no new
  // node takes the source's address within the instant.
  void use(const NodeBase* source, std::shared_ptr<NodeBase> carrier, const Instant& at);

 private:
  std::uint64_t instant_ = 0;
  std::vector<std::pair<const NodeBase*, std::shared_ptr<NodeBase>>> used_;
};

// What every frame of one runTask shares.
template <class A>
struct RunContext {
  explicit RunContext(TaskState s) : state(std::move(s)), debug(state.robot().debugChannel()) {}
  TaskState state;
  std::shared_ptr<DebugChannel> debug;
  const Instant* now = nullptr;
  double time = 0.0;                                             // of the latest instant
  AtomicBase<A>* current = nullptr;                              // the atomic task running
  std::vector<Event<std::exception_ptr>> interrupts;             // scoped errors and exits, innermost last
  std::vector<std::function<Behavior<A>(Behavior<A>)>> filters;  // withFilter, outermost first
  std::vector<std::function<void(const Instant&)>> watchers;     // sampled every instant (withB, withTask)
  std::shared_ptr<OutputCell<A>> output;                         // made when a task first reads its own output
  std::exception_ptr origin;                                     // an unexpected exception, and the task it first left
  std::string originTask;
  std::int64_t nextScope = 0;
  UsedOccurrences used;                           // one occurrence is delivered once
  std::vector<std::coroutine_handle<>> replaced;  // frames that became another task: the runner destroys them

  // Destroys the frames that became another task, once the resume they did so in has returned:
  // a compiler may still touch a frame after its await_suspend hands over to the next one.
  void destroyReplaced() {
    for (std::coroutine_handle<> h : std::exchange(replaced, {})) h.destroy();
  }

  // The paper's snapRobot: record where the robot is as one task ends and the next begins, at the
  // instant of the event that ended it (`at`'s lag before the sample).
  void snapshot(const Instant& at) {
    now = &at;
    time = at.time - at.lag;
    state.setInitialPlace(state.robot().place().at(at)).setInitialOrientation(state.robot().orientation().at(at)).setStartTime(time);
  }
  // The run's output one instant late (withMyResult, withTask); the runner records it from now on.
  Behavior<A> delayedOutput() {
    if (!output) output = std::make_shared<OutputCell<A>>();
    return Behavior<A>(makeNode<DelayedNode<A>>(output));
  }
  // `b` with every enclosing filter applied, innermost first.
  Behavior<A> filtered(Behavior<A> b) const {
    for (auto it = filters.rbegin(); it != filters.rend(); ++it) b = (*it)(std::move(b));
    return b;
  }
};

template <class R>
struct ResultSlot {
  std::coroutine_handle<> frame;  // the frame that will fill the slot; whoever owns the slot destroys it
  std::optional<R> value;
  std::exception_ptr error;
};

template <class A>
struct PromiseBase {
  explicit PromiseBase(const std::source_location& loc) : name(taskName(loc.function_name())), where(taskWhere(loc)) {
    liveFrames.fetch_add(1, std::memory_order_relaxed);
  }
  PromiseBase(const PromiseBase&) = delete;
  PromiseBase& operator=(const PromiseBase&) = delete;
  ~PromiseBase() {
    if (ctx != nullptr && record >= 0) {
      ctx->debug->timeline().end(record, ctx->time, TaskEnd::Aborted, "stopped by its parent");
    }
    liveFrames.fetch_sub(1, std::memory_order_relaxed);
  }

  // Joins run `c` under the task with record `parent`, awaited by `awaiting` (null at a run's top);
  // `quiet` frames (internal adapters) stay off the timeline. A chain of awaiting tasks deeper than
  // kMaxTaskDepth is a recursion that never unwinds: it fails here, before memory runs out.
  void begin(RunContext<A>* c, std::coroutine_handle<> cont, std::int64_t parent, const PromiseBase* awaiting) {
    caller = awaiting;
    depth = caller == nullptr ? 0 : caller->depth + 1;
    if (depth > kMaxTaskDepth) [[unlikely]]
      throwTooDeep();
    ctx = c;
    continuation = cont;
    parentRecord = parent;
    record = quiet ? -1 : ctx->debug->timeline().start(parent, name, where, ctx->time);
  }
  // The record subtasks hang under.
  [[nodiscard]] std::int64_t recordForChildren() const { return quiet ? parentRecord : record; }
  void end(TaskEnd how, std::string detail) {
    if (record >= 0) ctx->debug->timeline().end(record, ctx->time, how, std::move(detail));
    record = -1;
  }
  void noteException() {
    std::exception_ptr e = std::current_exception();
    TaskEnd how = TaskEnd::Failed;
    std::string what = describe(e, &how);
    if (how == TaskEnd::Failed && ctx->origin != e) {
      ctx->origin = e;  // the innermost frame sees it first
      ctx->originTask = name;
    }
    end(how, std::move(what));
  }

  [[gnu::noinline, noreturn]] void throwTooDeep() const {
    std::vector<std::pair<std::string, std::string>> chain;
    for (const PromiseBase* p = this; p != nullptr; p = p->caller) {
      if (!p->quiet) chain.emplace_back(p->name, p->where);
    }
    throw FrobError(tooDeepMessage(chain, kMaxTaskDepth));
  }

  RunContext<A>* ctx = nullptr;
  const PromiseBase* caller = nullptr;  // the task awaiting this one, in the same run
  int depth = 0;                        // tasks awaiting above this one in its run
  std::coroutine_handle<> continuation;
  std::string name;
  std::string where;
  std::int64_t record = -1;
  std::int64_t parentRecord = -1;
  bool quiet = false;
  void* catcher = nullptr;  // the Catcher<A, B> (of its B) of a taskCatch's frame
};

// Resumes whoever awaited the task (the parent, or the runner through a no-op handle).
struct FinalAwaiter {
  bool await_ready() noexcept { return false; }
  template <class P>
  std::coroutine_handle<> await_suspend(std::coroutine_handle<P> h) noexcept {
    return h.promise().continuation;
  }
  void await_resume() noexcept {}
};

// Awaitables a task may co_await, and the promise that accepts them.
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
// What co_await of something a task cannot await gives: its type is needed at the co_await, so its
// message is the first error there, not one about awaiting a void.
template <class X>
struct NotAwaitable {
  static_assert(kNever<X>,
                "a Task<A, B> can co_await only tasks that drive the same output type A, getTaskState(), "
                "setTaskState(ts), become(task) and taskError(error)");
  bool await_ready() noexcept { return true; }
  void await_suspend(std::coroutine_handle<>) noexcept {}
  void await_resume() noexcept {}
};
// The same for a task driving another output A2.
template <class A2>
struct OtherOutput {
  static_assert(kNever<A2>,
                "co_await: this task drives another output than the task that awaits it (a Task<double> inside a "
                "Task<Wheels>?): a task awaits only tasks of its own output; to compute a value, return it as the "
                "result (Task<Wheels, double>, co_return x), or run the other task beside it with withTask");
  bool await_ready() noexcept { return true; }
  void await_suspend(std::coroutine_handle<>) noexcept {}
  void await_resume() noexcept {}
};
template <class A, class B>
struct Become {
  Task<A, B> task;
};

// A taskCatch (see catching): its handler, the task it is to run in its scope, and how many nested
// taskCatches with this same handler it stands for. A taskCatch whose task becomes (or whose
// handler gives) a taskCatch with the same handler, as the paper's bug restarting itself does,
// folds that one into it instead of nesting it, with the same meaning: one layer handles an error,
// and its handler's task runs inside the layers left. So the restart runs in bounded depth.
template <class A, class B>
struct Catcher {
  Catcher(Erased<Task<A, B>, const RoboErr&> h, std::size_t size, Task<A, B> t) : handler(std::move(h)), handlerSize(size), body(std::move(t)) {}
  // `t`, or if it is a taskCatch with the same handler, its task (and so on), its layers added here.
  Task<A, B> absorb(Task<A, B> t) {
    for (auto* c = static_cast<Catcher*>(t.handle_.promise().catcher); c != nullptr && c->handler.sameAs(handler, handlerSize);
         c = static_cast<Catcher*>(t.handle_.promise().catcher)) {
      layers += c->layers;
      Task<A, B> inner = std::move(*c->body);
      t = std::move(inner);  // frees the folded taskCatch, which never ran
    }
    return t;
  }

  Erased<Task<A, B>, const RoboErr&> handler;
  std::size_t handlerSize;  // bytes of its closure
  std::optional<Task<A, B>> body;
  std::int64_t layers = 1;
};
struct GetContext {};
struct GetRecord {};
struct SetState {
  TaskState state;
};
template <class A, class B>
Task<A> discardResult(Task<A, B> t);

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
  explicit TaskPromise(std::source_location loc = detail::callSite()) : PromiseBase<A>(loc) {}
  // A taskCatch's frame, given its Catcher (catching's parameter), which it stays known by.
  explicit TaskPromise(std::unique_ptr<Catcher<A, B>>& c) : PromiseBase<A>(std::source_location::current()) { this->catcher = c.get(); }

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
  template <class A2, class B2>
  OtherOutput<A2> await_transform(Task<A2, B2>&&) {
    return {};
  }
  template <class A2, class B2>
  OtherOutput<A2> await_transform(Task<A2, B2>&) {
    return {};
  }
  template <class X>
  NotAwaitable<std::remove_cvref_t<X>> await_transform(X&&) {
    return {};
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
  // Becoming a taskCatch as a taskCatch's task, it folds into that one if it has the same handler.
  struct Awaiter {
    Task<A, B> next;
    bool await_ready() noexcept { return false; }
    std::coroutine_handle<> await_suspend(std::coroutine_handle<TaskPromise> self) {
      TaskPromise& p = self.promise();
      p.end(TaskEnd::Replaced, "became " + next.name());
      if (p.caller != nullptr && p.caller->catcher != nullptr) next = static_cast<Catcher<A, B>*>(p.caller->catcher)->absorb(std::move(next));
      ResultSlot<R>& mine = *p.slot;
      p.ctx->replaced.push_back(self);  // destroyed by the runner once this resume has returned
      return next.startIn(mine, p.ctx, p.continuation, p.parentRecord, p.caller);
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
        if (const std::optional<E>& exit = exit_.at(now); exit && ctx_->used.fresh(exit_.node()->origin().source, now)) {
          use(exit_, now);
          result_ = *exit;
          return nullptr;
        }
      }
      return &this->output.at(now);
    }
    return check(now) ? nullptr : &this->output.at(now);
  }
  void fail(std::exception_ptr e) override {
    failure_ = std::move(e);
    this->endLag = 0.0;  // at the sample that threw
  }

 private:
  // The occurrence of `e` at `now` unless it already ended or failed a task of this run.
  template <class T>
  const std::optional<T>* occurrence(const Event<T>& e, const Instant& now) const {
    const std::optional<T>& o = e.at(now);
    return o && ctx_->used.fresh(e.node()->origin().source, now) ? &o : nullptr;
  }
  // Uses up `e`'s occurrence at `now`, which ends this task then.
  template <class T>
  void use(const Event<T>& e, const Instant& now) {
    const Origin& o = e.node()->origin();
    ctx_->used.use(o.source, e.node().owner(), now);
    this->endLag = o.lag;
  }

  bool check(const Instant& now) {
    // Every event is sampled each instant so stateful ones stay current; the exit wins ties, then
    // the task's own error, then the innermost scope. Only the winner is used up: a scope's
    // occurrence that lost a tie still ends the next task started in this instant.
    const std::optional<E>* exit = occurrence(exit_, now);
    const std::optional<RoboErr>* error = error_ ? occurrence(*error_, now) : nullptr;
    const std::optional<std::exception_ptr>* interrupt = nullptr;
    const Event<std::exception_ptr>* scope = nullptr;
    for (auto it = ctx_->interrupts.rbegin(); it != ctx_->interrupts.rend(); ++it) {
      const std::optional<std::exception_ptr>* o = occurrence(*it, now);
      if (o && interrupt == nullptr) interrupt = o, scope = &*it;
    }
    if (exit) {
      use(exit_, now);
      result_ = **exit;
    } else if (error) {
      use(*error_, now);
      failure_ = std::make_exception_ptr(**error);
    } else if (interrupt) {
      use(*scope, now);
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

// What mkTask's function makes as its task starts: the behavior it drives, its exit and error events.
template <class A, class E>
struct AtomicParts {
  Behavior<A> drives;
  Event<E> exit;
  std::optional<Event<RoboErr>> error;
};

// The parts mkTask's function, an F in `closure`, makes, as AtomicParts.
template <class A, class E, class F>
AtomicParts<A, E> makeAtomicParts(void* closure, const TaskState& ts) {
  auto parts = (*static_cast<F*>(closure))(ts);
  if constexpr (std::tuple_size_v<decltype(parts)> == 3) {
    return {toBehavior(std::get<0>(parts)), std::get<1>(parts), std::get<2>(parts)};
  } else {
    return {toBehavior(std::get<0>(parts)), std::get<1>(parts), std::nullopt};
  }
}

// The coroutine behind mkTask and mkTaskE, one per task type (precompiled for the usual ones), not
// one per function; an exit event of Unit makes a Task<A> (no result).
template <class A, class B, class E>
Task<A, B> atomicTask(Erased<AtomicParts<A, E>, const TaskState&> make) {
  TaskState ts = co_await GetState{};
  AtomicParts<A, E> parts = make(ts);
  AtomicAwaiter<A, E> atom(std::move(parts.drives), std::move(parts.exit), std::move(parts.error));
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
}  // namespace frob
