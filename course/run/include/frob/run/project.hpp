#pragma once
/// A student's own controller project: `frob init [folder]` copies the student template into a
/// folder and writes what an editor's clangd needs to see frob's real headers with the flags
/// controllers are compiled with, so that completion, errors and go-to-definition work.

#include "frob/base/result.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace frob::course {

/// The flags clangd should read a controller with: those of compilerSetup(), with frob's headers at
/// their real folder instead of the compiler's virtual one, and the project's own folder.
[[nodiscard]] std::vector<std::string> editorFlags();

/// What initProject() did with each file, for the command to report.
struct ProjectFile {
  std::filesystem::path path;
  bool written = false;  ///< false: a file of that name was there already and is kept as it was
};

/// Makes `folder` (and its parents) if needed, copies into it the student template's files that it
/// does not hold yet (a file already there is never replaced), and writes compile_flags.txt, the
/// editorFlags() one per line as clangd reads them (rewritten each time: it belongs to frob).
[[nodiscard]] Result<std::vector<ProjectFile>> initProject(const std::filesystem::path& folder);

}  // namespace frob::course
