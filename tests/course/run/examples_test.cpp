// The course's numbered examples: found by name, and run from the module the whole build made or,
// when the product's build left it out, compiled on first use like a student's file.
#include "frob/run/examples.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

fs::path freshFolder(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "examples_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(Examples, AreFoundByNameWithOrWithoutTheirNumber) {
  const std::optional<Example> bug = findExample("bug");
  ASSERT_TRUE(bug.has_value());
  EXPECT_EQ(bug->name, "06_bug");
  EXPECT_EQ(findExample("06_bug")->source, bug->source);
  EXPECT_FALSE(findExample("no_such_example").has_value());
}

TEST(Examples, WithoutAModuleCompilesOnFirstUseIntoTheCache) {
  const fs::path dir = freshFolder("first_use");
  Example bug = findExample("bug").value();
  bug.module = dir / "not_built" / "06_bug.so";  // as after `cmake --build --preset default`
  CompilerSetup setup = compilerSetup();
  setup.cacheDir = dir / "cache";
  Result<CompiledController> c = compileExample(bug, setup);
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_TRUE(c.value().compiled);
  EXPECT_EQ(c.value().module.parent_path(), fs::absolute(setup.cacheDir));
  EXPECT_TRUE(fs::exists(c.value().module));
}

TEST(Examples, AModuleNewerThanItsSourceIsUsedAsItIs) {
  const fs::path dir = freshFolder("prebuilt");
  Example bug = findExample("bug").value();
  bug.module = dir / "06_bug.so";
  std::ofstream(bug.module) << "a module";
  fs::last_write_time(bug.module, fs::last_write_time(bug.source) + std::chrono::seconds(1));
  CompilerSetup setup = compilerSetup();
  setup.cacheDir = dir / "cache";
  Result<CompiledController> c = compileExample(bug, setup);
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_FALSE(c.value().compiled);
  EXPECT_EQ(c.value().module, bug.module);
  EXPECT_FALSE(fs::exists(setup.cacheDir));
}

}  // namespace
}  // namespace frob::course
