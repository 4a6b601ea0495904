// Must NOT compile with -Werror=unused-result (as `frob run` compiles controllers): a task called
// without co_await does nothing, and the compiler's message must say so.
#include <frob/frob.hpp>

using namespace frob;

Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) { return std::pair{wheels(0.3, 0), predicate(frontSonar(ts.robot()) < 0.5)}; });
}

Task<Wheels> runAround() {
  for (;;) goAhead();  // should be co_await goAhead();
}
