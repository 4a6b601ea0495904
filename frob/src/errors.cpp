#include "frob/errors.hpp"

#include "frob/switching.hpp"

#include <cstdio>

namespace frob::detail {

void failAssert(const char* condition, const char* message, const char* file, int line) {
  throw UsageError(std::string(file) + ":" + std::to_string(line) + ": " + message + " (" + condition + ")");
}

}  // namespace frob::detail

namespace frob::detail {

std::string notFiniteMessage(const std::string& what, const Instant& now) {
  char when[48];
  std::snprintf(when, sizeof when, " at t = %.3f s", now.time);
  return what + " is not a finite number (NaN or infinity)" + when;
}

}  // namespace frob::detail

namespace frob::detail {

namespace {
// Far beyond any sensible chain of switches at one instant, far below a stack overflow.
constexpr int kMaxSwitchesPerInstant = 1000;
thread_local int switchDepth = 0;
}  // namespace

SwitchChainGuard::SwitchChainGuard() {
  if (++switchDepth > kMaxSwitchesPerInstant) {
    --switchDepth;  // this guard is not constructed, so its destructor will not run
    throw FrobError("a behavior switched more than " + std::to_string(kMaxSwitchesPerInstant) +
                    " times at one instant: an untilB or switcher whose new behavior's event occurs at once, forever");
  }
}

SwitchChainGuard::~SwitchChainGuard() { --switchDepth; }

}  // namespace frob::detail
