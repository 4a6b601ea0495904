// Compiling a controller file: in a sandbox that lets the compiler read the system's headers, frob's
// and copies of the submission's files, and nothing else, within limits of time and memory, as a user
// of its own when frob is root.
#include "frob/run/controller_file.hpp"

#include "frob/run/host.hpp"
#include "sandbox_user.hpp"
#include "sandboxed.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the test's temp folder.
fs::path freshFolder(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "controller_file_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void writeFile(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

CompilerSetup setupIn(const fs::path& dir) {
  CompilerSetup s = compilerSetup();
  s.cacheDir = dir / "cache";
  return s;
}

constexpr const char* kController = R"(#include <frob/frob.hpp>
#include "speed.hpp"
frob::Behavior<frob::Wheels> go(const frob::Robot&) { return frob::Wheels{kSpeed, 0.0}; }
FROB_CONTROLLER(go)
)";

// Two controllers whose texts share a 64-bit FNV-1a hash (0xcba683c9e46f4199).
constexpr const char* kCollidingDrives =
    "#include <frob/frob.hpp>\nfrob::Behavior<frob::Wheels> go(const frob::Robot&) { return frob::Wheels{0.3, 0.0}; "
    "}\nFROB_CONTROLLER(go)\n//24Rt802QksB";
constexpr const char* kCollidingStandsStill =
    "#include <frob/frob.hpp>\nfrob::Behavior<frob::Wheels> go(const frob::Robot&) { return frob::Wheels{0.0, 0.0}; "
    "}\nFROB_CONTROLLER(go)\n//sJ$ku$W4zIG";

TEST(ControllerFile, CompilesWithHeadersFromItsOwnFolderAndCachesTheModule) {
  const fs::path dir = freshFolder("own_folder");
  writeFile(dir / "go.cpp", kController);
  writeFile(dir / "speed.hpp", "constexpr double kSpeed = 0.3;\n");
  std::string messages;
  Result<CompiledController> c = compileControllerFile(dir / "go.cpp", setupIn(dir), &messages);
  ASSERT_TRUE(c.ok()) << c.error() << messages;
  EXPECT_TRUE(c.value().compiled);
  EXPECT_TRUE(fs::exists(c.value().module));
  Result<CompiledController> again = compileControllerFile(dir / "go.cpp", setupIn(dir));
  ASSERT_TRUE(again.ok());
  EXPECT_FALSE(again.value().compiled);
  EXPECT_EQ(again.value().module, c.value().module);
  // Nothing but the module is left in the cache: the build folder is gone.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "cache"), fs::directory_iterator()), 1);
}

// The dynamic symbols of `module` that it defines (`defined`) or needs from its host, demangled.
std::string dynamicSymbols(const fs::path& module, bool defined) {
  const std::string command = std::string("nm -D -C ") + (defined ? "--defined-only " : "--undefined-only ") + module.string();
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), &::pclose);
  std::string out;
  for (char buffer[4096]; pipe && std::fgets(buffer, sizeof buffer, pipe.get()) != nullptr;) out += buffer;
  return out;
}

// Issue 29: a controller compiles only its own code; the task machinery of Task<Wheels> and the
// operators on numbers were compiled once, with the precompiled header (-fpch-codegen), into the
// host that loads it.
TEST(ControllerFile, AControllerCompilesOnlyItsOwnCodeAndTakesTheRestFromItsHost) {
  const fs::path dir = freshFolder("precompiled");
  writeFile(dir / "go.cpp", R"(#include <frob/frob.hpp>
using namespace frob;
Task<Wheels> go() {
  co_await mkTask([](const TaskState& ts) { return std::pair{wheels(sonar(ts.robot(), 0) * 0.5, 0.0), after(1.0)}; });
}
FROB_CONTROLLER(go)
)");
  Result<CompiledController> c = compileControllerFile(dir / "go.cpp", setupIn(dir));
  ASSERT_TRUE(c.ok()) << c.error();
  const std::string needs = dynamicSymbols(c.value().module, false), has = dynamicSymbols(c.value().module, true);
  ASSERT_NE(has.find("frob_controller_v1"), std::string::npos) << has;
  EXPECT_NE(needs.find("frob::detail::TaskPromise<frob::Wheels, void>::final_suspend()"), std::string::npos) << needs;
  EXPECT_NE(needs.find("frob::makeController<frob::Task<frob::Wheels, void> (*)()>"), std::string::npos) << needs;
  EXPECT_EQ(has.find("TaskPromise"), std::string::npos) << has;
  // A sonar reading times a number: an operator precompiled once, taken from the host.
  EXPECT_NE(needs.find("frob::operator*<frob::Pointwise<double"), std::string::npos) << needs;
  EXPECT_EQ(has.find("operator*"), std::string::npos) << has;
  EXPECT_EQ(has.find("PointwiseNode"), std::string::npos) << has;
}

