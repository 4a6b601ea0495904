#pragma once
// A checked controller's sanitizer reports (frob run --check), read in the trusted process: the host
// writes them unsymbolized into its scratch folder, since it may not start a symbolizer, and here
// they become a reason that names the student's file and line.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frob::course {

/// The environment of a checked host: the sanitizers stop at the first error and write their
/// report into `folder`, where readSanitizerReport() finds it.
[[nodiscard]] std::vector<std::string> sanitizerEnvironment(const std::filesystem::path& folder);

/// One frame of a report, symbolized: "pick(double)" at "bad.cpp:9:10".
struct SourceFrame {
  std::string function;
  std::string place;  ///< file:line[:column]
};

/// The frames of `module` at these offsets, innermost first; an inlined call gives several frames.
using Symbolizer = std::function<std::vector<std::vector<SourceFrame>>(const std::filesystem::path& module, const std::vector<std::string>& offsets)>;

/// What a report says, in a student's words.
struct SanitizerFinding {
  std::string reason;  ///< one line: what went wrong and in which function, file and line
  std::string stack;   ///< the controller's frames, one per line, innermost first
};

/// The finding of `report` (what a sanitizer wrote), whose frames in modules under `folder` are
/// symbolized by `symbolize`; `output` is what the host printed last (the C++ library's assertion
/// message goes there). Empty when `report` holds no sanitizer error.
[[nodiscard]] std::optional<SanitizerFinding> explainReport(std::string_view report, std::string_view output, const std::filesystem::path& folder,
                                                            const Symbolizer& symbolize);

/// Symbolizes with binutils' addr2line, run confined: it reads only the module and the system.
[[nodiscard]] std::vector<std::vector<SourceFrame>> addr2line(const std::filesystem::path& module, const std::vector<std::string>& offsets);

/// The finding of the reports written into `folder` by a host started with sanitizerEnvironment().
[[nodiscard]] std::optional<SanitizerFinding> readSanitizerReport(const std::filesystem::path& folder, std::string_view output);

}  // namespace frob::course
