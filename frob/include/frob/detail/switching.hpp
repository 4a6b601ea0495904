#pragma once
// The machinery behind switching.hpp: the nodes that follow one behavior, then another.

#include "frob/event.hpp"

#include <memory>
#include <optional>

namespace frob {
namespace detail {

// Counts switches nested within one instant on this thread; throws FrobError when a behavior
// switches endlessly at one instant (each switch immediately firing the next) instead of
// overflowing the stack.
class SwitchChainGuard {
 public:
  SwitchChainGuard();
  ~SwitchChainGuard();
  SwitchChainGuard(const SwitchChainGuard&) = delete;
  SwitchChainGuard& operator=(const SwitchChainGuard&) = delete;
};

// Follows `b` until `e` first occurs, then the behavior it carries, started at the occurrence (which
// a timer's may put between samples: what it first samples then begins that long before).
// With `repeat`, switches again at every occurrence (switcher).
template <class T>
class SwitchNode final : public BehaviorNode<T> {
 public:
  SwitchNode(NodeRef<BehaviorNode<T>> b, NodeRef<EventNode<Behavior<T>>> e, bool repeat) : e_(std::move(e)), repeat_(repeat) { follow(std::move(b)); }

 protected:
  T compute(const Instant& now) override {
    // A finished untilB inside only forwards: skip it, so a behavior that switches forever
    // (untilB of untilB of ...) stays a short chain and old nodes are freed.
    while (inner_ != nullptr && !inner_->e_) follow(inner_->b_);
    if (e_) {
      if (const std::optional<Behavior<T>>& next = e_->at(now)) {
        Instant at = now;
        at.lag = e_->origin().lag;
        follow(next->node());
        if (!repeat_) e_.reset();  // release the event so that its graph can be freed
        SwitchChainGuard guard;    // the new behavior may switch again at this instant, but not forever
        return b_->at(at);
      }
    }
    return b_->at(now);
  }

 private:
  void follow(NodeRef<BehaviorNode<T>> b) {
    b_ = std::move(b);
    inner_ = dynamic_cast<SwitchNode*>(b_.get());
  }

  NodeRef<BehaviorNode<T>> b_;
  SwitchNode* inner_ = nullptr;  // b_ when it is itself a switch
  NodeRef<EventNode<Behavior<T>>> e_;
  bool repeat_;
};

template <class T>
class HoldNode final : public BehaviorNode<T> {
 public:
  HoldNode(T init, NodeRef<EventNode<T>> e) : value_(std::move(init)), e_(std::move(e)) {}

 protected:
  T compute(const Instant& now) override {
    if (const std::optional<T>& o = e_->at(now)) value_ = *o;
    return value_;
  }

 private:
  T value_;
  NodeRef<EventNode<T>> e_;
};

}  // namespace detail
}  // namespace frob
