#pragma once
// Nodes of the behavior/event graph: memoised per instant so that each is evaluated once per step.

#include "frob/instant.hpp"

#include <atomic>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

// A call that must be compiled as a jump (a plan's steps chain this way), where the compiler can.
#if defined(__has_cpp_attribute) && __has_cpp_attribute(clang::musttail)
#define FROB_TAIL_CALL [[clang::musttail]]
#else
#define FROB_TAIL_CALL
#endif

namespace frob {

/// The number of behavior and event nodes alive in the process (to prove memory stays bounded).
[[nodiscard]] long liveNodeCount();

namespace detail {

extern std::atomic<long> liveNodes;
// The last instant at which an exception cut a plan short: at that instant, a node a plan leaves
// unchecked may already be up to date, so every plan checks every step.
extern std::atomic<std::uint64_t> planCutShort;

class NodeBase;

// A counted handle to a node, read as N (BehaviorNode<T>, EventNode<T> or the node's own type). The
// count is a shared_ptr<NodeBase>'s, one control block type for every node: a controller's compile
// makes no shared_ptr machinery per node or value type. Copies share the count.
template <class N>
class NodeRef {
 public:
  NodeRef() = default;
  NodeRef(std::shared_ptr<NodeBase> owner, N* node) : owner_(std::move(owner)), node_(node) {}
  N* operator->() const { return node_; }
  N& operator*() const { return *node_; }
  [[nodiscard]] N* get() const { return node_; }
  explicit operator bool() const { return node_ != nullptr; }
  // The number of handles that own the node.
  [[nodiscard]] long use_count() const { return owner_.use_count(); }
  [[nodiscard]] const std::shared_ptr<NodeBase>& owner() const { return owner_; }
  void reset() { owner_.reset(), node_ = nullptr; }

 private:
  std::shared_ptr<NodeBase> owner_;
  N* node_ = nullptr;
};

template <class T>
struct IsNodeRef : std::false_type {};
template <class N>
struct IsNodeRef<NodeRef<N>> : std::true_type {};

// A node a strict node reads, with the number of handles that own it: a plan finds from these
// which nodes no graph but its own can reach. Every input listed is owned by its reader.
struct Input {
  NodeBase* node;
  long owners;
};
// The Input of a node its reader holds through `handle`.
template <class N>
Input inputOf(const NodeRef<N>& handle) {
  return {handle.get(), handle.use_count()};
}
inline Input inputOf(const std::shared_ptr<NodeBase>& handle) { return {handle.get(), handle.use_count()}; }

// One step of a plan: refreshes its node, then runs the next step by a tail call, so that a plan
// runs without a loop or a return per step. The last step of a plan is `last`, which ends it.
struct PlanStep {
  using Run = void (*)(const PlanStep*, const Instant&, std::uint64_t id);
  NodeBase* node;
  Run run;
  static void last(const PlanStep*, const Instant&, std::uint64_t) {}
};

// Refreshes the node of `step` as a `Node` (its refresh inlined when final), then the next step.
template <class Node, bool checked>
void runStep(const PlanStep* step, const Instant& now, std::uint64_t id);

// Counts live nodes; every node derives from it. Holds the instant of the node's value, so that
// a plan (see StrictNode) can bring nodes of any type up to date.
class NodeBase {
 public:
  NodeBase() { liveNodes.fetch_add(1, std::memory_order_relaxed); }
  NodeBase(const NodeBase&) = delete;
  NodeBase& operator=(const NodeBase&) = delete;
  virtual ~NodeBase() { liveNodes.fetch_sub(1, std::memory_order_relaxed); }

