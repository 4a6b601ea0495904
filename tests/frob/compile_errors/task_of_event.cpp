// Must NOT compile: a task whose output is an event. The message must say what a task drives and
// what to write instead, not "implicitly-deleted default constructor of 'AtomicBase<Event<int>>'".
#include <frob/frob.hpp>

using namespace frob;

Task<Event<int>> keys(const Robot& r) {
  return mkTask([r](const TaskState&) { return std::pair{Behavior<Event<int>>(never<int>()), after(1.0)}; });
}
