// What a submission names and links: a file name never reaches the compiler as an option or a file
// of options, and a link or special file is never followed or opened for reading (the secret,
// /etc/shadow, a classmate's file, a FIFO that would block for ever).
#include "frob/run/controller_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

constexpr const char* kController =
    "#include <frob/frob.hpp>\nfrob::Behavior<frob::Wheels> go(const frob::Robot&) { return frob::Wheels{0.1, 0.0}; }\nFROB_CONTROLLER(go)\n";

class SubmissionFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / "submission_files_test" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "class");
    setup_ = compilerSetup();
    setup_.cacheDir = dir_ / "cache";
    std::ofstream(dir_ / "secret.txt") << "s3cr3t-first-line\n";
  }
  // Compiles `submission`, failing; its error and the compiler's messages.
  std::string refusal(const fs::path& submission) {
    std::string messages;
    Result<CompiledController> c = compileSubmission(submission, setup_, &messages);
    EXPECT_FALSE(c.ok()) << submission;
    return c.error() + "\n" + messages;
  }
  fs::path dir_;
  CompilerSetup setup_;
};

TEST_F(SubmissionFiles, NamesThatReadAsOptionsAreRefused) {
  fs::create_directories(dir_ / "class" / "bob");
  std::ofstream(dir_ / "class" / "bob" / "go.cpp") << kController;
  std::ofstream(dir_ / "class" / "bob" / "-x.cpp") << "int helper() { return 1; }\n";
  EXPECT_NE(refusal(dir_ / "class" / "bob").find("-x.cpp': a file name that begins with '-' would reach the compiler as an option: rename it"),
            std::string::npos);
  std::ofstream(dir_ / "class" / "@opts.cpp") << kController;
  std::ofstream(dir_ / "class" / "opts.cpp") << "-Xclang -load -Xclang /tmp/plugin.so\n";
  EXPECT_NE(refusal(dir_ / "class" / "@opts.cpp").find("would reach the compiler as a file of options to read (a response file): rename it"),
            std::string::npos);
}

TEST_F(SubmissionFiles, LinksAreNeverFollowed) {
  std::ofstream(dir_ / "class" / "carol.cpp") << kController;
  fs::create_symlink(dir_ / "secret.txt", dir_ / "class" / "alice.cpp");
  fs::create_symlink("/etc/shadow", dir_ / "class" / "eve.cpp");
  fs::create_symlink("carol.cpp", dir_ / "class" / "bob.cpp");
  fs::create_directory_symlink("..", dir_ / "class" / "dan");
  for (const char* name : {"alice.cpp", "eve.cpp", "bob.cpp", "dan"}) {
    const std::string why = refusal(dir_ / "class" / name);
    EXPECT_NE(why.find("is a symbolic link, and a submission's links are never followed"), std::string::npos) << name << ": " << why;
    EXPECT_EQ(why.find("s3cr3t"), std::string::npos) << why;
  }
  // A helper header linked to the secret is not there to include.
  fs::create_directories(dir_ / "class" / "frank");
  std::ofstream(dir_ / "class" / "frank" / "go.cpp") << "#include \"notes.hpp\"\n" << kController;
  fs::create_symlink(dir_ / "secret.txt", dir_ / "class" / "frank" / "notes.hpp");
  const std::string why = refusal(dir_ / "class" / "frank");
  EXPECT_NE(why.find("'notes.hpp' file not found"), std::string::npos) << why;
  EXPECT_EQ(why.find("s3cr3t"), std::string::npos) << why;
}

// A FIFO would block the grader's read for ever (then ctest's timeout).
TEST_F(SubmissionFiles, AFifoIsNeverOpenedForReading) {
  ASSERT_EQ(::mkfifo((dir_ / "class" / "pipe.cpp").c_str(), 0644), 0);
  EXPECT_NE(refusal(dir_ / "class" / "pipe.cpp").find("not a regular file"), std::string::npos);
  fs::create_directories(dir_ / "class" / "gina");
  std::ofstream(dir_ / "class" / "gina" / "go.cpp") << kController;
  ASSERT_EQ(::mkfifo((dir_ / "class" / "gina" / "helpers.cpp").c_str(), 0644), 0);
  ASSERT_EQ(::mkfifo((dir_ / "class" / "gina" / "notes.hpp").c_str(), 0644), 0);
  std::string messages;
  EXPECT_TRUE(compileSubmission(dir_ / "class" / "gina", setup_, &messages).ok()) << messages;
}

}  // namespace
}  // namespace frob::course
