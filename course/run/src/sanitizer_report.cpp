#include "sanitizer_report.hpp"

#include "frob/base/layout.hpp"
#include "sandboxed.hpp"

#include <sys/wait.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace frob::course {

namespace fs = std::filesystem;

namespace {

// One frame of a report, symbolized: "pick(double)" at "bad.cpp:9".
struct SourceFrame {
  std::string function;
  std::string place;  // file:line
};

// Each error gets a hint at its usual cause in a controller.
std::string_view likelyCause(std::string_view kind) {
  static const std::map<std::string_view, std::string_view> causes{
      {"heap-buffer-overflow", "an index past the end of a vector or an array?"},
      {"stack-buffer-overflow", "an index past the end of a local array?"},
      {"global-buffer-overflow", "an index past the end of a global array?"},
      {"heap-use-after-free", "a pointer or reference to something already destroyed?"},
      {"stack-use-after-scope", "a reference to a local that is gone, e.g. a lambda capturing it by [&]?"},
      {"stack-use-after-return", "a reference to a local of a function that returned?"},
      {"attempting double-free", "deleted twice?"},
      {"SEGV", "a null or dangling pointer?"},
      {"ABRT", "abort() or a failed assert"},
  };
  const auto it = causes.find(kind);
  return it == causes.end() ? std::string_view() : it->second;
}

std::string trimmed(std::string s) {
  const std::size_t from = s.find_first_not_of(" \t\r\n");
  if (from == std::string::npos) return {};
  return s.substr(from, s.find_last_not_of(" \t\r\n") - from + 1);
}

// A source place as a student reads it: relative to the working folder when inside it, no discriminator.
std::string readablePlace(std::string place) {
  if (const std::size_t d = place.find(" (discriminator"); d != std::string::npos) place.resize(d);
  if (place.empty() || place[0] != '/') return place;
  std::error_code ec;
  const fs::path relative = fs::proximate(place, ec);
  return ec || relative.empty() || *relative.begin() == ".." ? place : relative.string();
}

// "go(frob::Robot const&)::$_0::operator()(double) const" as a student reads it: "go(frob::Robot const&)'s lambda".
std::string lambdaNamed(const std::string& function) {
  static const std::regex lambda(R"(::\$_\d+::operator\(\)\(.*\)( const)?$)");
  return std::regex_replace(function, lambda, "'s lambda");
}

// The student's code: not the system's headers and libraries, not frob's.
bool isStudents(const SourceFrame& f) {
  return !f.place.empty() && f.place.rfind("??", 0) != 0 && f.place.rfind("/usr/", 0) != 0 && f.place.rfind(kSdkIncludeDir, 0) != 0;
}

// The last failed assertion in `output`, in words: "the assert 'x > 0' failed", or "".
std::string failedAssertion(std::string_view output) {
  static const std::regex assertion(R"(([^\n]*)Assertion [`']([^\n]*)' failed)");
  std::string last;
  const std::string text(output);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), assertion); it != std::sregex_iterator(); ++it) {
    const bool library = (*it)[1].str().find("/include/c++/") != std::string::npos;
    last = (library ? "the C++ library's check '" : "the assert '") + (*it)[2].str() + "' failed";
    if (library && last.find("size()") != std::string::npos) last += " (an index out of range?)";
  }
  return last;
}

// Symbolizes with binutils' addr2line, run in the sandbox: it reads only the module and the system. The
// frames of `module` at each offset, innermost first; an inlined call gives several.
std::vector<std::vector<SourceFrame>> addr2line(const fs::path& module, const std::vector<std::string>& offsets) {
  SandboxedDef program{.command = {"/usr/bin/addr2line", "--addresses", "--functions", "--demangle", "--inlines", "--exe", module.string()},
                       .limits = {.cpuSeconds = 10, .memoryBytes = 1ULL << 30, .fileBytes = 1 << 20, .openFiles = 32},
                       .files = {.read = {"/usr", "/lib", "/lib64", "/etc/ld.so.cache", module.string()}},
                       .cwd = "/",
                       .noNetwork = true};
  program.command.insert(program.command.end(), offsets.begin(), offsets.end());
  Result<SandboxedRun> run = runSandboxed(std::move(program), 10.0, 1 << 20);
  std::vector<std::vector<SourceFrame>> frames;
  if (!run || !WIFEXITED(run.value().status) || WEXITSTATUS(run.value().status) != 0) return frames;
  // Each address on a line of its own ("0x..."), then pairs of lines: function, file:line.
  std::istringstream out(run.value().output);
  for (std::string line; std::getline(out, line);) {
    if (line.rfind("0x", 0) == 0) {
      frames.emplace_back();
    } else if (!frames.empty()) {
      std::string place;
      std::getline(out, place);
      frames.back().push_back({lambdaNamed(line), place});
    }
  }
  return frames;
}

