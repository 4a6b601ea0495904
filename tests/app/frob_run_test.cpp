// End to end: ctest runs the built frob. Bad input of every kind exits non-zero with one clear
// message and leaves no output file behind; good runs write whole files and repeat exactly.
#include "run_frob.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace frob::testing {
namespace {

namespace fs = std::filesystem;

// A small controller file: drives forward at `forward` (an expression of the robot `r`) forever.
std::string controller(const std::string& forward, const std::string& extra = "") {
  return "#include <frob/frob.hpp>\nusing namespace frob;\n" + extra + "Behavior<Wheels> drive([[maybe_unused]] const Robot& r) { return wheels(" +
         forward +
         ", 0.0); }\n"
         "FROB_CONTROLLER(drive, .world = \"empty\", .seconds = 3)\n";
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

// The lines of `text` that are not empty.
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string l; std::getline(in, l);) {
    if (!l.empty()) out.push_back(l);
  }
  return out;
}

const std::vector<std::string> kAllOutputs{"--video",  "out.mp4", "--trace", "out.csv",  "--timeline",
                                           "out.json", "--plot",  "out.png", "--frames", "frames"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(FrobRun, GoodControllerWritesEveryOutputWhole) {
  const fs::path dir = freshFolder("good");
  write(dir, "slow.cpp", controller("0.2"));
  const FrobResult r = runFrob(dir, with({"run", "slow.cpp", "--seconds", "2"}, kAllOutputs));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("2.00 s simulated"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("distance 0.3"), std::string::npos) << r.out;  // 0.2 m/s for 2 s, less the acceleration
  EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"frames", "out.csv", "out.json", "out.mp4", "out.png", "slow.cpp"}));
  EXPECT_EQ(lines(readFile(dir / "out.csv")).size(), 1u + 200u);  // header, then 200 steps of one robot
  EXPECT_EQ(filesIn(dir / "frames").size(), 60u);                 // 2 s at 30 fps
}

