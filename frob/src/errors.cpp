#include "frob/errors.hpp"

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
