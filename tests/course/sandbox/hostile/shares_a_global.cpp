// Counts in a global variable the robots whose controllers were built in its process, and drives at
// 10 cm/s for each: robots that shared a process could tell one another anything this way.
#include "misbehave.hpp"
int robotsHere = 0;
Behavior<Wheels> sharesAGlobal(const Robot&) {
  ++robotsHere;
  return toBehavior(lift([](double) { return Wheels{0.1 * robotsHere, 0.0}; }, time()));
}
FROB_CONTROLLER(sharesAGlobal)