// A cached run shows the compiler's warnings again: a student who reruns still sees them.
TEST(ControllerFile, ACachedModuleShowsItsWarningsAgain) {
  const fs::path dir = freshFolder("warnings");
  writeFile(dir / "go.cpp", R"(#include <frob/frob.hpp>
frob::Behavior<frob::Wheels> go(const frob::Robot&) { int unused = 3; return frob::Wheels{0.1, 0.0}; }
FROB_CONTROLLER(go)
)");
  std::string first, second;
  Result<CompiledController> c = compileControllerFile(dir / "go.cpp", setupIn(dir), &first);
  ASSERT_TRUE(c.ok()) << c.error() << first;
  EXPECT_NE(first.find("go.cpp:2:59: warning: unused variable 'unused'"), std::string::npos) << first;
  Result<CompiledController> again = compileControllerFile(dir / "go.cpp", setupIn(dir), &second);
  ASSERT_TRUE(again.ok());
  EXPECT_FALSE(again.value().compiled);
  EXPECT_EQ(second, first);
}

TEST(ControllerFile, AnIncludeOutsideItsFolderCannotBeReadAndNoLineOfItIsShown) {
  const fs::path dir = freshFolder("secret");
  fs::create_directories(dir / "submission");
  writeFile(dir / "instructor_key.txt", "int answer = 42; // THE-SECRET-SOLUTION\n");
  writeFile(dir / "submission" / "steal.cpp", "#include \"" + (dir / "instructor_key.txt").string() + "\"\n");
  std::string messages;
  Result<CompiledController> c = compileControllerFile(dir / "submission" / "steal.cpp", setupIn(dir), &messages);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error(), "could not compile '" + (dir / "submission" / "steal.cpp").string() + "' (the compiler's messages follow)");
  EXPECT_NE(messages.find("cannot open file '" + (dir / "instructor_key.txt").string() + "': Permission denied"), std::string::npos) << messages;
  EXPECT_EQ(messages.find("THE-SECRET-SOLUTION"), std::string::npos) << messages;
  EXPECT_EQ(messages.find("answer"), std::string::npos) << messages;
}

// A class graded as one folder: each submission compiles alone with the headers beside it, and
// cannot read a classmate's file that stood there, by #include or by .incbin.
TEST(ControllerFile, ASubmissionCompilesAloneAndCannotReadAClassmatesFile) {
  const fs::path dir = freshFolder("class");
  writeFile(dir / "alice.cpp", std::string(kController) + "// ALICE-WAS-HERE\n");
  writeFile(dir / "speed.hpp", "constexpr double kSpeed = 0.3;\n");
  writeFile(dir / "mallory.cpp", "#include \"alice.cpp\"\n");
  writeFile(dir / "eve.cpp", "asm(\".incbin \\\"" + (dir / "alice.cpp").string() + "\\\"\");\n" + kController);
  std::string messages;
  ASSERT_TRUE(compileSubmission(dir / "alice.cpp", setupIn(dir), &messages).ok()) << messages;
  Result<CompiledController> mallory = compileSubmission(dir / "mallory.cpp", setupIn(dir), &messages);
  ASSERT_FALSE(mallory.ok());
  EXPECT_EQ(mallory.error(), "could not compile '" + (dir / "mallory.cpp").string() + "' (the compiler's messages follow)");
  EXPECT_NE(messages.find("mallory.cpp:1:10: fatal error: 'alice.cpp' file not found"), std::string::npos) << messages;
  Result<CompiledController> eve = compileSubmission(dir / "eve.cpp", setupIn(dir), &messages);
  ASSERT_FALSE(eve.ok());
  EXPECT_NE(messages.find("error: Could not find incbin file '" + (dir / "alice.cpp").string() + "'"), std::string::npos) << messages;
  EXPECT_EQ(messages.find("ALICE-WAS-HERE"), std::string::npos) << messages;
  // Nothing is left of the folders the submissions were copied to.
  for (const fs::directory_entry& e : fs::directory_iterator(dir / "cache"))
    EXPECT_EQ(e.path().filename().string().find("submission-"), std::string::npos);
}

