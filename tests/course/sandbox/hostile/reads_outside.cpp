// Reads /etc/passwd and prints it half a second into the run.
#include "misbehave.hpp"
#include <fstream>
#include <iostream>
Behavior<Wheels> readsOutside(const Robot&) {
  return misbehaveFrom(0.5, [] {
    std::ifstream in("/etc/passwd");
    std::cout << in.rdbuf();
  });
}
FROB_CONTROLLER(readsOutside)
