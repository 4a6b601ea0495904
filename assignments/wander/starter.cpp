// Wander: your starting point (paper section 3.1, runAround).
//
// This is the paper's runAround, nearly word for word: drive ahead slowly until the front sonar
// reads less than 20 cm, turn right until it reads more than 30 cm, for ever. It compiles and runs,
// but it creeps, it never sees what it meets at an angle, and it always turns the same way.
// Make it wander the rooms as the handout asks. Read the handout first, then course/examples/01.
//
// Run it:   build/app/frob run assignments/wander/starter.cpp --frames /tmp/frames --fps 1
// Check it: build/app/frob grade wander assignments/wander/starter.cpp --visible-only --report r.html

#include <frob/frob.hpp>

using namespace frob;
using namespace frob::literals;

// The paper's goAhead: drive ahead at 10 cm/s until the front sonar reads less than 20 cm.
// TODO: a sonar hears a wall only when it faces it nearly head-on: look with more than one.
// TODO: faster; steer away from what passes close beside you (a doorway is narrow).
Task<Wheels> goAhead() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(10_cm, 0), predicate(frontSonar(r) < 20_cm)};
  });
}

// The paper's turnRight: turn on the spot until the front sonar reads more than 30 cm.
// TODO: which way has more room? How far should you turn, so that you do not go round in a loop?
Task<Wheels> turnRight() {
  return mkTask([](const TaskState& ts) {
    const Robot& r = ts.robot();
    return std::pair{wheels(0, -0.5), predicate(frontSonar(r) > 30_cm)};
  });
}

// The paper's runAround: goAhead, then turnRight, for ever.
Task<Wheels> runAround() {
  for (;;) {
    co_await goAhead();
    co_await turnRight();
  }
}

FROB_CONTROLLER(runAround, .world = "assignments/wander/worlds/living_room.toml", .seconds = 120,
                .summary = "wander starter: the paper's runAround, word for word")
