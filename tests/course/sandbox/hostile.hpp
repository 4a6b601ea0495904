#pragma once
// Where the tests find the controller modules the build made: the course's examples and the
// hostile submissions of tests/course/sandbox/hostile/.
#include <filesystem>
#include <string>

namespace frob::course::testing {

inline std::filesystem::path exampleModule(const std::string& name) { return std::filesystem::path(FROB_EXAMPLE_MODULES) / (name + ".so"); }
inline std::filesystem::path hostileModule(const std::string& name) { return std::filesystem::path(FROB_HOSTILE_MODULES) / (name + ".so"); }

}  // namespace frob::course::testing
