#pragma once
/// Student controller files: one C++ file ending with FROB_CONTROLLER(...), compiled in a sandbox
/// against the project's headers into a shared object, cached by content, then run in a sandboxed
/// controller host (host.hpp) or, for trusted code, loaded into this process.

#include "frob/base/result.hpp"
#include "frob/controller.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace frob::course {

/// Begins the message of every failure that is frob's or the machine's, never the submission's (a
/// compiler or controller host that cannot start, a full disk, a compiler that crashed): no grade
/// may rest on it.
inline constexpr std::string_view kGraderFailure = "the grader failed: ";
/// A failure of frob or the machine, never the submission's: `what` after kGraderFailure.
[[nodiscard]] inline Status graderFailure(const std::string& what) { return Status::failure(std::string(kGraderFailure) + what); }
/// Whether `s` failed through frob or the machine, not the submission (graderFailure()).
[[nodiscard]] inline bool isGraderFailure(const Status& s) { return s.error().starts_with(kGraderFailure); }

/// How controller files are compiled. compilerSetup() gives the one the project was built with.
struct CompilerSetup {
  std::string compiler;                    ///< the C++ compiler, as found on PATH or absolute
  std::vector<std::string> flags;          ///< language, optimisation, sanitizer and include flags (the project's ABI)
  std::string precompiledHeader;           ///< frob.hpp precompiled with `flags`; empty or missing: compile without
  std::vector<std::string> reads;          ///< files and folders the compiler reads besides the system's and its -I folders
  std::filesystem::path cacheDir;          ///< where compiled controllers are kept, named by a hash of what made them
  double seconds = 120.0;                  ///< wall-clock and CPU time a compile may take
  std::uint64_t memoryBytes = 4ULL << 30;  ///< address space of the compiler
  std::uint64_t fileBytes = 128ULL << 20;  ///< largest file it may write (an object, the module): twice the largest module kept
  bool checked = false;                    ///< with AddressSanitizer, UBSan and the C++ library's checks (`frob run --check`)
};

/// The compiler controllers are compiled with, and its version: "/usr/bin/clang++-16 (Clang 16.0.6)".
[[nodiscard]] std::string compilerDescription();

/// The build's compiler and flags, and the headers and precompiled header of frob::layout(); the cache is $FROB_CACHE_DIR, else
/// $XDG_CACHE_HOME/frob, else ~/.cache/frob. With `checked`, controllers are compiled with AddressSanitizer, UBSan, asserts
/// and std::vector's index checks on, for a host started with HostDef::checked (no precompiled header: slower to build).
[[nodiscard]] CompilerSetup compilerSetup(bool checked = false);

/// Where clang's AddressSanitizer runtime is, which a checked controller needs (Debian: libclang-rt-16-dev).
[[nodiscard]] std::string sanitizerRuntime();

/// A controller file compiled into a module, not loaded anywhere yet.
struct CompiledController {
  std::filesystem::path module;  ///< the shared object
  std::string source;            ///< the file it came from, as given
  bool compiled = false;         ///< true when it was compiled now, false when the cache (or the build) had it
  bool checked = false;          ///< compiled with CompilerSetup::checked: it runs only in a checked host
};

/// A controller ready to run: what its FROB_CONTROLLER declared, and where it came from.
struct LoadedController {
  ControllerEntry entry;         ///< its `make` is empty when the controller runs only in a controller host
  std::string source;            ///< the file it came from, as given
  std::filesystem::path module;  ///< its module; empty for a controller built in this process
  bool compiled = false;         ///< true when it was compiled now, false when the cache (or the build) had it
};

/// Whether C++ text holds a line that starts FROB_CONTROLLER(, as a controller file's does.
[[nodiscard]] bool holdsController(std::string_view text);
/// The .cpp files compiled with controller file `source`: the others in its folder that hold no
/// FROB_CONTROLLER(...) line (a student's helpers), by name.
[[nodiscard]] std::vector<std::filesystem::path> companionsOf(const std::filesystem::path& source);

/// Compiles `source`, with companionsOf(source), unless the cache already holds it (the cache knows
/// it by its text and the texts of its companions and of the headers beside it). The compiler runs
/// in the sandbox, as a user of its own when frob runs as root: it reads only the system's headers,
/// frob's, and copies of those texts in a folder of its own, within time and memory limits. On a compile error the error names the file; the
/// compiler's messages go to `messages`, or to stderr.
[[nodiscard]] Result<CompiledController> compileControllerFile(const std::filesystem::path& source, const CompilerSetup& setup = compilerSetup(),
                                                               std::string* messages = nullptr);
/// Compiles a submission as compileControllerFile() does: from copies of it and the headers (.h, .hpp)
/// beside it, so that its compile reads no other file that stood there (a classmate's, when a class
/// is one folder of .cpp files). A submission is a .cpp file,
/// compiled alone, or a folder of several: its one .cpp file with a FROB_CONTROLLER(...) line,
/// compiled with the other .cpp files there. The compiler's messages name the files by name only.
[[nodiscard]] Result<CompiledController> compileSubmission(const std::filesystem::path& submission, const CompilerSetup& setup = compilerSetup(),
                                                           std::string* messages = nullptr);
/// Loads `compiled` into this process, where its code runs outside the sandbox (trusted code only). Its
/// module stays loaded for the life of the process.
[[nodiscard]] Result<LoadedController> loadInProcess(const CompiledController& compiled);

}  // namespace frob::course
