#pragma once
/// Student controller files: one C++ file ending with FROB_CONTROLLER(...), compiled against the
/// project's headers into a shared object, cached by content, and loaded into this process.

#include "frob/controller.hpp"
#include "frob/render/result.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace frob::course {

using render::Result;
using render::Status;

/// How controller files are compiled. compilerSetup() gives the one the project was built with.
struct CompilerSetup {
  std::string compiler;              ///< the C++ compiler, as found on PATH or absolute
  std::vector<std::string> flags;    ///< language, optimisation, sanitizer and include flags (the project's ABI)
  std::string precompiledHeader;     ///< frob.hpp precompiled with `flags`; empty or missing: compile without
  std::filesystem::path cacheDir;    ///< where compiled controllers are kept, named by a hash of what made them
};

/// The build's compiler, flags and precompiled header; the cache is $FROB_CACHE_DIR, else
/// $XDG_CACHE_HOME/frob, else ~/.cache/frob.
[[nodiscard]] CompilerSetup compilerSetup();

/// A controller loaded from a file. Its module stays loaded for the life of the process.
struct LoadedController {
  ControllerEntry entry;  ///< what the file's FROB_CONTROLLER declared
  std::string source;     ///< the file it came from, as given
  bool compiled = false;  ///< true when it was compiled now, false when the cache (or the build) had it
};

/// Compiles `source` unless the cache already holds it, then loads it. On a compile error the
/// compiler's own messages have gone to stderr and the error names the file.
[[nodiscard]] Result<LoadedController> loadControllerFile(const std::filesystem::path& source,
                                                          const CompilerSetup& setup = compilerSetup());
/// Loads an already compiled controller module (a .so built from `source`).
[[nodiscard]] Result<LoadedController> loadControllerModule(const std::filesystem::path& module,
                                                            const std::string& source);

}  // namespace frob::course
