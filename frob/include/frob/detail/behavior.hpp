#pragma once
// The machinery behind behavior.hpp: type traits for behaviors, the nodes constant and time
// behaviors become, and how a lifted function reads each of its arguments.

#include "frob/detail/node.hpp"
#include "frob/geometry.hpp"

#include <functional>
#include <memory>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace frob {

template <class T>
class Behavior;
template <class R, class F, class... Args>
class Pointwise;

namespace detail {

template <class T>
struct IsBehavior : std::false_type {};
template <class T>
struct IsBehavior<Behavior<T>> : std::true_type {};
template <class R, class F, class... Args>
struct IsBehavior<Pointwise<R, F, Args...>> : std::true_type {};

template <class T>
struct ValueOf {
  using type = T;
};
template <class T>
struct ValueOf<Behavior<T>> {
  using type = T;
};
template <class R, class F, class... Args>
struct ValueOf<Pointwise<R, F, Args...>> {
  using type = R;
};

template <class T>
struct IsPointwise : std::false_type {};
template <class R, class F, class... Args>
struct IsPointwise<Pointwise<R, F, Args...>> : std::true_type {};

// What a computed value is kept as: Eigen's lazy expressions become plain vectors, pointwise
// behavior expressions become behaviors (e.g. a behavior returned from an event's map function).
template <class R>
auto plain(R&& r) {
  using D = std::remove_cvref_t<R>;
  if constexpr (std::is_base_of_v<Eigen::EigenBase<D>, D>) {
    return r.eval();
  } else if constexpr (IsPointwise<D>::value) {
    return r.behavior();
  } else {
    return D(std::forward<R>(r));
  }
}

template <class T>
class ConstantNode final : public BehaviorNode<T> {
 public:
  explicit ConstantNode(T v) : value_(std::move(v)) {}

 protected:
  T compute(const Instant&) override { return value_; }

 private:
  T value_;
};

// One argument of a lifted function: a behavior sampled at the instant, a pointwise expression
// evaluated in place, or a plain value. `fresh` is `get` for a node whose inputs a plan has
// already brought up to date; `inputs` lists the nodes read.
template <class A>
struct Arg {
  A value;
  const A& get(const Instant&) const { return value; }
  const A& fresh(const Instant&) const { return value; }
  void inputs(std::vector<Input>&) const {}
};
template <class T>
struct Arg<Behavior<T>> {
  std::shared_ptr<BehaviorNode<T>> node;
  const T& get(const Instant& now) const { return node->at(now); }
  const T& fresh(const Instant&) const { return node->value(); }
  void inputs(std::vector<Input>& out) const { out.push_back(inputOf(node)); }
};
template <class R, class F, class... Args>
struct Arg<Pointwise<R, F, Args...>> {
  Pointwise<R, F, Args...> expr;
  R get(const Instant& now) const { return expr.eval(now); }
  R fresh(const Instant& now) const { return expr.evalFresh(now); }
  void inputs(std::vector<Input>& out) const { expr.inputs(out); }
};

template <class A>
Arg<std::remove_cvref_t<A>> makeArg(A&& a) {
  if constexpr (IsBehavior<std::remove_cvref_t<A>>::value && !IsPointwise<std::remove_cvref_t<A>>::value) {
    return {a.node()};
  } else {
    return {std::forward<A>(a)};
  }
}

// The node a pointwise expression becomes: one node for the whole expression tree.
template <class R, class Expr>
class PointwiseNode final : public StrictNode<R, PointwiseNode<R, Expr>> {
 public:
  explicit PointwiseNode(Expr e) : expr_(std::move(e)) {}
  R computeFresh(const Instant& now) { return expr_.evalFresh(now); }
  void strictInputs(std::vector<Input>& out) const override { expr_.inputs(out); }

 private:
  Expr expr_;
};

class TimeNode final : public BehaviorNode<double> {
 protected:
  double compute(const Instant& now) override { return start_.local(now); }

 private:
  StartTime start_;
};

}  // namespace detail
}  // namespace frob
