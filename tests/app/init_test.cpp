// frob init: a project folder in which Debian's clangd-16 sees frob's real headers with the flags
// controllers compile with, so that a controller has no errors and a misspelt name is reported.
#include "run_frob.hpp"

#include <gtest/gtest.h>

namespace frob::testing {
namespace {

namespace fs = std::filesystem;

// clangd's own check of `file` as an editor would open it (without its per-token code actions).
FrobResult clangdCheck(const fs::path& file) {
  return runCommand(file.parent_path(), {FROB_CLANGD, "--check=" + file.string(), "--check-locations=false"});
}

TEST(FrobInit, ClangdFindsNoErrorInTheProjectAndNamesAMisspeltName) {
  const fs::path dir = freshFolder("init_clangd");
  const FrobResult init = runFrob(dir, {"init", "my project"});
  ASSERT_EQ(init.status, 0) << init.err;
  const fs::path project = dir / "my project";
  for (const char* f : {"wander.cpp", "wander.hpp", "tests/wander_test.cpp", "CMakeLists.txt", "compile_flags.txt"}) {
    EXPECT_TRUE(fs::is_regular_file(project / f)) << f;
    EXPECT_NE(init.out.find("wrote " + (project.lexically_relative(dir) / f).string()), std::string::npos) << init.out;
  }

  for (const char* f : {"wander.cpp", "wander.hpp", "tests/wander_test.cpp"}) {  // the test reads wander.hpp through -I.
    const FrobResult check = clangdCheck(project / f);
    EXPECT_EQ(check.status, 0) << f << "\n" << check.err;
    EXPECT_NE(check.err.find("All checks completed, 0 errors"), std::string::npos) << f << "\n" << check.err;
  }

  std::ofstream(project / "misspelt.cpp")
      << "#include <frob/frob.hpp>\nusing namespace frob;\n"
         "Task<Wheels> go(Vector2 p) { co_await mkTask([p](const TaskState&) { return std::pair{wheels(0.1, 0), after(1.0)}; }); }\n"
         "FROB_CONTROLLER(go)\n";
  const FrobResult misspelt = clangdCheck(project / "misspelt.cpp");
  EXPECT_NE(misspelt.status, 0);
  EXPECT_NE(misspelt.err.find("Line 3: unknown type name 'Vector2'"), std::string::npos) << misspelt.err;
}

TEST(FrobInit, KeepsTheFilesAlreadyThereAndRenewsTheFlags) {
  const fs::path dir = freshFolder("init_keeps");
  std::ofstream(dir / "wander.cpp") << "// mine\n";
  std::ofstream(dir / "compile_flags.txt") << "-I/a/frob/that/moved\n";
  const FrobResult init = runFrob(dir, {"init"});
  ASSERT_EQ(init.status, 0) << init.err;
  EXPECT_EQ(readFile(dir / "wander.cpp"), "// mine\n");
  EXPECT_NE(init.out.find("kept   ./wander.cpp (already there)"), std::string::npos) << init.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "wander.hpp"));
  const std::string flags = readFile(dir / "compile_flags.txt");
  EXPECT_EQ(flags.find("/a/frob/that/moved"), std::string::npos);
  EXPECT_NE(flags.find("-std=c++20\n"), std::string::npos) << flags;
  EXPECT_EQ(flags.find("frob-sdk"), std::string::npos) << "clangd must see the real headers, not the compiler's virtual folder";
  EXPECT_FALSE(fs::exists(dir / "compile_flags.txt.partial"));
}

TEST(FrobInit, AFolderThatCannotBeMadeIsAnErrorThatNamesIt) {
  const fs::path dir = freshFolder("init_blocked");
  std::ofstream(dir / "taken") << "a file, not a folder\n";
  const FrobResult init = runFrob(dir, {"init", "taken/project"});
  EXPECT_EQ(init.status, 1);
  EXPECT_NE(init.err.find("frob: cannot create the folder 'taken/project'"), std::string::npos) << init.err;
}

}  // namespace
}  // namespace frob::testing
