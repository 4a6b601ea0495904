#pragma once
// What frob grade's command-line tests share: a small assignment, "forward", and controllers for it.
#include "run_frob.hpp"

#include <filesystem>
#include <fstream>
#include <string>

namespace frob::testing {

inline constexpr const char* kRubric = R"(title = "Forward"
seconds = 3
[[check]]
name = "goes forward"
points = 2
worlds = ["room.toml"]
seeds = [1, 2]
goal = { within = 0.4 }
[[check]]
name = "no bumps"
worlds = ["room.toml"]
collisions = { max = 0 }
)";

// Drives forward at `speed`: fast ones reach the goal 1 m ahead in 3 s, slow ones do not.
inline std::string driver(const std::string& speed) {
  return "#include <frob/frob.hpp>\nusing namespace frob;\nBehavior<Wheels> go(const Robot&) { return Wheels{" + speed +
         ", 0.0}; }\nFROB_CONTROLLER(go)\n";
}

// A fresh folder `name` holding the assignment "forward": its rubric and its room.
inline std::filesystem::path assignment(const std::string& name) {
  const std::filesystem::path dir = freshFolder(name);
  std::filesystem::create_directories(dir / "forward");
  std::ofstream(dir / "forward" / "rubric.toml") << kRubric;
  std::ofstream(dir / "forward" / "room.toml") << "size = [4.0, 3.0]\n[points]\ngoal = [2.0, 1.5]\n[[robot]]\nstart = [1.0, 1.5]\n";
  return dir;
}

}  // namespace frob::testing
