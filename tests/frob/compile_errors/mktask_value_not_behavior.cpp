// Must NOT compile: a plain Wheels value where mkTask wants the behavior the task drives... a value
// is accepted by Behavior's constructor, but not deduced as one: the message names the fix.
#include <frob/frob.hpp>

using namespace frob;

Task<Wheels> stop() {
  return mkTask([](const TaskState&) { return std::pair{Wheels{0, 0}, after(1.0)}; });
}
