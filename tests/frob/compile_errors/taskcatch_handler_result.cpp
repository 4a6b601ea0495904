// Must NOT compile: a taskCatch handler whose task ends without the bool the guarded task ends
// with. The message must say "handler" and what it must return, not fail deep in frob's detail.
#include <frob/frob.hpp>

using namespace frob;

Task<Wheels, bool> attempt() { co_return true; }
Task<Wheels> giveUp() { co_return; }

Task<Wheels, bool> guarded() {
  return taskCatch(attempt(), [](const RoboErr&) { return giveUp(); });
}
