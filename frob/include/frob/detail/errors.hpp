#pragma once
// The machinery behind errors.hpp: the node checkFinite makes.
// errors.hpp includes it once it has declared FrobError and isFinite.

#include "frob/behavior.hpp"

#include <memory>
#include <string>

namespace frob {
namespace detail {

[[nodiscard]] std::string notFiniteMessage(const std::string& what, const Instant& now);

template <class T>
class CheckFiniteNode final : public BehaviorNode<T> {
 public:
  CheckFiniteNode(NodeRef<BehaviorNode<T>> b, std::string what) : b_(std::move(b)), what_(std::move(what)) {}

 protected:
  T compute(const Instant& now) override {
    const T& v = b_->at(now);
    if (!isFinite(v)) throw FrobError(notFiniteMessage(what_, now));
    return v;
  }

 private:
  NodeRef<BehaviorNode<T>> b_;
  std::string what_;
};

}  // namespace detail
}  // namespace frob
