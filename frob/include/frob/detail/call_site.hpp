#pragma once
// Where a frob function was called from, for its messages and the timeline's task names.

#include <bit>
#include <source_location>

namespace frob::detail {

// As a default argument, the caller's location. std::source_location::current() names the callee
// there under clang 15 (it evaluates the consteval call where the default is written, not where it is
// used); the builtin it wraps names the caller under clang 15 and 16 alike.
[[nodiscard]] inline std::source_location callSite(decltype(__builtin_source_location()) site = __builtin_source_location()) noexcept {
  return std::bit_cast<std::source_location>(site);
}

}  // namespace frob::detail
