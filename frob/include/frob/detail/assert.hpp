#pragma once
// What FROB_ASSERT calls.

namespace frob::detail {

// Throws UsageError for FROB_ASSERT.
[[noreturn]] void failAssert(const char* condition, const char* message, const char* file, int line);

}  // namespace frob::detail