  // The id of the instant whose value the node holds (0: none yet).
  [[nodiscard]] std::uint64_t stamp() const { return stamp_; }
  // Computes the value at `now` and holds it; called only when stamp() != now.id.
  virtual void refresh(const Instant& now) = 0;
  // refresh, given now.id, which a plan keeps in a register.
  void refreshAt(const Instant& now, std::uint64_t id) {
    (void)id;
    refresh(now);
  }
  // A plan's step for this node (see PlanStep). A `checked` one first skips a node already up to
  // date (one that other graphs share).
  [[nodiscard]] virtual PlanStep::Run planStep(bool checked) const { return checked ? &runStep<NodeBase, true> : &runStep<NodeBase, false>; }
  // True if the node reads the same inputs at every instant (strictInputs lists them).
  [[nodiscard]] virtual bool strict() const { return false; }
  // True if the node holds one value from its creation: plans leave it out.
  [[nodiscard]] virtual bool constant() const { return false; }
  // True once the node's value is its type's zero for ever: a controller whose task has returned.
  [[nodiscard]] virtual bool stoppedForGood() const { return false; }
  // Appends the nodes a strict node reads at every instant, in the order it reads them. Other
  // nodes (switches, events) read their inputs only sometimes and pull them themselves.
  virtual void strictInputs(std::vector<Input>& out) const { (void)out; }

 protected:
  std::uint64_t stamp_ = 0;
};

// A new node, as the handle its kind is read through (BehaviorNode<T> or EventNode<T>).
template <class Node, class... A>
auto makeNode(A&&... a) {
  using Interface = std::remove_pointer_t<decltype(interfaceOf(static_cast<Node*>(nullptr)))>;
  Node* node = new Node(std::forward<A>(a)...);
  return NodeRef<Interface>(std::shared_ptr<NodeBase>(static_cast<NodeBase*>(node)), node);
}

template <class Node, bool checked>
void runStep(const PlanStep* step, const Instant& now, std::uint64_t id) {
  if (!checked || step->node->stamp() != id) static_cast<Node*>(step->node)->refreshAt(now, id);
  FROB_TAIL_CALL return step[1].run(step + 1, now, id);
}
#undef FROB_TAIL_CALL

// A behavior node: a value at every instant, computed once per instant after its inputs.
template <class T>
class BehaviorNode : public NodeBase {
 public:
  const T& at(const Instant& now) {
    if (stamp_ != now.id) {
      hold(compute(now));
      stamp_ = now.id;
    }
    return value();
  }
  // The value held: the value at `now` once at(now) or a plan has brought the node up to date.
  const T& value() const {
    if constexpr (kPlain) {
      return value_;
    } else {
      return *value_;
    }
  }
  void refresh(const Instant& now) override {
    hold(compute(now));
    stamp_ = now.id;
  }

 protected:
  virtual T compute(const Instant& now) = 0;
  void hold(T&& v) {
    if constexpr (kPlain) {
      value_ = std::move(v);
    } else {
      value_.emplace(std::move(v));
    }
  }

 private:
  // Values that can be default-constructed and assigned are kept directly (cheaper per step).
  static constexpr bool kPlain = std::is_default_constructible_v<T> && std::is_move_assignable_v<T>;
  std::conditional_t<kPlain, T, std::optional<T>> value_{};
};

// The nodes to bring up to date before `root`, in the order a recursive pull would compute them
// (inputs before the nodes that read them, each once): `root`'s strict cone, without `root`. A node
// that only `root` and nodes of the plan own (so no other graph can reach it) is refreshed
// unchecked: it is brought up to date at an instant only by a pass that ends with `root`. The last
// step ends the plan; no steps at all if `root` reads no node.
std::vector<PlanStep> planFor(const NodeBase& root);

// A behavior node that reads the same inputs at every instant (pointwise functions, integral...).
// Sampled directly, it first runs its plan: one flat pass over its strict cone that computes each
// stale node once, inputs first, exactly as a recursive pull would, but without a nested call and
// a memo check for every edge (nor for nodes only this graph reaches). Within a plan, a strict node
// reads its inputs' values directly.
// Derived provides `T computeFresh(const Instant&)`, which may assume its inputs are up to date.
template <class T, class Derived>
class StrictNode : public BehaviorNode<T> {
 public:
  void refresh(const Instant& now) final { refreshAt(now, now.id); }
  void refreshAt(const Instant& now, std::uint64_t id) {
    this->hold(static_cast<Derived*>(this)->computeFresh(now));
    this->stamp_ = id;
  }
  [[nodiscard]] bool strict() const final { return true; }
  [[nodiscard]] PlanStep::Run planStep(bool checked) const final { return checked ? &runStep<StrictNode, true> : &runStep<StrictNode, false>; }

