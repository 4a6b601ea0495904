#pragma once
// What every hostile submission shares: drive slowly ahead, and misbehave from a given time on.
#include <frob/frob.hpp>

using namespace frob;

// Drives ahead at 10 cm/s and calls `act` at every instant from `from` seconds on.
template <class F>
Behavior<Wheels> misbehaveFrom(double from, F act) {
  return toBehavior(lift(
      [from, act](double now) {
        if (now >= from) act();
        return Wheels{0.1, 0.0};
      },
      time()));
}
