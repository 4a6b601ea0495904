// The pointwise functions of behaviors of numbers, truths and points (behavior.hpp), compiled once
// here: each is the lift a controller's own expression would otherwise instantiate.
#include "frob/behavior.hpp"

#include <cmath>
#include <initializer_list>
#include <memory>
#include <vector>

namespace frob::detail::numbers {

B add(const B& a, const B& b) {
  return lift([](double x, double y) { return x + y; }, a, b);
}
B subtract(const B& a, const B& b) {
  return lift([](double x, double y) { return x - y; }, a, b);
}
B multiply(const B& a, const B& b) {
  return lift([](double x, double y) { return x * y; }, a, b);
}
B divide(const B& a, const B& b) {
  return lift([](double x, double y) { return x / y; }, a, b);
}
Truth less(const B& a, const B& b) {
  return lift([](double x, double y) { return x < y; }, a, b);
}
Truth lessEqual(const B& a, const B& b) {
  return lift([](double x, double y) { return x <= y; }, a, b);
}
Truth greater(const B& a, const B& b) {
  return lift([](double x, double y) { return x > y; }, a, b);
}
Truth greaterEqual(const B& a, const B& b) {
  return lift([](double x, double y) { return x >= y; }, a, b);
}
Truth equal(const B& a, const B& b) {
  return lift([](double x, double y) { return x == y; }, a, b);
}
Truth notEqual(const B& a, const B& b) {
  return lift([](double x, double y) { return x != y; }, a, b);
}
Truth logicalAnd(const Truth& a, const Truth& b) {
  return lift([](bool x, bool y) { return x && y; }, a, b);
}
Truth logicalOr(const Truth& a, const Truth& b) {
  return lift([](bool x, bool y) { return x || y; }, a, b);
}
Truth negate(const Truth& a) {
  return lift([](bool x) { return !x; }, a);
}
B minus(const B& a) {
  return lift([](double x) { return -x; }, a);
}
B sin(const B& a) {
  return lift([](double x) { return std::sin(x); }, a);
}
B cos(const B& a) {
  return lift([](double x) { return std::cos(x); }, a);
}
B tan(const B& a) {
  return lift([](double x) { return std::tan(x); }, a);
}
B asin(const B& a) {
  return lift([](double x) { return std::asin(x); }, a);
}
B acos(const B& a) {
  return lift([](double x) { return std::acos(x); }, a);
}
B atan(const B& a) {
  return lift([](double x) { return std::atan(x); }, a);
}
B sqrt(const B& a) {
  return lift([](double x) { return std::sqrt(x); }, a);
}
B exp(const B& a) {
  return lift([](double x) { return std::exp(x); }, a);
}
B log(const B& a) {
  return lift([](double x) { return std::log(x); }, a);
}
B abs(const B& a) {
  return lift([](double x) { return std::abs(x); }, a);
}
B floor(const B& a) {
  return lift([](double x) { return std::floor(x); }, a);
}
B ceil(const B& a) {
  return lift([](double x) { return std::ceil(x); }, a);
}
B wrapAngle(const B& a) {
  return lift([](double x) { return frob::wrapAngle(x); }, a);
}
B max(const B& a, const B& b) {
  return lift([](double x, double y) { return x < y ? y : x; }, a, b);
}
B min(const B& a, const B& b) {
  return lift([](double x, double y) { return y < x ? y : x; }, a, b);
}

namespace {
// The largest (`larger`) or smallest of its inputs at each instant, the first of equals, as
// std::max and std::min of an initializer list choose.
class ExtremumNode final : public StrictNode<double, ExtremumNode> {
 public:
  ExtremumNode(std::initializer_list<B> all, bool larger) : larger_(larger) {
    for (const B& b : all) inputs_.push_back(b.node());
  }
  double computeFresh(const Instant&) {
    double best = inputs_.front()->value();
    for (std::size_t i = 1; i < inputs_.size(); ++i) {
      const double v = inputs_[i]->value();
      if (larger_ ? best < v : v < best) best = v;
    }
    return best;
  }
  void strictInputs(std::vector<Input>& out) const override {
    for (const auto& node : inputs_) out.push_back(inputOf(node));
  }

 private:
  std::vector<NodeRef<BehaviorNode<double>>> inputs_;
  bool larger_;
};
}  // namespace

B maxOf(std::initializer_list<B> all) { return B(makeNode<ExtremumNode>(all, true)); }
B minOf(std::initializer_list<B> all) { return B(makeNode<ExtremumNode>(all, false)); }
B clamp(const B& v, const B& lo, const B& hi) {
  return lift([](double x, double l, double h) { return x < l ? l : (h < x ? h : x); }, v, lo, hi);
}
B atan2(const B& y, const B& x) {
  return lift([](double a, double b) { return std::atan2(a, b); }, y, x);
}
B pow(const B& base, const B& e) {
  return lift([](double a, double b) { return std::pow(a, b); }, base, e);
}
P add(const P& a, const P& b) {
  return lift([](const Point2& x, const Point2& y) { return x + y; }, a, b);
}
P subtract(const P& a, const P& b) {
  return lift([](const Point2& x, const Point2& y) { return x - y; }, a, b);
}
P multiply(const P& a, const B& b) {
  return lift([](const Point2& x, double y) { return x * y; }, a, b);
}
P multiply(const B& a, const P& b) {
  return lift([](double x, const Point2& y) { return x * y; }, a, b);
}
P divide(const P& a, const B& b) {
  return lift([](const Point2& x, double y) { return x / y; }, a, b);
}
B distance(const P& a, const P& b) {
  return lift([](const Point2& p, const Point2& q) { return (p - q).norm(); }, a, b);
}
B norm(const Behavior<Vec2>& v) {
  return lift([](const Vec2& x) { return x.norm(); }, v);
}
B heading(const Behavior<Vec2>& v) {
  return lift([](const Vec2& x) { return std::atan2(x.y(), x.x()); }, v);
}

}  // namespace frob::detail::numbers
