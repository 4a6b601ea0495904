// Must NOT compile: a Task<double> awaited inside a Task<Wheels>. The first error must say that a
// task awaits only tasks of its own output, not "member reference base type 'void'".
#include <frob/frob.hpp>

using namespace frob;

Task<double> measure() { co_return; }

Task<Wheels> drive() {
  co_await measure();
}
