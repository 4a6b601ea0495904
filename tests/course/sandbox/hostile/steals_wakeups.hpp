#pragma once
// Takes the grader's wake-ups: half a second into the run, makes the wake-up channel it shares with
// the grader (fd 4) blocking with `makeBlocking`, says whether it can read back a wake-up it rang
// (one meant for the grader), then one thread of its own rings the channel many times over while
// another reads every wake-up it can, and the step itself never answers. Were the grader's end of
// that channel the host's too, the grader could lose a race for a wake-up it was told of and block
// in a read of it where no deadline applies.
#include "misbehave.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <thread>

template <class F>
Behavior<Wheels> stealsWakeups(F makeBlocking) {
  return misbehaveFrom(0.5, [makeBlocking] {
    makeBlocking(4);
    std::uint64_t n = 1;
    if (::write(4, &n, sizeof n) == sizeof n && ::read(4, &n, sizeof n) == sizeof n) std::printf("took a wake-up meant for the grader\n");
    std::thread([] {
      for (std::uint64_t m;;) (void)::read(4, &m, sizeof m);
    }).detach();
    std::thread([] {
      for (int i = 0; i < 300000; ++i) {
        const std::uint64_t m = 1;
        (void)::write(4, &m, sizeof m);
      }
    }).detach();
    ::sleep(60);
  });
}
