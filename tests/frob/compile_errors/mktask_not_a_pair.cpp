// Must NOT compile: mkTask's function returns only a behavior, without the event that ends it.
#include <frob/frob.hpp>

using namespace frob;

Task<Wheels> spin() {
  return mkTask([](const TaskState&) { return wheels(0, 1); });
}
