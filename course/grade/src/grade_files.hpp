#pragma once
// Private: what the grade's writers share (grade_report.cpp, gradebook.cpp): whole files, and
// points as text.
#include "frob/base/result.hpp"

#include <filesystem>
#include <string>

namespace frob::course::detail {

/// Writes `bytes` to `<path>.partial` and renames it to `path`; `what` names the file in messages.
[[nodiscard]] Status writeWhole(const std::filesystem::path& path, const std::string& what, const std::string& bytes);
/// The whole of a file; `what` names it in messages.
[[nodiscard]] Result<std::string> readWhole(const std::filesystem::path& path, const std::string& what);
/// `points` rounded to 1e-4, in the shortest text that reads back as the same double ("2", "0.5").
[[nodiscard]] std::string number(double points);

}  // namespace frob::course::detail
