#pragma once
// The machinery behind behavior.hpp: type traits for behaviors, the nodes constant and time
// behaviors become, and the node of a lifted function (one type per signature).

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
  explicit ConstantNode(T v) { this->hold(std::move(v)); }
  [[nodiscard]] bool constant() const override { return true; }

 protected:
  T compute(const Instant&) override { return this->value(); }
};

// A lifted function's node, one type per signature R(Vs...): the function is kept type-erased (a
// pointer to its call and its closure on the heap), so that each lambda a controller lifts costs a
// call and a delete, not a node type of its own; the common signatures are precompiled.
template <class F>
void deleteClosure(void* f) {
  delete static_cast<F*>(f);
}
template <class R, class F, class... Vs>
R callClosure(const void* f, const Vs&... v) {
  return R(plain(std::invoke(*static_cast<const F*>(f), v...)));
}
template <class R, class... Vs>
class LiftNode final : public StrictNode<R, LiftNode<R, Vs...>> {
 public:
  using Call = R (*)(const void*, const Vs&...);
  LiftNode(Call call, std::unique_ptr<void, void (*)(void*)> closure, std::shared_ptr<BehaviorNode<Vs>>... inputs)
      : call_(call), closure_(std::move(closure)), inputs_(std::move(inputs)...) {}
  R computeFresh(const Instant&) {
    return std::apply([&](const auto&... in) { return call_(closure_.get(), in->value()...); }, inputs_);
  }
  void strictInputs(std::vector<Input>& out) const override {
    std::apply([&](const auto&... in) { (out.push_back(inputOf(in)), ...); }, inputs_);
  }

 private:
  Call call_;
  std::unique_ptr<void, void (*)(void*)> closure_;
  std::tuple<std::shared_ptr<BehaviorNode<Vs>>...> inputs_;
};

// The node a lifted argument is read from: a behavior's own, or a constant's for a plain value.
template <class A>
auto inputNode(A&& a) {
  using D = std::remove_cvref_t<A>;
  if constexpr (IsPointwise<D>::value) {
    return a.behavior().node();
  } else if constexpr (IsBehavior<D>::value) {
    return a.node();
  } else {
    return makeNode<ConstantNode<D>>(std::forward<A>(a));
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