constexpr const char* kUsesHelper = R"(#include <frob/frob.hpp>
double speed();
frob::Behavior<frob::Wheels> go(const frob::Robot&) { return frob::Wheels{speed(), 0.0}; }
FROB_CONTROLLER(go)
)";
constexpr const char* kHelper = "#include \"speed.hpp\"\ndouble speed() { return kSpeed; }\n";

// A student's helpers: the .cpp files beside a controller that hold no controller compile with it
// (else loading fails on speed()'s undefined symbol), and a change to one of them, or to a header
// beside it, compiles anew. Another controller beside it is not compiled in (it would clash).
TEST(ControllerFile, HelpersBesideItCompileWithItAndChangesToThemCompileAnew) {
  const fs::path dir = freshFolder("helpers");
  writeFile(dir / "go.cpp", kUsesHelper);
  writeFile(dir / "helpers.cpp", kHelper);
  writeFile(dir / "speed.hpp", "constexpr double kSpeed = 0.3;\n");
  writeFile(dir / "other.cpp", "  FROB_CONTROLLER (go)\n");
  EXPECT_EQ(companionsOf(dir / "go.cpp"), std::vector<fs::path>{dir / "helpers.cpp"});
  std::string messages;
  Result<CompiledController> c = compileControllerFile(dir / "go.cpp", setupIn(dir), &messages);
  ASSERT_TRUE(c.ok()) << c.error() << messages;
  Result<LoadedController> loaded = describeInHost(c.value());
  EXPECT_TRUE(loaded.ok()) << loaded.error();
  writeFile(dir / "speed.hpp", "constexpr double kSpeed = 0.4;\n");
  Result<CompiledController> header = compileControllerFile(dir / "go.cpp", setupIn(dir));
  ASSERT_TRUE(header.ok());
  EXPECT_TRUE(header.value().compiled);
  writeFile(dir / "helpers.cpp", std::string(kHelper) + "// changed\n");
  Result<CompiledController> helper = compileControllerFile(dir / "go.cpp", setupIn(dir));
  ASSERT_TRUE(helper.ok());
  EXPECT_TRUE(helper.value().compiled);
  EXPECT_NE(helper.value().module, header.value().module);
}

// A submission of several files is a folder: its one controller compiles with the rest. A .cpp
// file submitted alone compiles alone, whatever lies beside it (a classmate's file, in a class).
TEST(ControllerFile, ASubmissionFolderCompilesItsOneControllerWithTheRest) {
  const fs::path dir = freshFolder("submission_folder");
  fs::create_directories(dir / "bob");
  writeFile(dir / "bob" / "go.cpp", kUsesHelper);
  writeFile(dir / "bob" / "helpers.cpp", kHelper);
  writeFile(dir / "bob" / "speed.hpp", "constexpr double kSpeed = 0.3;\n");
  std::string messages;
  Result<CompiledController> folder = compileSubmission(dir / "bob", setupIn(dir), &messages);
  ASSERT_TRUE(folder.ok()) << folder.error() << messages;
  EXPECT_EQ(folder.value().source, (dir / "bob").string());
  Result<LoadedController> both = describeInHost(folder.value());
  EXPECT_TRUE(both.ok()) << both.error();
  Result<CompiledController> alone = compileSubmission(dir / "bob" / "go.cpp", setupIn(dir), &messages);
  ASSERT_TRUE(alone.ok()) << alone.error() << messages;
  Result<LoadedController> loaded = describeInHost(alone.value());
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().find("undefined symbol: speed()"), std::string::npos) << loaded.error();

  writeFile(dir / "bob" / "again.cpp", kUsesHelper);
  EXPECT_EQ(compileSubmission(dir / "bob", setupIn(dir)).error(),
            "2 .cpp files of '" + (dir / "bob").string() + "' have a FROB_CONTROLLER(...) line: a submission holds one controller");
  fs::remove(dir / "bob" / "again.cpp");
  fs::remove(dir / "bob" / "go.cpp");
  EXPECT_EQ(compileSubmission(dir / "bob", setupIn(dir)).error(),
            "none of the .cpp files of '" + (dir / "bob").string() + "' has a FROB_CONTROLLER(...) line: submit the file that holds your controller");
}

