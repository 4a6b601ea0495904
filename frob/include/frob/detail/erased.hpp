#pragma once
// Functions a controller passes to frob (lifted, mapped, a task's maker or handler), kept
// type-erased: a call through a pointer and the closure on the heap. Each lambda then costs the
// controller's compile a call and a delete, not a node type or a coroutine of its own.

#include <cstddef>
#include <cstring>
#include <memory>
#include <utility>

namespace frob::detail {

template <class F>
void deleteClosure(void* f) {
  delete static_cast<F*>(f);
}

// A closure on the heap, freed by the deleter of its type.
using Closure = std::unique_ptr<void, void (*)(void*)>;

// A function R(Args...), one type per signature (std::function would instantiate more per lambda).
template <class R, class... Args>
class Erased {
 public:
  using Call = R (*)(void* closure, Args...);
  template <class F>
  explicit Erased(F f) : call_(&callAs<F>), closure_(new F(std::move(f)), &deleteClosure<F>) {}
  // `closure` called by `call`, which adapts its arguments or result.
  Erased(Call call, Closure closure) : call_(call), closure_(std::move(closure)) {}
  R operator()(Args... a) const { return call_(closure_.get(), std::forward<Args>(a)...); }
  // Whether `other` is the same function: a closure of the same type, of `size` bytes, equal byte
  // for byte (the same lambda capturing the same values).
  [[nodiscard]] bool sameAs(const Erased& other, std::size_t size) const {
    return call_ == other.call_ && std::memcmp(closure_.get(), other.closure_.get(), size) == 0;
  }

 private:
  template <class F>
  static R callAs(void* f, Args... a) {
    return (*static_cast<F*>(f))(std::forward<Args>(a)...);
  }
  Call call_;
  Closure closure_;
};

}  // namespace frob::detail
