// Checked runs (frob run --check): a controller compiled with AddressSanitizer, UBSan and the C++
// library's checks stops at its first mistake, and the trusted side names the student's file and
// line, which the sandboxed host could not symbolize itself. Each submission in checked/ marks the
// line it goes wrong on with "// CHECKED".
#include "frob/run/controller_file.hpp"
#include "frob/run/host.hpp"
#include "frob/run/session.hpp"
#include "frob/worlds/world_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

fs::path submission(const std::string& name) { return fs::path(FROB_CHECKED_SOURCES) / (name + ".cpp"); }

// The number of the line marked "// CHECKED" in `file`.
int markedLine(const fs::path& file) {
  std::ifstream in(file);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.find("// CHECKED") != std::string::npos) return n;
  }
  ADD_FAILURE() << file << " marks no line";
  return 0;
}

Result<CompiledController> compiled(const std::string& name, bool checked) {
  CompilerSetup setup = compilerSetup(checked);
  setup.cacheDir = fs::path(::testing::TempDir()) / "checked_test_cache";
  std::string messages;
  Result<CompiledController> c = compileControllerFile(submission(name), setup, &messages);
  EXPECT_TRUE(c.ok()) << c.error() << messages;
  return c;
}

// What became of `name` in a 4 x 3 m room for at most two simulated seconds.
struct Outcome {
  std::vector<worlds::ControllerFailure> failures;
  std::string output;  // what the host and the report printed
};

Outcome runIn(const std::string& name, bool checked) {
  Outcome o;
  Result<CompiledController> c = compiled(name, checked);
  if (!c) return o;
  HostDef def{.output = [&o](std::string_view text) { o.output.append(text); }, .checked = checked};
  Result<std::shared_ptr<ControllerHost>> host = ControllerHost::start({c.value().module}, {submission(name).string()}, def);
  EXPECT_TRUE(host.ok()) << host.error();
  if (!host) return o;
  const worlds::WorldDef room = *worlds::parseWorld("size = [4.0, 3.0]\nseed = 7\n[[robot]]\nname = \"ada\"\nstart = [1.0, 1.0]\n", "room.toml");
  worlds::Run run(room, {}, host.value()->driver({0}, false));
  while (run.failures().empty() && run.simulation().time() < 2.0) run.step();
  o.failures = run.failures();
  return o;
}

struct Case {
  std::string name;
  std::string what;      // the failure's message, up to " in FUNCTION"
  std::string function;  // the student's function that went wrong
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class Checked : public ::testing::TestWithParam<Case> {};

TEST_P(Checked, StopsAtTheMistakeNamingTheFileAndLine) {
  const Case& c = GetParam();
  const Outcome o = runIn(c.name, true);
  ASSERT_EQ(o.failures.size(), 1u) << o.output;
  EXPECT_DOUBLE_EQ(o.failures[0].time, 0.5);
  // "ada: WHAT in FUNCTION at .../checked/NAME.cpp:LINE[:COLUMN] at t = 0.50 s"
  const std::string& message = o.failures[0].message;
  const std::string head = "ada: " + c.what + " in " + c.function + " at ";
  const std::string place = "checked/" + c.name + ".cpp:" + std::to_string(markedLine(submission(c.name)));
  ASSERT_EQ(message.substr(0, head.size()), head) << message;
  const std::size_t at = message.find(place, head.size());
  ASSERT_NE(at, std::string::npos) << message;
  EXPECT_TRUE(message[at + place.size()] == ':' || message[at + place.size()] == ' ') << message;
  EXPECT_EQ(message.substr(message.size() - 14), " at t = 0.50 s") << message;
  // The report says the same, then the student's frames, innermost first.
  EXPECT_NE(o.output.find("frob --check: " + c.what + " in " + c.function + " at "), std::string::npos) << o.output;
  const std::size_t frame = o.output.find("\n    " + c.function + " at ");
  ASSERT_NE(frame, std::string::npos) << o.output;
  EXPECT_EQ(o.output.find(place + "\n", frame), o.output.find('\n', frame + 1) - place.size()) << o.output;
}

INSTANTIATE_TEST_SUITE_P(
    Sanitizers, Checked,
    ::testing::Values(Case{"out_of_range", "the C++ library's check '__n < this->size()' failed (an index out of range?)", "speedAt(double)"},
                      Case{"use_after_free",
                           "AddressSanitizer: heap-use-after-free, reading 8 bytes (a pointer or reference to something already destroyed?)",
                           "speedAt(double)"},
                      Case{"int_division", "undefined behaviour: division by zero", "stepsPerSecond(int, int)"},
                      Case{"fails_assert", "the assert 'speed > 0' failed", "speedAt(double)"}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

// The same mistakes unchecked go unnoticed: the run drives on (which is why --check exists).
TEST(Checked, UncheckedTheSameMistakesDriveOnSilently) {
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
  GTEST_SKIP() << "a sanitized build compiles every controller with the sanitizers";
#endif
#endif
  for (const char* name : {"out_of_range", "use_after_free"}) {
    const Outcome o = runIn(name, false);
    EXPECT_TRUE(o.failures.empty()) << name << ": " << o.failures[0].message;
  }
}

// A run that looks stuck suggests --check, unless it was checked.
TEST(Checked, ARunThatNeverMovedSuggestsCheckingUnlessItWasChecked) {
  for (const bool checked : {false, true}) {
    Result<CompiledController> c = compiled("stands_still", checked);
    ASSERT_TRUE(c.ok());
    const HostDef host{.checked = checked};
    Result<LoadedController> loaded = describeInHost(c.value(), host);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    RunDef def{.world = *worlds::parseWorld("size = [4.0, 3.0]\n[[robot]]\nname = \"ada\"\nstart = [1.0, 1.0]\n", "room.toml"),
               .worldName = "room",
               .controllers = {loaded.value()},
               .host = host,
               .seconds = 1.0};
    Result<Summary> s = runSession(def);
    ASSERT_TRUE(s.ok()) << s.error();
    const std::vector<std::string>& hints = s.value().robots.at(0).hints;
    const bool suggested = std::any_of(hints.begin(), hints.end(), [](const std::string& h) {
      return h ==
             "ada never moved, and this run was not checked: frob run --check stops at an index out of range, a use after free or an integer "
             "division by zero, naming your file and line";
    });
    EXPECT_EQ(suggested, !checked) << (checked ? "checked" : "unchecked");
  }
}

}  // namespace
}  // namespace frob::course
