#pragma once
// Private: printf-style formatting into a std::string, for the grader's and the diagnosis's messages.
#include <cstdio>
#include <string>

namespace frob::course {

template <class... A>
std::string format(const char* f, A... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, f, args...);
  return buf;
}

}  // namespace frob::course
