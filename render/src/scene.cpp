#include "frob/render/scene.hpp"

#include <cmath>

namespace frob::render {

int frontSonarIndex(const RobotSpec& spec) {
  int best = -1;
  double bestAngle = 1e9;
  for (std::size_t i = 0; i < spec.sonarAngles.size(); ++i) {
    const double a = std::abs(wrapAngle(spec.sonarAngles[i]));
    if (a < bestAngle) bestAngle = a, best = static_cast<int>(i);
  }
  return best;
}

}  // namespace frob::render