// A compiled controller past the size kept in the cache fails to compile, saying why.
TEST(ControllerFile, AHugeModuleIsRefused) {
  const fs::path dir = freshFolder("huge");
  writeFile(
      dir / "huge.cpp",
      std::string("extern \"C\" const char huge[80 << 20] = {1};\n") +
          "#include <frob/frob.hpp>\nfrob::Behavior<frob::Wheels> go(const frob::Robot&) { return frob::Wheels{0.1, 0.0}; }\nFROB_CONTROLLER(go)\n");
  Result<CompiledController> c = compileControllerFile(dir / "huge.cpp", setupIn(dir));
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error(), "could not compile '" + (dir / "huge.cpp").string() +
                           "': the compiled controller is 80 MB, more than the 64 MB allowed (a huge array, or a file pulled in with .incbin?)");
}

// A compile that runs into the compiler's limit of file size fails on the submission's account
// with that reason, though the signal reached clang's own process, which then reported a crash
// (its reproducer included): never "the compiler crashed", which gives no grade.
TEST(ControllerFile, AnObjectPastTheFileLimitIsTheSubmissionsFailure) {
  const fs::path dir = freshFolder("file_limit");
  writeFile(
      dir / "big.cpp",
      std::string("asm(\".section .data\\n.zero 20000000\\n.text\");\n") +
          "#include <frob/frob.hpp>\nfrob::Behavior<frob::Wheels> go(const frob::Robot&) { return frob::Wheels{0.1, 0.0}; }\nFROB_CONTROLLER(go)\n");
  CompilerSetup setup = setupIn(dir);
  setup.fileBytes = 8 << 20;
  std::string messages;
  const Result<CompiledController> c = compileControllerFile(dir / "big.cpp", setup, &messages);
  ASSERT_FALSE(c.ok());
  EXPECT_FALSE(isGraderFailure(c.status())) << c.error() << messages.substr(0, 400);
  EXPECT_EQ(c.error(),
            "could not compile '" + (dir / "big.cpp").string() + "' within the compiler's limits of time, memory and file size (8 MB a file)");
  // The limit's words in an ordinary error (a line of the source quoted) are no limit.
  writeFile(dir / "says.cpp", "const char* why = \"File size limit exceeded\"; int x = why;\n");
  const Result<CompiledController> says = compileControllerFile(dir / "says.cpp", setup, &messages);
  ASSERT_FALSE(says.ok());
  EXPECT_EQ(says.error(), "could not compile '" + (dir / "says.cpp").string() + "' (the compiler's messages follow)");
}

