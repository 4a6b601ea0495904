#pragma once
/// FROB_ASSERT: a programmer's mistake (a call the function does not allow), caught in every build.

#include "frob/detail/assert.hpp"

/// Checks a precondition in every build; throws frob::UsageError naming the file, line and `message`.
#define FROB_ASSERT(condition, message) ((condition) ? static_cast<void>(0) : ::frob::detail::failAssert(#condition, message, __FILE__, __LINE__))
