#include "frob/robot_values.hpp"

#include <cstdio>

namespace frob {

std::string toString(const Wheels& w) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "{forward %.3f m/s, turn %.3f rad/s}", w.forward, w.turn);
  return buf;
}

std::string toString(const Pose2& p) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.3f, %.3f) heading %.3f rad", p.position.x(), p.position.y(), p.heading);
  return buf;
}

}  // namespace frob
