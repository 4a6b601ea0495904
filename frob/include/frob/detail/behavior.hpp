#pragma once
// The machinery behind behavior.hpp: type traits for behaviors, the nodes constant and time
// behaviors become, and the node of a lifted function (one type per result type and arity).

#include "frob/detail/erased.hpp"
#include "frob/detail/node.hpp"
#include "frob/geometry.hpp"

#include <array>
#include <functional>
#include <memory>
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
  explicit ConstantNode(T v) { this->hold(std::move(v)); }
  [[nodiscard]] bool constant() const override { return true; }

 protected:
  T compute(const Instant&) override { return this->value(); }
};

// A lifted function's node, one type per result type R and number of inputs N: the function is
// type-erased (see erased.hpp), with a call that reads the inputs, so that a lambda costs no node
// type of its own (nor one per signature); the common result types are precompiled.
template <class... Vs>
struct Inputs {};
// Calls closure F with the values of its inputs, which are BehaviorNode<Vs>... in order.
template <class R, class F, class Vs, class I = void>
struct LiftCall;
template <class R, class F, class... Vs>
struct LiftCall<R, F, Inputs<Vs...>, void> : LiftCall<R, F, Inputs<Vs...>, std::index_sequence_for<Vs...>> {};
template <class R, class F, class... Vs, std::size_t... I>
struct LiftCall<R, F, Inputs<Vs...>, std::index_sequence<I...>> {
  static R call(const void* closure, NodeBase* const* in) {
    const F& f = *static_cast<const F*>(closure);
    if constexpr (std::is_member_pointer_v<F>) {
      return R(plain(std::invoke(f, static_cast<BehaviorNode<Vs>*>(in[I])->value()...)));
    } else {
      return R(plain(f(static_cast<BehaviorNode<Vs>*>(in[I])->value()...)));
    }
  }
};
template <class R, std::size_t N>
class LiftNode final : public StrictNode<R, LiftNode<R, N>> {
 public:
  using Call = R (*)(const void* closure, NodeBase* const* inputs);
  LiftNode(Call call, Closure closure, std::array<std::shared_ptr<NodeBase>, N> inputs)
      : call_(call), closure_(std::move(closure)), owners_(std::move(inputs)) {
    for (std::size_t i = 0; i < N; ++i) inputs_[i] = owners_[i].get();
  }
  R computeFresh(const Instant&) { return call_(closure_.get(), inputs_.data()); }
  void strictInputs(std::vector<Input>& out) const override {
    for (const std::shared_ptr<NodeBase>& in : owners_) out.push_back(inputOf(in));
  }

 private:
  Call call_;
  Closure closure_;
  std::array<std::shared_ptr<NodeBase>, N> owners_;
  std::array<NodeBase*, N> inputs_{};  // the nodes of owners_
};

// The node a lifted argument is read from: a behavior's own, or a constant's for a plain value.
template <class A>
std::shared_ptr<NodeBase> inputNode(A&& a) {
  using D = std::remove_cvref_t<A>;
  if constexpr (IsPointwise<D>::value) {
    return a.behavior().node().owner();
  } else if constexpr (IsBehavior<D>::value) {
    return a.node().owner();
  } else {
    return makeNode<ConstantNode<D>>(std::forward<A>(a)).owner();
  }
}

// The node a reading (a Pointwise) becomes.
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