// The compiler reads copies of the files it compiles, not the folder they are in: a file beside a
// controller that is not one of them (notes, a key, a classmate's work) is not there to pull in.
TEST(ControllerFile, TheCompilerReadsCopiesOfTheControllersFilesNotItsFolder) {
  const fs::path dir = freshFolder("copies");
  writeFile(dir / "notes.txt", "NOTES-NOT-COMPILED\n");
  writeFile(dir / "go.cpp", std::string("asm(\".incbin \\\"notes.txt\\\"\");\n") + kController);
  writeFile(dir / "speed.hpp", "constexpr double kSpeed = 0.3;\n");
  std::string messages;
  ASSERT_FALSE(compileControllerFile(dir / "go.cpp", setupIn(dir), &messages).ok());
  EXPECT_NE(messages.find("error: Could not find incbin file 'notes.txt'"), std::string::npos) << messages;
  EXPECT_EQ(messages.find("NOTES-NOT-COMPILED"), std::string::npos) << messages;
  // Its messages name the files as they were given, never the copies.
  writeFile(dir / "go.cpp", std::string(kController) + "int f() { return undeclared; }\n");
  writeFile(dir / "speed.hpp", "constexpr double kSpeed = 0.3;\nint g() { return alsoUndeclared; }\n");
  ASSERT_FALSE(compileControllerFile(dir / "go.cpp", setupIn(dir), &messages).ok());
  EXPECT_NE(messages.find((dir / "go.cpp").string() + ":5:18: error: use of undeclared identifier 'undeclared'"), std::string::npos) << messages;
  EXPECT_NE(messages.find("In file included from " + (dir / "go.cpp").string() + ":2:\n" + (dir / "speed.hpp").string() + ":2:18: error"),
            std::string::npos)
      << messages;
  EXPECT_EQ(messages.find("frob-compile-"), std::string::npos) << messages;
}

// What the compiler ran as: a shell in its place prints its user and group ids.
std::string compilerIds(CompilerSetup setup) {
  const fs::path dir = freshFolder("ids");
  writeFile(dir / "go.cpp", kController);
  setup.compiler = "/bin/sh";
  setup.flags = {"-c", "echo ids $(id -u) $(id -g); exit 1"};
  setup.precompiledHeader.clear();
  std::string messages;
  EXPECT_FALSE(compileControllerFile(dir / "go.cpp", setup, &messages).ok());
  const std::size_t at = messages.find("ids ");
  return at == std::string::npos ? messages : messages.substr(at + 4, messages.find('\n', at) - at - 4);
}

// Issue 48: where frob runs as root the compiler does not: it runs as a user of its own, held by no
// other sandboxed program at the same time (here, one this test holds).
TEST(ControllerFile, TheCompilerRunsAsAUserOfItsOwnWhenFrobIsRoot) {
  const fs::path dir = freshFolder("user");
  if (::geteuid() != 0) {
    EXPECT_EQ(compilerIds(setupIn(dir)), std::to_string(::getuid()) + " " + std::to_string(::getgid()));
    return;
  }
  Result<SandboxUser> held = SandboxUser::take();
  ASSERT_TRUE(held.ok()) << held.error();
  const std::string ids = compilerIds(setupIn(dir));
  const std::uint32_t uid = static_cast<std::uint32_t>(std::atol(ids.c_str()));
  EXPECT_GE(uid, kFirstSandboxUid) << ids;
  EXPECT_LT(uid, kEndSandboxUid) << ids;
  EXPECT_NE(uid, held.value().uid());
  EXPECT_EQ(ids, std::to_string(uid) + " " + std::to_string(uid));
}

// Where frob's own files are in a folder only root may enter (a build in root's home), that user
// could not read them: the compiler stays root rather than fail every student, and frob says so.
TEST(ControllerFile, FrobsFilesWhereOnlyRootMayGoKeepTheCompilerRoot) {
  if (::geteuid() != 0) GTEST_SKIP() << "only root changes the compiler's user";
  const fs::path dir = freshFolder("private");
  fs::create_directories(dir / "private" / "include");
  fs::permissions(dir / "private", fs::perms::owner_all);
  CompilerSetup setup = setupIn(dir);
  setup.reads.push_back((dir / "private" / "include").string());
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(compilerIds(setup), "0 0");
  const std::string warned = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(warned.find("frob: warning: the compiler runs as root here: uid "), std::string::npos) << warned;
  EXPECT_NE(warned.find((dir / "private" / "include").string() + ": Permission denied"), std::string::npos) << warned;
}

TEST(ControllerFile, AFileOfTheSystemOutsideTheHeadersCannotBeIncluded) {
  const fs::path dir = freshFolder("passwd");
  writeFile(dir / "passwd.cpp", "#include \"/etc/passwd\"\n");
  std::string messages;
  ASSERT_FALSE(compileControllerFile(dir / "passwd.cpp", setupIn(dir), &messages).ok());
  EXPECT_NE(messages.find("cannot open file '/etc/passwd': Permission denied"), std::string::npos) << messages;
  EXPECT_EQ(messages.find("root:"), std::string::npos) << messages;
}

