#pragma once
// The machinery behind calculus.hpp: the nodes that integrate, differentiate and keep extremes.

#include "frob/behavior.hpp"

#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace frob {
namespace detail {

// Trapezoidal integral from its start: at the first sample, the value there times the instant's lag
// (the time since an event between samples started it), as though it had held since.
template <class T>
class IntegralNode final : public StrictNode<T, IntegralNode<T>> {
 public:
  explicit IntegralNode(NodeRef<BehaviorNode<T>> b) : b_(std::move(b)), sum_(zeroOf<T>()) {}
  void strictInputs(std::vector<Input>& out) const override { out.push_back(inputOf(b_)); }
  T computeFresh(const Instant& now) {
    const T& v = b_->value();
    if (started_) {
      sum_ = sum_ + (v + previous_) * (0.5 * (now.time - previousTime_));
    } else {
      sum_ = v * now.lag;
    }
    started_ = true;
    previous_ = v;
    previousTime_ = now.time;
    return sum_;
  }

 private:
  NodeRef<BehaviorNode<T>> b_;
  T sum_;
  T previous_ = zeroOf<T>();
  double previousTime_ = 0.0;
  bool started_ = false;
};

// Backward difference; zero at the first sample.
template <class T>
class DerivativeNode final : public StrictNode<T, DerivativeNode<T>> {
 public:
  explicit DerivativeNode(NodeRef<BehaviorNode<T>> b) : b_(std::move(b)) {}
  void strictInputs(std::vector<Input>& out) const override { out.push_back(inputOf(b_)); }
  T computeFresh(const Instant& now) {
    const T& v = b_->value();
    T d = zeroOf<T>();
    if (now.time > previousTime_) d = (v - previous_) / (now.time - previousTime_);
    previous_ = v;
    previousTime_ = now.time;
    return d;
  }

 private:
  NodeRef<BehaviorNode<T>> b_;
  T previous_ = zeroOf<T>();
  double previousTime_ = std::numeric_limits<double>::infinity();  // no difference at the first sample
};

// The value of `b` when `key` was best so far (smallest, or largest with `wantMax`); earliest wins ties.
template <class K, class T>
class AtExtremumNode final : public StrictNode<T, AtExtremumNode<K, T>> {
 public:
  AtExtremumNode(NodeRef<BehaviorNode<K>> key, NodeRef<BehaviorNode<T>> b, bool wantMax)
      : key_(std::move(key)), b_(std::move(b)), wantMax_(wantMax) {}
  void strictInputs(std::vector<Input>& out) const override {
    out.push_back(inputOf(key_));
    out.push_back(inputOf(b_));
  }
  T computeFresh(const Instant&) {
    const K& k = key_->value();
    const T& v = b_->value();
    if (!best_ || (wantMax_ ? *bestKey_ < k : k < *bestKey_)) {
      bestKey_ = k;
      best_ = v;
    }
    return *best_;
  }

 private:
  NodeRef<BehaviorNode<K>> key_;
  NodeRef<BehaviorNode<T>> b_;
  bool wantMax_;
  std::optional<K> bestKey_;
  std::optional<T> best_;
};

}  // namespace detail
}  // namespace frob
