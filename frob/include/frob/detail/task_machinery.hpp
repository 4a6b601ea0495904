#pragma once
// The machinery behind Task: promises, awaiters, the per-run context and the runner node.
// Every frame of one runTask shares a RunContext; an atomic task parks itself in the context and
// suspends back to the runner, which checks its events each instant and resumes it when one occurs.

#include "frob/debug.hpp"
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
#include <sstream>
#include <string>
#include <string_view>
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

// "frob::Task<frob::Wheels> goAhead()" -> "goAhead"; file and line as "file.cpp:12".
[[nodiscard]] std::string taskName(const char* functionName);
[[nodiscard]] std::string taskWhere(const std::source_location& loc);
// A readable message for an exception in flight; `why` gives its kind for the timeline.
[[nodiscard]] std::string describe(const std::exception_ptr& e, TaskEnd* why = nullptr);
// How deep tasks may await one another in one run; only a recursion that never unwinds gets there.
inline constexpr int kMaxTaskDepth = 1000;
// Why a run stopped with tasks nested deeper than `limit`: `chain`, innermost first, names the
// tasks, and the one most often in it is the recursion, shown with its fix (become).
[[nodiscard]] std::string tooDeepMessage(const std::vector<std::string>& chain, int limit);
// The robot error `e` holds, if it is one (only a RoboErr is; a std::logic_error is a bug).
[[nodiscard]] std::optional<RoboErr> roboErrIn(const std::exception_ptr& e);

namespace print {
// Matches an enum exactly, so that `os << v` picks it over the enum's promotion to int or char,
// but loses to an operator<< the enum's author wrote (a function beats a template). Never defined.
struct NoOperator {};
template <class E>
  requires std::is_enum_v<E>
NoOperator operator<<(std::ostream&, const E&);
// A value with an operator<< of its own (or the standard one of a number or string).
template <class R>
concept Streamable = requires(std::ostream& os, const R& v) {
  { os << v } -> std::same_as<std::ostream&>;
};
}  // namespace print

// "frob::Wheels" from the signature of typeName<frob::Wheels>() (its __PRETTY_FUNCTION__).
[[nodiscard]] std::string typeNameIn(std::string_view signature);
template <class T>
std::string typeName() {
  return typeNameIn(__PRETTY_FUNCTION__);
}

// Printable form of a task's result for the timeline, as the type reads: its operator<< (a bool as
// true or false), its toString, an optional's value or "none", else the type's name.
template <class R>
std::string printable(const R& v) {
  if constexpr (std::is_same_v<R, Unit>) {
    return "";
  } else if constexpr (print::Streamable<R>) {
    std::ostringstream os;
    os << std::boolalpha << v;
    return os.str();
  } else if constexpr (requires { toString(v); }) {
    return toString(v);
  } else if constexpr (requires {
                         v.has_value();
                         *v;
                       }) {
    return v.has_value() ? printable(*v) : std::string("none");
  } else {
    return typeName<R>();
  }
}

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
  // Its output at `now`, or null when it ended at `now` (its result or error is then stored).
  virtual const A* step(const Instant& now) = 0;
  virtual void fail(std::exception_ptr e) = 0;  // ends it with an error
  AtomicBase() = default;
  AtomicBase(const AtomicBase&) = delete;
  AtomicBase& operator=(const AtomicBase&) = delete;
  virtual ~AtomicBase() = default;
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

  // The paper's snapRobot: record where the robot is as one task ends and the next begins.
  void snapshot(const Instant& at) {
    now = &at;
    time = at.time;
    state.setInitialPlace(state.robot().place().at(at)).setInitialOrientation(state.robot().orientation().at(at)).setStartTime(at.time);
  }
  // The run's output one instant late (withMyResult, withTask); the runner records it from now on.
  Behavior<A> delayedOutput() {
    if (!output) output = std::make_shared<OutputCell<A>>();
    return Behavior<A>(std::make_shared<DelayedNode<A>>(output));
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
    std::vector<std::string> chain;
    for (const PromiseBase* p = this; p != nullptr; p = p->caller) {
      if (!p->quiet) chain.push_back(p->name);
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

}  // namespace detail
}  // namespace frob
