// Prints what a terminal acts on: clearing the screen (CSI), writing the clipboard (OSC 52), a
// device control string (DCS), CSI as a C1 control in UTF-8, and a bare carriage return that would
// overwrite the line with a forged total; a Latin-1 byte, and a character cut across two writes.
#include "misbehave.hpp"

#include <cstdio>
Behavior<Wheels> printsEscapes(const Robot&) {
  return misbehaveFrom(0.5, [] {
    static bool once = false;
    if (std::exchange(once, true)) return;
    std::printf("\x1b[2J\x1b]52;c;ZXZpbA==\x07\x1bPq#0\x1b\\\xc2\x9b" "31m\rTotal 7 / 7 \xe9\n");
    std::fputs("caf\xc3", stdout);
    std::fflush(stdout);
    std::fputs("\xa9\n", stdout);
    std::fflush(stdout);
  });
}
FROB_CONTROLLER(printsEscapes)