 protected:
  T compute(const Instant& now) final {
    if (first_ == nullptr) [[unlikely]]
      plan();
    if (planCutShort.load(std::memory_order_relaxed) == now.id) [[unlikely]]
      return computeChecked(now);
    try {
      first_->run(first_, now, now.id);
      return static_cast<Derived*>(this)->computeFresh(now);
    } catch (...) {
      planCutShort.store(now.id, std::memory_order_relaxed);
      throw;
    }
  }

 private:
  // At the first sample, not at creation, so that building a graph stays cheap.
  [[gnu::noinline]] void plan() {
    static constexpr PlanStep kNoSteps{nullptr, &PlanStep::last};
    plan_ = planFor(*this);
    first_ = plan_.empty() ? &kNoSteps : plan_.data();
  }
  // The plan with every step checked (a slower pass, after an exception).
  [[gnu::noinline]] T computeChecked(const Instant& now) {
    for (const PlanStep& step : plan_) {
      if (step.node != nullptr && step.node->stamp() != now.id) step.node->refresh(now);
    }
    return static_cast<Derived*>(this)->computeFresh(now);
  }
  std::vector<PlanStep> plan_;       // nodes owned by this node's inputs, which it keeps alive
  const PlanStep* first_ = nullptr;  // where the plan starts; none before the first sample
};

// Where an event's latest occurrence comes from: the source event it occurred in (a sensor, a timer,
// a predicate), which every event derived from it (map, filter, |, once, snapshot) passes on, so that
// one occurrence is known as one whichever event carries it; and how long before the sample it
// happened (a timer's due time falls between samples), seconds.
struct Origin {
  const NodeBase* source = nullptr;
  double lag = 0.0;
};

// An event node: at each instant, at most one occurrence carrying a T.
template <class T>
class EventNode : public NodeBase {
 public:
  const std::optional<T>& at(const Instant& now) {
    if (stamp_ != now.id) {
      occurrence_ = compute(now);
      stamp_ = now.id;
    }
    return occurrence_;
  }
  void refresh(const Instant& now) override {
    occurrence_ = compute(now);
    stamp_ = now.id;
  }
  // The origin of the latest occurrence.
  [[nodiscard]] const Origin& origin() const { return origin_; }

 protected:
  virtual std::optional<T> compute(const Instant& now) = 0;
  // A source's own, at its samples; a derived event's compute copies its input's with each occurrence.
  Origin origin_{this, 0.0};

 private:
  std::optional<T> occurrence_;
};

// Records the instant a stateful node starts: its first sample, less that instant's lag (an event
// between samples started it).
class StartTime {
 public:
  // Seconds since the start (the first call's lag at the first call), from whole steps: k steps
  // after a start on a sample read k × dt, exactly as every other node started with it reads.
  double local(const Instant& now) {
    if (!started_) {
      step_ = now.step;
      lag_ = now.lag;
      started_ = true;
    }
    return static_cast<double>(now.step - step_) * now.dt + lag_;
  }
  [[nodiscard]] bool started() const { return started_; }

 private:
  std::int64_t step_ = 0;
  double lag_ = 0.0;
  bool started_ = false;
};

// The kind a node is read through, for makeNode (declared only: its type is all that is used).
template <class T>
BehaviorNode<T>* interfaceOf(BehaviorNode<T>*);
template <class T>
EventNode<T>* interfaceOf(EventNode<T>*);

}  // namespace detail
}  // namespace frob
