// Divides an integer by zero from half a second on; frob run --check stops it at the marked line.
#include <frob/frob.hpp>

using namespace frob;

int stepsPerSecond(int steps, int seconds) {
  return steps / seconds;  // CHECKED: seconds is 0
}

Behavior<Wheels> intDivision(const Robot&) {
  return toBehavior(lift([](double now) { return Wheels{0.001 * stepsPerSecond(100, now < 0.5 ? 1 : 0), 0.0}; }, time()));
}
FROB_CONTROLLER(intDivision)