// --from RUN#t=T, through the sandboxed host: the trace's rows up to T are the earlier run's; the
// controller's clock reads T when it takes over (its task starts there), and its behaviors start
// there (time() is 0: forward 0.1 + time() / 10 is 0.1); the summary says where the run came from.
TEST(FrobRun, AForkTakesOverAtTheInstantWithItsClockThere) {
  const fs::path dir = freshFolder("fork");
  write(dir, "slow.cpp", controller("0.2"));
  write(dir, "clocked.cpp",
        "#include <frob/frob.hpp>\nusing namespace frob;\nTask<Wheels> drive(const Robot&) {\n  return mkTask([](const TaskState&) { "
        "return std::pair{wheels(0.1 + time() / 10.0, 0.0), after(100.0)}; }).named(\"clocked\");\n}\n"
        "FROB_CONTROLLER(drive, .world = \"empty\", .seconds = 3)\n");
  ASSERT_EQ(runFrob(dir, {"run", "slow.cpp", "--seconds", "2", "--trace", "a.csv"}).status, 0);
  const FrobResult r = runFrob(dir, {"run", "clocked.cpp", "--seconds", "2", "--from", "a.csv#t=1.5", "--trace", "b.csv"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("note: the run up to 1.50 s is a.csv's, played back step by step; the controllers took over at 1.50 s"), std::string::npos)
      << r.out;
  const std::vector<std::string> a = lines(readFile(dir / "a.csv")), b = lines(readFile(dir / "b.csv"));
  ASSERT_EQ(b.size(), a.size());
  for (std::size_t k = 1; k <= 150; ++k) EXPECT_EQ(b[k], a[k]) << k;  // rows of 0 to 1.49 s, the header first
  const auto forward = [](const std::string& row) {
    std::stringstream cells(row);
    std::string cell;
    for (int j = 0; j <= 8; ++j) std::getline(cells, cell, ',');
    return std::stod(cell);
  };
  EXPECT_DOUBLE_EQ(forward(b[151]), 0.1) << b[151];
  EXPECT_DOUBLE_EQ(forward(b[161]), 0.1 + 0.1 / 10.0) << b[161];
  const FrobResult json = runFrob(dir, {"run", "clocked.cpp", "--seconds", "2", "--from", "a.csv#t=1.5", "--json"});
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_EQ(nlohmann::json::parse(json.out)["robots"][0]["last_tasks"][0]["start"], 1.5) << json.out;
  EXPECT_EQ(runFrob(dir, {"run", "clocked.cpp", "--seconds", "2", "--from", "a.csv#t=3"}).err,
            "frob: --from: a.csv has its run up to 1.99 s, not to 3.00 s\n");
  EXPECT_EQ(runFrob(dir, {"run", "clocked.cpp", "--seconds", "1", "--from", "a.csv#t=1.5"}).err,
            "frob: --from: the run ends at 1.00 s, before its fork at 1.50 s (--seconds)\n");
}

// A video fits in --video-size (8 MB unless given; 0 for any size): a long run's bitrate is lowered.
TEST(FrobRun, AVideoFitsInItsSize) {
  const fs::path dir = freshFolder("video_size");
  write(dir, "fast.cpp", controller("0.5"));
  const FrobResult capped = runFrob(dir, {"run", "fast.cpp", "--seconds", "8", "--video", "capped.mp4", "--video-size", "0.06"});
  ASSERT_EQ(capped.status, 0) << capped.err;
  const FrobResult free = runFrob(dir, {"run", "fast.cpp", "--seconds", "8", "--video", "free.mp4", "--video-size", "0"});
  ASSERT_EQ(free.status, 0) << free.err;
  EXPECT_LE(fs::file_size(dir / "capped.mp4"), 60'000u);
  EXPECT_GT(fs::file_size(dir / "free.mp4"), 2 * fs::file_size(dir / "capped.mp4"));
}

TEST(FrobRun, WithoutAControllerTheDemoWritesAVideo) {
  const fs::path dir = freshFolder("demo");
  const FrobResult r = runFrob(dir, {"run", "--seconds", "2"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("bug: bugToGoal (" FROB_EXAMPLES_DIR "/06_bug.cpp)"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("frob: now watch bug.mp4"), std::string::npos) << r.err;
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"bug.mp4"});
}

// The README's five-minute tutorial, as a newcomer copies it: it compiles, runs, and wanders
// the room for its minute without touching a wall.
TEST(FrobRun, TheReadmeTutorialWorks) {
  const std::string readme = readFile(FROB_SOURCE_DIR "/README.md");
  const std::size_t intro = readme.find("Save this as `wander.cpp`");
  ASSERT_NE(intro, std::string::npos);
  const std::size_t from = readme.find("```cpp\n", intro) + 7, to = readme.find("```", from);
  const fs::path dir = freshFolder("readme");
  write(dir, "wander.cpp", readme.substr(from, to - from));
  const FrobResult r = runFrob(dir, {"run", "wander.cpp", "--quiet"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("60.00 s simulated"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("collisions 0"), std::string::npos) << r.out;
}

// A controller's world is found beside it, then among the reference worlds, in the working folder
// and in the course: a starter copied to a folder of one's own runs in its assignment's world, and
// a world file beside a controller is found from any working folder.
TEST(FrobRun, AControllersWorldIsFoundBesideItOrInTheCourse) {
  const fs::path dir = freshFolder("world_beside");
  fs::create_directories(dir / "mine");
  fs::copy_file(FROB_SOURCE_DIR "/assignments/go_to_goal/starter.cpp", dir / "mine" / "starter.cpp");
  const FrobResult starter = runFrob(dir / "mine", {"run", "starter.cpp", "--seconds", "1", "--quiet"});
  ASSERT_EQ(starter.status, 0) << starter.err;
  EXPECT_NE(starter.out.find("assignments/go_to_goal/worlds/lounge.toml"), std::string::npos) << starter.out;
  std::ofstream(dir / "mine" / "box.toml") << "size = [4.0, 4.0]\n[[robot]]\nname = \"boxed\"\nstart = [2.0, 2.0]\n";
  std::string beside = controller("0.1");
  beside.replace(beside.find("\"empty\""), 7, "\"box.toml\"");
  write(dir / "mine", "boxed.cpp", beside);
  const FrobResult r = runFrob(dir, {"run", "mine/boxed.cpp", "--quiet"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("mine/box.toml"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("boxed"), std::string::npos) << r.out;
}

TEST(FrobRun, SameSeedSameTrace) {
  const fs::path dir = freshFolder("same_seed");
  write(dir, "slow.cpp", controller("0.2"));
  ASSERT_EQ(runFrob(dir, {"run", "slow.cpp", "--world", "maze", "--seed", "7", "--trace", "a.csv"}).status, 0);
  ASSERT_EQ(runFrob(dir, {"run", "slow.cpp", "--world", "maze", "--seed", "7", "--trace", "b.csv"}).status, 0);
  ASSERT_EQ(runFrob(dir, {"run", "slow.cpp", "--world", "maze", "--seed", "8", "--trace", "c.csv"}).status, 0);
  EXPECT_EQ(readFile(dir / "a.csv"), readFile(dir / "b.csv"));
  EXPECT_NE(readFile(dir / "a.csv"), readFile(dir / "c.csv"));  // sonar noise follows the seed
}

TEST(FrobRun, SecondRunUsesTheCompiledController) {
  const fs::path dir = freshFolder("cache");
  write(dir, "cached.cpp", controller("0.1", "// cache test " + std::to_string(::getpid()) + "\n"));
  const FrobResult first = runFrob(dir, {"run", "cached.cpp"});
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.err.find("compiled cached.cpp"), std::string::npos) << first.err;
  const FrobResult second = runFrob(dir, {"run", "cached.cpp"});
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_EQ(second.err.find("compiled"), std::string::npos) << second.err;
}

TEST(FrobRun, ExampleFileCompilesLikeAStudentFile) {
  const fs::path dir = freshFolder("example_file");
  const FrobResult r = runFrob(dir, {"run", FROB_EXAMPLES_DIR "/01_run_around.cpp", "--seconds", "1"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;  // examples are clean under the students' flags
  EXPECT_NE(r.out.find("runAround (" FROB_EXAMPLES_DIR "/01_run_around.cpp)"), std::string::npos) << r.out;
}

TEST(FrobRun, CompileErrorShowsTheCompilerThenOneLine) {
  const fs::path dir = freshFolder("compile_error");
  write(dir, "broken.cpp", controller("frontSonar(r) < \"x\""));
  const FrobResult r = runFrob(dir, with({"run", "broken.cpp"}, kAllOutputs));
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(r.err.rfind("broken.cpp:3:", 0), 0u) << r.err;  // the compiler's own message, naming the file as typed
  EXPECT_EQ(lines(r.err).back(), "frob: could not compile 'broken.cpp' (the compiler's messages are above)");
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"broken.cpp"});
}

// Each way a controller misbehaves: exit 1, one line on stderr, no output files at all; returns the line.
std::string expectCleanFailure(const std::string& name, const std::string& file, const std::string& message) {
  const fs::path dir = freshFolder(name);
  write(dir, name + ".cpp", file);
  const FrobResult r = runFrob(dir, with({"run", name + ".cpp", "--quiet"}, kAllOutputs));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no output files were written"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{name + ".cpp"});
  return r.err;
}

TEST(FrobRun, ControllerThatThrows) {
  expectCleanFailure("throws",
                     controller("lift([](double d) -> double { if (d < 5.0) throw std::runtime_error(\"too close\"); return d; }, frontSonar(r))",
                                "#include <stdexcept>\n"),
                     "too close");
}

TEST(FrobRun, ControllerThatGivesNaN) {
  // NaN from t = 1.01 s: the message says how to keep the run up to then.
  const std::string err = expectCleanFailure(
      "nan", controller("lift([](double t) { return t > 1.0 ? std::nan(\"\") : 0.1; }, time())", "#include <cmath>\n"), "non-finite wheels");
  EXPECT_NE(err.find("at t = 1.010 s; no output files were written (--seconds 1.00 keeps the run up to the failure)"), std::string::npos) << err;
}

TEST(FrobRun, AControllerThatCrashesIsOneLineAndFrobLivesOn) {
  const std::string err =
      expectCleanFailure("crash", controller("lift([](double t) { if (t > 0.5) *static_cast<volatile int*>(nullptr) = 1; return 0.1; }, time())"),
                         "frob: the controller failed: nomad: crashed with SIGSEGV (a bad pointer, or an index out of range?) at t = 0.51 s;");
  EXPECT_EQ(err.rfind("frob: ", 0), 0u);
}

TEST(FrobRun, AControllerThatLoopsForeverIsStopped) {
  expectCleanFailure("loops", controller("lift([](double t) { volatile bool stuck = t > 0.5; while (stuck) {} return 0.1; }, time())"),
                     "nomad: used more than 1 s of CPU in one step (an endless loop?) at t = 0.51 s;");
}

// --check: the same vector read past its end drives on unchecked, and stops checked with the
// student's file, function and line on one line, with the stack above it.
TEST(FrobRun, CheckStopsAtAnIndexOutOfRangeNamingTheLine) {
  const std::string file = controller("lift([](double t) { return speeds[t < 0.5 ? 0 : 3]; }, time())",
                                      "#include <vector>\nconst std::vector<double> speeds{0.1, 0.1, 0.1};\n");
  const fs::path dir = freshFolder("check");
  write(dir, "reads_past.cpp", file);
#if defined(__has_feature)
#if !__has_feature(address_sanitizer)  // a sanitized build compiles every controller with the sanitizers
  EXPECT_EQ(runFrob(dir, {"run", "reads_past.cpp", "--quiet", "--seconds", "1"}).status, 0);
#endif
#endif
  const FrobResult r = runFrob(dir, {"run", "reads_past.cpp", "--check", "--quiet", "--seconds", "1"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(lines(r.err).back(),
            "frob: the controller failed: nomad: the C++ library's check '__n < this->size()' failed (an index out of range?) in "
            "drive(frob::Robot const&)'s lambda at reads_past.cpp:5 at t = 0.50 s; no output files were written")
      << r.err;
  EXPECT_NE(r.err.find("\n    drive(frob::Robot const&)'s lambda at reads_past.cpp:5\n"), std::string::npos) << r.err;
}

TEST(FrobRun, CheckNeedsTheSandboxAndASourceFile) {
  const fs::path dir = freshFolder("check_refused");
  write(dir, "go.cpp", controller("0.1"));
  FrobResult r = runFrob(dir, {"run", "go.cpp", "--check", "--no-sandbox"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "frob: --check runs the controllers in their sandboxed process: leave out --no-sandbox\n");
  r = runFrob(dir, {"run", "go.so", "--check"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "frob: --check compiles the controller with its checks: give its .cpp, not go.so\n");
}

TEST(FrobRun, SandboxedAndInProcessRunsDriveTheSameTrajectory) {
  const fs::path dir = freshFolder("sandboxed_same");
  write(dir, "slow.cpp", controller("0.2"));
  const FrobResult sandboxed = runFrob(dir, {"run", "slow.cpp", "--seconds", "3", "--json", "--quiet"});
  const FrobResult here = runFrob(dir, {"run", "slow.cpp", "--seconds", "3", "--json", "--quiet", "--no-sandbox"});
  ASSERT_EQ(sandboxed.status, 0) << sandboxed.err;
  ASSERT_EQ(here.status, 0) << here.err;
  const nlohmann::json a = nlohmann::json::parse(sandboxed.out), b = nlohmann::json::parse(here.out);
  EXPECT_EQ(a["trajectory_hash"], b["trajectory_hash"]);
  EXPECT_EQ(a["steps"], 300);
  // The sandbox's layers are in the summary; none is there when the controller ran in frob itself.
  std::vector<std::string> layers;
  for (const auto& l : a["sandbox"]) layers.push_back(l["layer"]);
  EXPECT_EQ(layers, (std::vector<std::string>{"resource limits", "unprivileged user", "namespaces", "no new privileges", "landlock", "seccomp"}));
  EXPECT_TRUE(b["sandbox"].empty());
}

TEST(FrobRun, FileWithoutControllerLine) {
  const fs::path dir = freshFolder("no_entry");
  write(dir, "none.cpp", "#include <frob/frob.hpp>\nint helper() { return 1; }\n");
  const FrobResult r = runFrob(dir, {"run", "none.cpp", "--quiet"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(lines(r.err).back(), "frob: 'none.cpp' names no controller: end it with a line FROB_CONTROLLER(yourFunction)");
}

TEST(FrobRun, UndefinedFunctionIsNamed) {
  const fs::path dir = freshFolder("undefined");
  write(dir, "undef.cpp",
        "#include <frob/frob.hpp>\nusing namespace frob;\nTask<Wheels> wander(double speed);\n"
        "Task<Wheels> start() { return wander(0.2); }\nFROB_CONTROLLER(start)\n");
  const FrobResult r = runFrob(dir, {"run", "undef.cpp", "--quiet"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("undefined symbol: wander(double) (declared but never defined?)"), std::string::npos) << r.err;
}

TEST(FrobRun, BadNamesAndPaths) {
  const fs::path dir = freshFolder("bad_input");
  write(dir, "slow.cpp", controller("0.1"));
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases{
      {{"run", "slow.cpp", "--world", "atlantis"}, "frob: unknown world 'atlantis': not a reference world (see frob list) and no such file"},
      {{"run", "nosuch"}, "frob: unknown controller 'nosuch': not a file and not an example (see frob list)"},
      {{"run", "missing.cpp"}, "frob: controller file 'missing.cpp' cannot be read: it does not exist"},
      {{"run", "slow.cpp", "--video", "no/such/dir/out.mp4"},
       "frob: video: cannot write 'no/such/dir/out.mp4': directory 'no/such/dir' does not exist"},
      {{"run", "slow.cpp", "--trace", "slow.cpp/x.csv"}, "frob: trace: cannot write 'slow.cpp/x.csv': 'slow.cpp' is not a directory"},
      {{"run", "slow.cpp", "slow.cpp", "--world", "empty"},
       "frob: the world 'empty' has 1 robots: give one controller for all of them or one per robot (2 given)"},
      {{"run", "slow.cpp", "--size", "big"}, "frob: --size must look like 854x480, not 'big'"},
  };
  for (const Case& c : cases) {
    const FrobResult r = runFrob(dir, with(c.args, {"--quiet"}));
    EXPECT_EQ(r.status, 1) << c.message;
    EXPECT_EQ(lines(r.err), std::vector<std::string>{c.message});
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"slow.cpp"});
  }
}

TEST(FrobRun, MalformedWorldFileNamesFileLineAndField) {
  const fs::path dir = freshFolder("bad_world");
  write(dir, "slow.cpp", controller("0.1"));
  write(dir, "w.toml", "size = [5.0, 5.0]\n[[wall]]\nfrom = [1.0]\nto = [2.0, 2.0]\n[[robot]]\nstart = [1.0, 1.0]\n");
  const FrobResult r = runFrob(dir, {"run", "slow.cpp", "--world", "w.toml", "--quiet"});
  EXPECT_EQ(r.status, 1);
  ASSERT_EQ(lines(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("w.toml:3: wall[0].from"), std::string::npos) << r.err;
}

TEST(FrobRun, AWorldWithNoRobotIsRefused) {
  const fs::path dir = freshFolder("no_robot");
  write(dir, "slow.cpp", controller("0.1"));
  write(dir, "w.toml", "size = [5.0, 5.0]\n");
  const FrobResult r = runFrob(dir, {"run", "slow.cpp", "--world", "w.toml", "--quiet"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(lines(r.err), std::vector<std::string>{"frob: w.toml: the world has no robot to drive: add one, e.g. a [[robot]] table "
                                                   "with start = [1, 1] (the world format: worlds/data/README.md)"});
}

// A student who guesses at a world file is told its format and where it is described.
TEST(FrobRun, HelpSaysWhereTheWorldFormatIs) {
  for (const char* command : {"run", "render"}) {
    const FrobResult r = runFrob(freshFolder("help"), {command, "--help"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("a world file: TOML, its format in worlds/data/README.md"), std::string::npos) << command << ":\n" << r.out;
  }
}

TEST(FrobRender, WritesAPictureOfTheWorld) {
  const fs::path dir = freshFolder("render");
  const FrobResult r = runFrob(dir, {"render", "maze", "--out", "maze.png", "--size", "320x240"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"maze.png"});
  EXPECT_EQ(readFile(dir / "maze.png").substr(1, 3), "PNG");
}

TEST(FrobList, NamesTheWorlds) {
  const FrobResult r = runFrob(freshFolder("list"), {"list"});
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* world : {"empty", "corridor", "maze", "office", "obstacles", "mesh", "arena"}) {
    EXPECT_NE(r.out.find(std::string("  ") + world + " "), std::string::npos) << world;
  }
}

}  // namespace
}  // namespace frob::testing
