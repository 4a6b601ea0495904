// An assert that fails from half a second on: checked, asserts are on, and the run stops there.
#include <frob/frob.hpp>

#include <cassert>

using namespace frob;

double speedAt(double now) {
  const double speed = now < 0.5 ? 0.1 : -0.1;
  assert(speed > 0);  // CHECKED: fails from 0.5 s
  return speed;
}

Behavior<Wheels> failsAssert(const Robot&) {
  return toBehavior(lift([](double now) { return Wheels{speedAt(now), 0.0}; }, time()));
}
FROB_CONTROLLER(failsAssert)
