// Reads past the end of a vector from half a second on. Unchecked it drives on with whatever lies
// there; frob run --check stops it at the marked line.
#include <frob/frob.hpp>

#include <vector>

using namespace frob;

double speedAt(double now) {
  static const std::vector<double> speeds{0.1, 0.1, 0.1};
  const std::size_t i = now < 0.5 ? 0 : 3;
  return speeds[i];  // CHECKED: one past the end
}

Behavior<Wheels> outOfRange(const Robot&) {
  return toBehavior(lift([](double now) { return Wheels{speedAt(now), 0.0}; }, time()));
}
FROB_CONTROLLER(outOfRange)
