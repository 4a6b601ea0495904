#pragma once
/// FNV-1a, 64 bits: the one hash of the project's golden values and caches (trajectories, the
/// renderer's static layers, compiled controllers, secret seeds).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <type_traits>

namespace frob::worlds {

/// Start value of the FNV-1a 64-bit hash.
inline constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ULL;

/// A running FNV-1a hash. add() folds in bytes; value() is the hash so far.
class Fnv1a {
 public:
  explicit Fnv1a(std::uint64_t start = kFnvOffset) : h_(start) {}
  /// The bytes of `text`.
  Fnv1a& add(std::string_view text) { return addBytes(text.data(), text.size()); }
  /// The exact bytes of a plain value (a double's bits, an integer's bytes).
  template <class T>
    requires std::is_trivially_copyable_v<T>
  Fnv1a& add(const T& v) {
    unsigned char bytes[sizeof v];
    std::memcpy(bytes, &v, sizeof v);
    return addBytes(bytes, sizeof v);
  }
  [[nodiscard]] std::uint64_t value() const { return h_; }

 private:
  Fnv1a& addBytes(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ULL;
    return *this;
  }
  std::uint64_t h_;
};

}  // namespace frob::worlds
