#include "frob/sensing.hpp"

#include "frob/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace frob {

std::string toString(const Echo& e) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f m at %.1f deg", e.range, e.angle * 180.0 / pi);
  return buf;
}

Behavior<Echo> nearestEcho(const Robot& r, double from, double to) {
  FROB_ASSERT(from <= to && to - from <= 2 * pi + 1e-9, "nearestEcho: give from <= to, at most a full turn apart");
  // The sonars in the span, in order of their offset counter-clockwise from `from`.
  const std::vector<double>& angles = r.spec().sonarAngles;
  std::vector<std::pair<double, std::size_t>> inSpan;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    double offset = std::fmod(angles[i] - from, 2 * pi);
    if (offset < -1e-9) offset += 2 * pi;
    if (offset <= to - from + 1e-9) inSpan.emplace_back(offset, i);
  }
  FROB_ASSERT(!inSpan.empty(), "nearestEcho: no sonar points between `from` and `to`");
  std::sort(inSpan.begin(), inSpan.end());
  std::vector<std::size_t> which;
  for (const auto& [offset, i] : inSpan) which.push_back(i);
  return lift(
      [which, angles](const std::vector<double>& ranges) {
        Echo best{ranges.at(which.front()), angles[which.front()]};
        for (std::size_t i : which) {
          if (ranges.at(i) < best.range) best = Echo{ranges[i], angles[i]};
        }
        return best;
      },
      r.sonars());
}

}  // namespace frob