// Issue 18: a task called without co_await does nothing (and a run of it hung silently); in a
// controller it is an error that says so.
TEST(ControllerFile, ATaskThatIsNotAwaitedIsAnErrorThatSaysSo) {
  const fs::path dir = freshFolder("forgotten_co_await");
  writeFile(dir / "forgot.cpp", R"(#include <frob/frob.hpp>
using namespace frob;
Task<Wheels> ahead() { return mkTask([](const TaskState&) { return std::pair{wheels(0.3, 0), after(1.0)}; }); }
Task<Wheels> loop() { for (;;) ahead(); }
FROB_CONTROLLER(loop)
)");
  std::string messages;
  ASSERT_FALSE(compileControllerFile(dir / "forgot.cpp", setupIn(dir), &messages).ok());
  EXPECT_NE(messages.find("forgot.cpp:4:32: error: ignoring return value of function declared with 'nodiscard' "
                          "attribute: a Task does nothing unless you co_await it"),
            std::string::npos)
      << messages;
}

TEST(ControllerFile, ACompileThatNeverEndsIsStoppedAtItsTimeLimit) {
  const fs::path dir = freshFolder("bomb");
  // Ten to the sixteenth tokens: it would run until it ran out of memory, minutes later.
  writeFile(dir / "bomb.cpp", "#define A(x) x x x x x x x x x x\n#define B(x) A(A(A(A(A(A(A(A(x))))))))\nint v[] = { B(B(1)) };\n");
  CompilerSetup setup = setupIn(dir);
  setup.seconds = 2;
  Result<CompiledController> c = compileControllerFile(dir / "bomb.cpp", setup);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error(),
            "compiling '" + (dir / "bomb.cpp").string() + "' took longer than 2 s, so it was stopped (an #include or a macro that never ends?)");
}

// An `else if` chain of 8000 branches (160 KB) overflows the 8 MB stack clang's parser usually has: a
// compiler crash, which gives no grade, so any student could turn a zero into "not graded". With the
// compiler's own large stack it compiles.
TEST(ControllerFile, ADeepNestingCompilesInsteadOfCrashingTheCompiler) {
  const fs::path dir = freshFolder("deep");
  std::string chain = "int chain(int x) {\n  int y = 0;\n  if (x == 0) y = 0;\n";
  for (int i = 1; i < 8000; ++i) chain += "  else if (x == " + std::to_string(i) + ") y = " + std::to_string(i % 7) + ";\n";
  writeFile(dir / "deep.cpp",
            "#include <frob/frob.hpp>\n" + chain +
                "  return y;\n}\nfrob::Behavior<frob::Wheels> go(const frob::Robot&) { return frob::Wheels{0.1 * chain(3), 0.0}; }\n"
                "FROB_CONTROLLER(go)\n");
  std::string messages;
  Result<CompiledController> c = compileControllerFile(dir / "deep.cpp", setupIn(dir), &messages);
  ASSERT_TRUE(c.ok()) << c.error() << messages.substr(0, 2000);
  EXPECT_TRUE(fs::exists(c.value().module));
}

