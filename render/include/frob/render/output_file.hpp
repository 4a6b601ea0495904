#pragma once
/// Files that appear under their name only when complete: written as `<path>.partial`, renamed.

#include "frob/base/result.hpp"

#include <string>

namespace frob::render {

/// The temporary a file is written to before it is complete.
[[nodiscard]] inline std::string partialPath(const std::string& path) { return path + ".partial"; }

/// Checks that the directory of `path` exists and is writable; `what` names the output in messages.
[[nodiscard]] Status checkWritable(const std::string& path, const std::string& what);

/// Renames `<path>.partial` to `path`.
[[nodiscard]] Status commitPartial(const std::string& path, const std::string& what);

/// Removes `<path>.partial` if it exists.
void discardPartial(const std::string& path);

}  // namespace frob::render
