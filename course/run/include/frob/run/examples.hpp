#pragma once
/// The course's numbered examples (course/examples/NN_name.cpp): the paper's programs as controller
/// files, prebuilt as modules so that `frob run bug` starts at once.

#include "frob/run/controller_file.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frob::course {

/// One example: its file and its prebuilt module.
struct Example {
  std::string name;              ///< the file's stem, e.g. "06_bug"
  std::filesystem::path source;  ///< the .cpp under course/examples
  std::filesystem::path module;  ///< the module the build made of it (may be missing in a partial build)
};

/// Every example, in number order.
[[nodiscard]] std::vector<Example> examples();
/// The example called `name`, with or without its number ("06_bug" or "bug").
[[nodiscard]] std::optional<Example> findExample(std::string_view name);
/// `example` as a module: the one the build made, or its source compiled with `setup` when that is missing or
/// older, or when `setup` is checked.
[[nodiscard]] Result<CompiledController> compileExample(const Example& example, const CompilerSetup& setup = compilerSetup());

}  // namespace frob::course
