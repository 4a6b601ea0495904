#include "frob/geometry.hpp"

#include <cmath>

namespace frob {

double wrapAngle(double radians) {
  if (radians > -pi && radians <= pi) return radians;  // the usual case, and what remainder gives it
  double a = std::remainder(radians, 2.0 * pi);        // in [-pi, pi]
  return a <= -pi ? a + 2.0 * pi : a;
}

double angleDiff(double from, double to) { return wrapAngle(to - from); }

}  // namespace frob
