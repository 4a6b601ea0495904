#pragma once
/// Where frob's files are at run time. A program in the build tree uses the build's folders; a
/// program installed with `cmake --install` finds them relative to its own path, so that an
/// installed prefix can be moved or packaged without rebuilding.

#include <filesystem>

namespace frob {

/// The folder controllers are compiled as seeing frob's headers in: a clang VFS overlay
/// (Layout::headerOverlay) maps it to the real folder, so that one precompiled header serves any
/// place the headers are installed in.
extern const char* const kSdkIncludeDir;

/// The folders and files frob reads at run time.
struct Layout {
  bool installed = false;                   ///< true for an installed program, false in the build tree
  std::filesystem::path prefix;             ///< the installed prefix; the build tree's source folder otherwise
  std::filesystem::path sourceTree;         ///< the source tree; empty when installed
  std::filesystem::path worlds;             ///< the reference world files
  std::filesystem::path models;             ///< robot.obj
  std::filesystem::path examples;           ///< the numbered example controllers' sources
  std::filesystem::path exampleModules;     ///< the examples prebuilt, one stem.so each
  std::filesystem::path assignments;        ///< one folder per assignment
  std::filesystem::path studentTemplate;    ///< the student project template
  std::filesystem::path includeDir;         ///< frob's headers (the folder holding frob/)
  std::filesystem::path precompiledHeader;  ///< frob.hpp precompiled as seen through headerOverlay
  std::filesystem::path headerOverlay;      ///< clang VFS overlay mapping kSdkIncludeDir to includeDir
  std::filesystem::path controllerHost;     ///< frob-controller-host
  std::filesystem::path sandbox;            ///< frob-sandbox, which runs a program under the sandbox
};

/// The layout of the running program: the installed one when the program sits in the bin folder of
/// a prefix holding frob's files, the build tree's otherwise.
[[nodiscard]] const Layout& layout();

/// The layout of a prefix `prefix` that frob was installed into.
[[nodiscard]] Layout installedLayout(const std::filesystem::path& prefix);

/// This build's version, e.g. "0.1.0".
[[nodiscard]] const char* version();

}  // namespace frob
