#pragma once
// Nodes of the behavior/event graph: memoised per instant so that each is evaluated once per step.

#include "frob/instant.hpp"

#include <atomic>
#include <memory>
#include <optional>
#include <type_traits>

namespace frob {

/// The number of behavior and event nodes alive in the process (to prove memory stays bounded).
[[nodiscard]] long liveNodeCount();

namespace detail {

extern std::atomic<long> liveNodes;

// Counts live nodes; every node derives from it.
class NodeBase {
 public:
  NodeBase() { liveNodes.fetch_add(1, std::memory_order_relaxed); }
  NodeBase(const NodeBase&) = delete;
  NodeBase& operator=(const NodeBase&) = delete;
  virtual ~NodeBase() { liveNodes.fetch_sub(1, std::memory_order_relaxed); }
};

// A behavior node: a value at every instant, computed once per instant after its inputs.
template <class T>
class BehaviorNode : public NodeBase {
 public:
  const T& at(const Instant& now) {
    if (stamp_ != now.id) {
      if constexpr (kPlain) {
        value_ = compute(now);
      } else {
        value_.emplace(compute(now));
      }
      stamp_ = now.id;
    }
    if constexpr (kPlain) {
      return value_;
    } else {
      return *value_;
    }
  }

 protected:
  virtual T compute(const Instant& now) = 0;

 private:
  // Values that can be default-constructed and assigned are kept directly (cheaper per step).
  static constexpr bool kPlain = std::is_default_constructible_v<T> && std::is_move_assignable_v<T>;
  std::uint64_t stamp_ = 0;
  std::conditional_t<kPlain, T, std::optional<T>> value_{};
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

 protected:
  virtual std::optional<T> compute(const Instant& now) = 0;

 private:
  std::uint64_t stamp_ = 0;
  std::optional<T> occurrence_;
};

// Records the first instant a stateful node is sampled: its start time.
class StartTime {
 public:
  // Seconds since the first call (0 at the first call).
  double local(const Instant& now) {
    if (!started_) {
      start_ = now.time;
      started_ = true;
    }
    return now.time - start_;
  }
  [[nodiscard]] bool started() const { return started_; }

 private:
  double start_ = 0.0;
  bool started_ = false;
};

}  // namespace detail
}  // namespace frob
