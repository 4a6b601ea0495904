// Must NOT compile: a Behavior<bool> where mkTask wants the event that ends the task. The message
// must ask whether predicate(...) was forgotten.
#include <frob/frob.hpp>

using namespace frob;

Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) { return std::pair{wheels(0.3, 0), frontSonar(ts.robot()) < 0.5}; });
}
