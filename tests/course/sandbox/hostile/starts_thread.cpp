// Uses a thread of its own to compute its command: allowed (threads are not processes).
#include "misbehave.hpp"
#include <thread>
Behavior<Wheels> startsThread(const Robot&) {
  return toBehavior(lift(
      [](double) {
        double speed = 0;
        std::thread([&speed] { speed = 0.2; }).join();
        return Wheels{speed, 0.0};
      },
      time()));
}
FROB_CONTROLLER(startsThread)
