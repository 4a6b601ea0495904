#pragma once
// A checked controller's sanitizer reports (frob run --check), read in the trusted process: the host
// writes them unsymbolized into its scratch folder, since it may not start a symbolizer, and here
// they become a reason that names the student's file and line.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frob::course {

/// The environment of a checked host: the sanitizers stop at the first error and write their
/// report into `folder`, where readSanitizerReport() finds it.
[[nodiscard]] std::vector<std::string> sanitizerEnvironment(const std::filesystem::path& folder);

/// What a report says, in a student's words.
struct SanitizerFinding {
  std::string reason;  ///< one line: what went wrong and in which function, file and line
  std::string stack;   ///< the controller's frames, one per line, innermost first
};

/// The finding of the reports written into `folder` by a host started with sanitizerEnvironment(), whose
/// frames in the controller modules in `modules` are symbolized; `output` is what the host printed last
/// (the C++ library's assertion message goes there). Empty when no report holds an error.
[[nodiscard]] std::optional<SanitizerFinding> readSanitizerReport(const std::filesystem::path& folder, std::string_view output,
                                                                  const std::filesystem::path& modules);

}  // namespace frob::course