// A nesting deep enough to grow the compiler's stack until its memory runs out (an `else if` chain
// two million long, from a 1 KB file of macros) crashes clang: a crash of the compiler's memory
// limit, the submission's failure like any other limit, never "the compiler crashed", which gives no
// grade. (A crash with little memory in use stays the grader's: GraderFailure's tests.)
TEST(ControllerFile, ANestingPastTheCompilersMemoryIsTheSubmissionsFailure) {
  if (kSanitizedBuild) GTEST_SKIP() << "a sanitizer build gives the compiler no memory limit to run into";
  const fs::path dir = freshFolder("deeper");
  std::string source = "#include <frob/frob.hpp>\n#define A0 else if (0);\n";
  for (int i = 1; i <= 21; ++i) source += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + " A" + std::to_string(i - 1) + "\n";
  source +=
      "void deep() { if (0); A21 }\n"
      "frob::Behavior<frob::Wheels> go(const frob::Robot&) { return frob::Wheels{0.1, 0.0}; }\nFROB_CONTROLLER(go)\n";
  writeFile(dir / "deeper.cpp", source);
  std::string messages;
  CompilerSetup setup = setupIn(dir);
  setup.memoryBytes = 2ULL << 30;  // sooner full than the usual 4 GiB, and the macros' tokens still fit
  const Result<CompiledController> c = compileControllerFile(dir / "deeper.cpp", setup, &messages);
  ASSERT_FALSE(c.ok());
  EXPECT_FALSE(isGraderFailure(c.status())) << c.error() << messages.substr(messages.size() - std::min<std::size_t>(messages.size(), 600));
  // The stack's crash, not an allocation's (which clang names: "LLVM ERROR: out of memory").
  EXPECT_NE(messages.find("Segmentation fault"), std::string::npos) << messages.substr(messages.size() - std::min<std::size_t>(messages.size(), 600));
  EXPECT_EQ(c.error(),
            "could not compile '" + (dir / "deeper.cpp").string() + "' within the compiler's limits of time, memory and file size (128 MB a file)");
}

// Without a memory limit (0) no crash is one of running out of it: clang crashing on purpose (its
// debug pragma, allowed here) stays the grader's failure, however little memory it used.
TEST(ControllerFile, ACrashWithNoMemoryLimitIsTheGradersFailure) {
  const fs::path dir = freshFolder("crash_unlimited");
  writeFile(dir / "crash.cpp", "#pragma clang __debug crash\n");
  CompilerSetup setup = setupIn(dir);
  const auto disabled = std::find(setup.flags.begin(), setup.flags.end(), "-disable-pragma-debug-crash");
  ASSERT_NE(disabled, setup.flags.end());
  setup.flags.erase(disabled - 1, disabled + 1);  // with its -Xclang
  setup.memoryBytes = 0;
  const Result<CompiledController> c = compileControllerFile(dir / "crash.cpp", setup);
  ASSERT_FALSE(c.ok());
  EXPECT_TRUE(isGraderFailure(c.status())) << c.error();
}

// The compiler's large stack is not every thread's: a linker that starts a thread per core (lld, the
// linker where there is no gold) links, as it did not when the stack was limited to 1 GB (glibc
// gives each thread a stack the size of a finite limit, past the compiler's memory).
TEST(ControllerFile, ALinkerWithAThreadPerCoreLinksBesideTheCompilersLargeStack) {
  if (::access("/usr/bin/ld.lld", X_OK) != 0) GTEST_SKIP() << "no lld here";
  const fs::path dir = freshFolder("lld_threads");
  writeFile(dir / "go.cpp", kCollidingDrives);
  CompilerSetup setup = setupIn(dir);
  setup.flags.insert(setup.flags.end(), {"--ld-path=/usr/bin/ld.lld", "-Wl,--threads=16"});
  std::string messages;
  Result<CompiledController> c = compileControllerFile(dir / "go.cpp", setup, &messages);
  ASSERT_TRUE(c.ok()) << c.error() << messages.substr(0, 2000);
}

// The cache knows a compile by SHA-256: these two files (a robot that drives, one that stands still)
// share a 64-bit FNV-1a hash, which the cache was once keyed by, so the second was given the first's
// module (the comments at their ends were searched for, in two minutes, to make them collide).
TEST(ControllerFile, TwoFilesWhoseFnvHashesCollideCompileToTheirOwnModules) {
  const fs::path dir = freshFolder("collide");
  const CompilerSetup setup = setupIn(dir);
  writeFile(dir / "go.cpp", kCollidingDrives);
  Result<CompiledController> drives = compileControllerFile(dir / "go.cpp", setup);
  ASSERT_TRUE(drives.ok()) << drives.error();
  writeFile(dir / "go.cpp", kCollidingStandsStill);
  Result<CompiledController> still = compileControllerFile(dir / "go.cpp", setup);
  ASSERT_TRUE(still.ok()) << still.error();
  EXPECT_TRUE(still.value().compiled) << "the cache gave it the other file's module";
  EXPECT_NE(still.value().module, drives.value().module);
}

}  // namespace
}  // namespace frob::course