// The finding of `report` (what a sanitizer wrote), whose frames in the modules in `modules` are
// symbolized; `output` is what the host printed last. Empty when `report` holds no sanitizer error.
std::optional<SanitizerFinding> explainReport(std::string_view report, std::string_view output, const fs::path& modules) {
  static const std::regex asanError(R"(ERROR: AddressSanitizer: ([A-Za-z-]+(?: [a-z-]+)?) on)");
  static const std::regex access(R"((READ|WRITE) of size (\d+))");
  static const std::regex ubsanError(R"(([^\s:]+:\d+(?::\d+)?): runtime error: ([^\n]*))");
  static const std::regex frame(R"(^\s*#\d+ 0x[0-9a-f]+.*\(([^()\s]+)\+(0x[0-9a-f]+)\))");
  const std::string text(report);
  std::smatch m;
  std::string what, where;
  if (std::regex_search(text, m, asanError)) {
    const std::string kind = m[1];
    what = "AddressSanitizer: " + kind;
    if (std::smatch a; std::regex_search(text, a, access))
      what += std::string(", ") + (a[1] == "READ" ? "reading " : "writing ") + a[2].str() + " bytes";
    if (const std::string assertion = failedAssertion(output); kind == "ABRT" && !assertion.empty()) {
      what = assertion;
    } else if (const std::string_view cause = likelyCause(kind); !cause.empty()) {
      what += " (" + std::string(cause) + ")";
    }
  } else if (std::regex_search(text, m, ubsanError)) {
    what = "undefined behaviour: " + m[2].str();
    where = readablePlace(m[1]);
  } else {
    return std::nullopt;
  }

  // The frames in the controller's modules, symbolized one module at a time.
  std::vector<std::string> lines;
  std::map<std::string, std::vector<std::string>> offsets;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::smatch f;
    if (std::regex_search(line, f, frame)) {
      const fs::path module = f[1].str();             // the host names its modules by their whole path
      if (module.parent_path() != modules) continue;  // frob's and the system's frames are not the student's business
      offsets[module].push_back(f[2]);
      lines.push_back(module.string() + "+" + f[2].str());
    } else if (line.find(" here:") != std::string::npos) {
      lines.push_back(trimmed(line));  // "freed by thread T0 here:"
    }
  }
  std::map<std::string, std::vector<SourceFrame>> frames;  // by "module+offset"
  for (const auto& [module, list] : offsets) {
    const std::vector<std::vector<SourceFrame>> found = addr2line(module, list);
    for (std::size_t i = 0; i < list.size() && i < found.size(); ++i) frames[module + "+" + list[i]] = found[i];
  }
  SanitizerFinding finding;
  std::string function;
  for (const std::string& line : lines) {
    const auto it = frames.find(line);
    if (it == frames.end()) {
      finding.stack += line + "\n";
      continue;
    }
    for (SourceFrame f : it->second) {
      f.place = readablePlace(f.place);
      if (!isStudents(f)) continue;  // the library's and frob's frames say nothing to a student
      if (function.empty()) function = f.function, where = where.empty() ? f.place : where;
      finding.stack += "    " + f.function + " at " + f.place + "\n";
    }
  }
  finding.reason = what + (function.empty() ? "" : " in " + function) + (where.empty() ? "" : " at " + where);
  return finding;
}

}  // namespace

std::vector<std::string> sanitizerEnvironment(const fs::path& folder) {
  // Stop at the first error with its report in `folder`, unsymbolized; leave crashes to the host's
  // own handlers (they tell a stack overflow), but trace an abort(), which a failed check ends in.
  const std::string common = "log_path=" + (folder / "sanitizer").string() + ":symbolize=0:print_summary=0";
  return {"ASAN_OPTIONS=" + common +
              ":detect_leaks=0:handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_abort=1:detect_stack_use_after_return=0:"
              "quarantine_size_mb=64:malloc_context_size=8",
          "UBSAN_OPTIONS=" + common + ":print_stacktrace=1:halt_on_error=1"};
}

std::optional<SanitizerFinding> readSanitizerReport(const fs::path& folder, std::string_view output, const fs::path& modules) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    if (e.path().filename().string().rfind("sanitizer.", 0) != 0) continue;
    std::ifstream in(e.path(), std::ios::binary);
    const std::string report{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (std::optional<SanitizerFinding> f = explainReport(report, output, modules)) return f;
  }
  return std::nullopt;
}

}  // namespace frob::course
