#include "frob/base/layout.hpp"

#include <system_error>

namespace frob {

namespace fs = std::filesystem;

namespace {

// The marker an installed prefix holds (cmake/FrobInstall.cmake writes it).
fs::path marker(const fs::path& prefix) { return prefix / FROB_INSTALL_DATADIR / "frob" / "version"; }

Layout buildLayout() {
  return Layout{.installed = false,
                .prefix = FROB_BUILD_SOURCE_DIR,
                .sourceTree = FROB_BUILD_SOURCE_DIR,
                .worlds = FROB_BUILD_WORLDS_DIR,
                .models = FROB_BUILD_MODELS_DIR,
                .examples = FROB_BUILD_EXAMPLES_DIR,
                .exampleModules = FROB_BUILD_EXAMPLE_MODULES_DIR,
                .assignments = FROB_BUILD_ASSIGNMENTS_DIR,
                .studentTemplate = FROB_BUILD_TEMPLATE_DIR,
                .includeDir = FROB_BUILD_INCLUDE_DIR,
                .precompiledHeader = FROB_BUILD_PCH,
                .headerOverlay = FROB_BUILD_OVERLAY,
                .controllerHost = FROB_BUILD_HOST,
                .sandbox = FROB_BUILD_SANDBOX};
}

// The prefix the running program is installed in, or empty: the program is P/bin/frob (bin being
// the install's bin folder) and P holds the marker.
fs::path installedPrefix() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  fs::path prefix = exe.parent_path();
  for (const fs::path& part : fs::path(FROB_INSTALL_BINDIR)) {
    if (!part.empty() && part != ".") prefix = prefix.parent_path();
  }
  return fs::is_regular_file(marker(prefix), ec) ? prefix : fs::path();
}

}  // namespace

Layout installedLayout(const fs::path& prefix) {
  const fs::path lib = prefix / FROB_INSTALL_LIBDIR / "frob";
  const fs::path share = prefix / FROB_INSTALL_DATADIR / "frob";
  const fs::path libexec = prefix / FROB_INSTALL_LIBEXECDIR / "frob";
  return Layout{.installed = true,
                .prefix = prefix,
                .worlds = share / "worlds",
                .models = share / "models",
                .examples = share / "examples",
                .exampleModules = lib / "examples",
                .assignments = share / "assignments",
                .studentTemplate = share / "template",
                .includeDir = prefix / FROB_INSTALL_INCLUDEDIR,
                .precompiledHeader = lib / "frob.pch",
                .headerOverlay = lib / "frob-headers.yaml",
                .controllerHost = libexec / "frob-controller-host",
                .sandbox = libexec / "frob-sandbox"};
}

const Layout& layout() {
  static const Layout l = [] {
    const fs::path prefix = installedPrefix();
    return prefix.empty() ? buildLayout() : installedLayout(prefix);
  }();
  return l;
}

const char* version() { return FROB_VERSION; }

const char* const kSdkIncludeDir = FROB_SDK_INCLUDE_DIR;

}  // namespace frob
