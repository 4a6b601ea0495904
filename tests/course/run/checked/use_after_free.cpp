// Reads memory it has just freed, from half a second on; frob run --check stops it at the marked line.
#include <frob/frob.hpp>

using namespace frob;

double* kept = nullptr;  // global, so that the compiler cannot drop the allocation

double speedAt(double now) {
  kept = new double(0.1);
  if (now >= 0.5) delete kept;
  const double speed = *kept;  // CHECKED: freed above
  if (now < 0.5) delete kept;
  return speed;
}

Behavior<Wheels> useAfterFree(const Robot&) {
  return toBehavior(lift([](double now) { return Wheels{speedAt(now), 0.0}; }, time()));
}
FROB_CONTROLLER(useAfterFree)
