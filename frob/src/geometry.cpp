#include "frob/geometry.hpp"

#include <cmath>

namespace frob {

double wrapAngle(double radians) {
  double a = std::remainder(radians, 2.0 * pi);  // in [-pi, pi]
  return a <= -pi ? a + 2.0 * pi : a;
}

double angleDiff(double from, double to) { return wrapAngle(to - from); }

}  // namespace frob
