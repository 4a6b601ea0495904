// Must NOT compile: comparing a sonar range with a string. ctest checks that the compiler's
// message names the invalid expression rather than drowning the student in template internals.
#include <frob/frob.hpp>

frob::Event<frob::Unit> tooClose(const frob::Robot& r) { return frob::predicate(frob::frontSonar(r) < "x"); }
