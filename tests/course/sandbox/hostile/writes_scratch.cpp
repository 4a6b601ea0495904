// Writes and reads back a file in its working folder (its scratch folder, where that is allowed).
#include "misbehave.hpp"
#include <fstream>
#include <string>
Behavior<Wheels> writesScratch(const Robot&) {
  return toBehavior(lift(
      [](double now) {
        if (now < 0.5) return Wheels{0.1, 0.0};
        std::ofstream("notes.txt") << "0.25";
        std::string text;
        std::ifstream("notes.txt") >> text;
        return Wheels{std::stod(text), 0.0};
      },
      time()));
}
FROB_CONTROLLER(writesScratch)
