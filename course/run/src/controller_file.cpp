#include "frob/run/controller_file.hpp"

#include "cache_key.hpp"
#include "controller_setup.inc"
#include "frob/base/layout.hpp"
#include "frob/run/scratch.hpp"
#include "load_error.hpp"
#include "sandboxed.hpp"

#include <cxxabi.h>
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>

namespace frob::course {

namespace fs = std::filesystem;

namespace {

#define FROB_STRINGIFY2(x) #x
#define FROB_STRINGIFY(x) FROB_STRINGIFY2(x)
constexpr const char* kEntrySymbol = FROB_STRINGIFY(FROB_CONTROLLER_SYMBOL);
constexpr std::uintmax_t kModuleBytes = 64 << 20;  // largest compiled controller kept (a large one is 6 MB)
// The compiler's stack: bounded by its memory only. Clang's parser recurses once per level of nesting
// (an `else if` chain of a few thousand overflows the usual 8 MB, a crash that gives no grade).
// Unlimited, not merely large: glibc gives each thread a stack the size of a finite limit, and lld's
// threads, one per core, would not fit in the compiler's memory; without a limit, 32 MB each.
constexpr std::uint64_t kCompilerStackBytes = RLIM_INFINITY;
// What clang says when a limit stopped it (strsignal's words for SIGXCPU and SIGXFSZ, and LLVM's when
// memory ran out).
constexpr const char* kLimitWords[] = {"CPU time limit exceeded", "File size limit exceeded", "LLVM ERROR: out of memory", "Allocation failed"};
constexpr std::uintmax_t kHeaderBytes = 1 << 20;  // largest header of its own a submission brings
constexpr int kHeaders = 64;                      // most headers it brings
constexpr std::uintmax_t kSourceBytes = 1 << 20;  // largest .cpp file compiled with a controller
constexpr std::size_t kCompanions = 16;           // most .cpp files compiled with a controller

// Size and modification time of a file, as text: a rebuilt file changes it.
std::string fileStamp(const std::string& path) {
  struct stat st {};
  if (path.empty() || ::stat(path.c_str(), &st) != 0) return "none";
  return std::to_string(st.st_size) + "@" + std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec);
}

// A symbol name in a loader message, demangled where it is a C++ one.
std::string demangled(std::string message) {
  const std::string marker = "undefined symbol: ";
  const std::size_t at = message.find(marker);
  if (at == std::string::npos) return message;
  const std::size_t from = at + marker.size();
  const std::string symbol = message.substr(from, message.find_first_of(" \t\n", from) - from);
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> name(abi::__cxa_demangle(symbol.c_str(), nullptr, nullptr, &status), std::free);
  if (status == 0 && name) message.replace(from, symbol.size(), name.get());
  return message + " (declared but never defined?)";
}

// The folders a compile may read: the system's, the include folders its flags name, and the
// precompiled header.
std::vector<std::string> compilerReads(const CompilerSetup& setup, bool pch) {
  std::vector<std::string> read{"/usr",     "/lib", "/lib64", "/etc/ld.so.cache", "/etc/os-release", "/etc/debian_version", "/etc/lsb-release",
                                "/dev/null"};
  for (const std::string& f : setup.flags) {
    if (f.rfind("-I", 0) == 0 && f.size() > 2) read.push_back(f.substr(2));
  }
  read.insert(read.end(), setup.reads.begin(), setup.reads.end());
  if (pch) read.push_back(setup.precompiledHeader);
  return read;
}

// A lock for compiling `module`, held by one thread at a time.
std::unique_lock<std::mutex> lockModule(const fs::path& module) {
  static std::mutex guard;
  static std::map<fs::path, std::unique_ptr<std::mutex>> locks;
  std::unique_lock<std::mutex> g(guard);
  std::unique_ptr<std::mutex>& lock = locks[module];
  if (!lock) lock = std::make_unique<std::mutex>();
  std::mutex& m = *lock;
  g.unlock();
  return std::unique_lock<std::mutex>(m);
}

// The compiler on PATH, as an absolute path for frob-sandbox.
std::string onPath(const std::string& program) {
  if (program.find('/') != std::string::npos) return program;
  for (const char* dir : {"/usr/local/bin", "/usr/bin", "/bin"}) {
    const fs::path p = fs::path(dir) / program;
    if (::access(p.c_str(), X_OK) == 0) return p.string();
  }
  return program;
}

}  // namespace

std::string compilerDescription() { return std::string(FROB_CONTROLLER_COMPILER) + " (" + FROB_CONTROLLER_COMPILER_VERSION + ")"; }

std::string sanitizerRuntime() { return FROB_CONTROLLER_SANITIZER_RUNTIME; }

CompilerSetup compilerSetup(bool checked) {
  const Layout& files = layout();
  CompilerSetup s{.compiler = FROB_CONTROLLER_COMPILER, .precompiledHeader = files.precompiledHeader.string()};
  std::stringstream flags(FROB_CONTROLLER_FLAGS);
  for (std::string f; std::getline(flags, f);) {
    if (!f.empty()) s.flags.push_back(f);
  }
  // frob's headers, seen where the precompiled header saw them (see course/run/CMakeLists.txt).
  s.flags.insert(s.flags.end(), {"-ivfsoverlay", files.headerOverlay.string(), std::string("-I") + kSdkIncludeDir});
  s.reads = {files.headerOverlay.string(), files.includeDir.string()};
  // A Task called and not awaited does nothing: Task's [[nodiscard]] says so, and here it stops the build.
  s.flags.emplace_back("-Werror=unused-result");
  // No crashing the compiler on purpose (#pragma clang __debug crash): a crash is the grader's failure.
  s.flags.insert(s.flags.end(), {"-Xclang", "-disable-pragma-debug-crash"});
  if (checked) {
    // Code that stops at its first mistake and says where: asserts on, line tables for the
    // report's stack, and -O1, at which the stack still names the student's functions.
    std::erase(s.flags, "-DNDEBUG");
    std::replace(s.flags.begin(), s.flags.end(), std::string("-O0"), std::string("-O1"));
    // DWARF 4: binutils 2.40's addr2line, which symbolizes the reports, misnames headers in clang's DWARF 5.
    s.flags.insert(s.flags.end(), {"-fsanitize=address,undefined", "-fno-sanitize-recover=all", "-fno-omit-frame-pointer", "-gline-tables-only",
                                   "-gdwarf-4", "-D_GLIBCXX_ASSERTIONS"});
    // It calls its own, checked copies of the library's inline functions, never the host's unchecked ones.
    s.flags.emplace_back("-Wl,-Bsymbolic-functions");
    s.precompiledHeader.clear();  // made with other flags
    s.checked = true;
  }
  if (const char* dir = std::getenv("FROB_CACHE_DIR"); dir != nullptr && *dir != '\0') {
    s.cacheDir = dir;
  } else if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    s.cacheDir = fs::path(xdg) / "frob";
  } else if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    s.cacheDir = fs::path(home) / ".cache" / "frob";
  } else {
    s.cacheDir = fs::temp_directory_path() / "frob-cache";
  }
  return s;
}

std::string loadError(const std::string& source, const std::string& loaderMessage) {
  if (loaderMessage.empty()) return "'" + source + "' names no controller: end it with a line FROB_CONTROLLER(yourFunction)";
  return "cannot load the controller '" + source + "': " + demangled(loaderMessage);
}

Result<LoadedController> loadInProcess(const CompiledController& compiled) {
  const std::string& source = compiled.source;
  void* handle = ::dlopen(compiled.module.c_str(), RTLD_NOW | RTLD_LOCAL);  // never closed: its code runs the controller
  if (handle == nullptr) return Status::failure(loadError(source, ::dlerror()));
  using Entry = const ControllerEntry* (*)();
  auto entry = reinterpret_cast<Entry>(::dlsym(handle, kEntrySymbol));
  if (entry == nullptr) return Status::failure(loadError(source, ""));
  return LoadedController{.entry = *entry(), .source = source, .module = compiled.module, .compiled = compiled.compiled};
}

namespace {

// The text of `file` if it is a regular file of at most `bytes`: a FIFO or a device is never opened
// for reading (it could block for ever) and, unless `followLinks`, a symbolic link is not followed
// (it could name the secret, /etc/shadow or a classmate's file); else why not.
Result<std::string> regularFileText(const fs::path& file, std::uintmax_t bytes, bool followLinks) {
  const auto refused = [&](const std::string& why) { return Status::failure("'" + file.string() + "' cannot be read: " + why); };
  const sandbox::Fd fd(::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | (followLinks ? 0 : O_NOFOLLOW)));
  struct stat st {};
  if (!fd.valid() && errno == ELOOP) return refused("it is a symbolic link, and a submission's links are never followed: submit the file itself");
  if (!fd.valid()) return refused(errno == ENOENT ? "it does not exist" : std::strerror(errno));
  if (::fstat(fd.get(), &st) != 0 || !S_ISREG(st.st_mode)) return refused("not a regular file (a folder, a FIFO or a device?)");
  if (static_cast<std::uintmax_t>(st.st_size) > bytes) return refused("larger than " + std::to_string(bytes >> 10) + " KiB");
  std::string text(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t got = 0;
  for (ssize_t n; got < text.size() && (n = ::read(fd.get(), text.data() + got, text.size() - got)) > 0;) got += static_cast<std::size_t>(n);
  text.resize(got);
  return text;
}

// The text of controller file `source`, or why it cannot be read.
Result<std::string> readControllerFile(const fs::path& source, bool followLinks) {
  Result<std::string> text = regularFileText(source, kSourceBytes, followLinks);
  if (!text) return Status::failure("controller file " + text.error());
  return text;
}

// The regular files of `dir` (not links) with one of `extensions`, by name, at most `most` of at most `bytes` each.
std::vector<fs::path> filesIn(const fs::path& dir, std::initializer_list<const char*> extensions, std::size_t most, std::uintmax_t bytes) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir.empty() ? "." : dir, ec)) {
    const std::string ext = e.path().extension().string();
    if (std::find(extensions.begin(), extensions.end(), ext) != extensions.end() && e.is_regular_file(ec) && !e.is_symlink(ec) &&
        e.file_size(ec) <= bytes)
      found.push_back(e.path());
  }
  std::sort(found.begin(), found.end());
  if (found.size() > most) found.resize(most);
  return found;
}

// The text of a file filesIn() found: "" if it has since become anything but such a file.
std::string textOf(const fs::path& file) {
  Result<std::string> text = regularFileText(file, kSourceBytes, false);
  return text ? text.value() : std::string();
}

// A file compiled with a controller, or read by its compile: its name and text.
struct Companion {
  fs::path file;
  std::string text;
};

// The headers beside `source`, and the .cpp files compiled with it.
std::vector<Companion> companionsBeside(const fs::path& source, const std::vector<fs::path>& sources) {
  std::vector<Companion> all;
  for (const fs::path& f : sources) all.push_back({f, textOf(f)});
  for (const fs::path& f : filesIn(source.parent_path(), {".h", ".hpp"}, kHeaders, kHeaderBytes)) all.push_back({f, textOf(f)});
  return all;
}

// Refuses a file of a controller named like a compiler's option or response file ("-x.cpp", "@opts.cpp").
// (They reach it as "./-x.cpp" anyway: this says what the name would have done, and how to mend it.)
Status namesNoOption(const fs::path& source, std::vector<fs::path> sources) {
  sources.push_back(source);
  for (const fs::path& f : sources) {
    const std::string name = f.filename().string();
    if (!name.starts_with('-') && !name.starts_with('@')) continue;
    return Status::failure("'" + f.string() + "': a file name that begins with '" + name.substr(0, 1) + "' would reach the compiler as " +
                           (name[0] == '-' ? "an option" : "a file of options to read (a response file)") + ": rename it");
  }
  return {};
}

std::string tooMany(const fs::path& dir, std::size_t n) {
  return "'" + dir.string() + "' holds " + std::to_string(n) + " .cpp files besides the controller; at most " + std::to_string(kCompanions) +
         " compile with it";
}

// Says once, on stderr, that the compiler stayed root because its own user could not read frob's files
// (in a folder only root may enter). (A user namespace without the id is said with the host's layers.)
void warnIfRoot(const std::vector<sandbox::Layer>& layers) {
  static std::once_flag said;
  for (const sandbox::Layer& l : layers) {
    if (l.name == "unprivileged user" && !l.applied && !l.required && ::geteuid() == 0)
      std::call_once(said, [&] { std::fprintf(stderr, "frob: warning: the compiler runs as root here: %s\n", l.note.c_str()); });
  }
}

// `text` as the compiler is given it: its messages name the file `shown` (a #line directive),
// after the byte-order mark a file may begin with.
std::string marked(const std::string& text, const fs::path& shown) {
  std::string line = "#line 1 \"";
  for (const char c : shown.string()) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f || c == '"' || c == '\\') {
      char octal[8];
      std::snprintf(octal, sizeof octal, "\\%03o", byte);
      line += octal;
    } else {
      line += c;
    }
  }
  const std::string_view bom = "\xEF\xBB\xBF";
  const bool marks = text.starts_with(bom);
  return (marks ? std::string(bom) : std::string()) + line + "\"\n" + (marks ? text.substr(bom.size()) : text);
}

// Compiles `text`, the contents of `source`, with `companions` (the .cpp files among them are
// compiled too), from copies in a folder of the compiler's own: it reads no file of the submission's,
// only these texts (what the cache knows it by), and its messages name each file as `shown` and
// Companion::file say.
Result<CompiledController> compile(const fs::path& source, const std::string& text, const std::vector<Companion>& companions, const fs::path& shown,
                                   const CompilerSetup& setup, std::string* messages) {
  // The cache key: the source and the files beside it, how it is compiled, and the headers and program it is compiled for.
  const bool pch = !setup.precompiledHeader.empty() && fs::exists(setup.precompiledHeader);
  CacheKey key;
  key.add(text).add(setup.compiler);
  key.add(std::to_string(companions.size()));
  for (const Companion& c : companions) key.add(c.file.filename().string()).add(c.text);
  key.add(std::to_string(setup.flags.size()));
  for (const std::string& f : setup.flags) key.add(f);
  key.add(pch ? fileStamp(setup.precompiledHeader) : "no pch");
  key.add(fileStamp("/proc/self/exe"));
  const std::string name = key.hex();
  const fs::path module = setup.cacheDir / (source.stem().string() + "-" + name + ".so");
  const CompiledController compiled{.module = module, .source = source.string(), .compiled = true, .checked = setup.checked};
  // The compiler's warnings are kept beside the module and shown again on every cached run.
  const fs::path warnings = fs::path(module).replace_extension(".warnings");
  const auto show = [&](const std::string& text) {
    if (messages != nullptr) {
      *messages = text;
    } else {
      std::fwrite(text.data(), 1, text.size(), stderr);
    }
  };
  // One compile of a module at a time in this process: a class of identical files compiles once.
  const std::unique_lock<std::mutex> once = lockModule(module);
  if (fs::exists(module)) {
    std::ifstream kept(warnings, std::ios::binary);
    show(std::string{std::istreambuf_iterator<char>(kept), std::istreambuf_iterator<char>()});
    return CompiledController{.module = module, .source = source.string(), .checked = setup.checked};
  }

  // A folder of the compiler's own, which its user may enter wherever frob runs from (the cache may be
  // in root's home), and the only one it may write; the module is then stored in the cache.
  std::error_code ec;
  fs::create_directories(setup.cacheDir, ec);
  if (ec) return graderFailure("cannot create the controller cache '" + setup.cacheDir.string() + "': " + ec.message());
  const fs::path temp = fs::temp_directory_path(ec);
  static std::once_flag swept;
  std::call_once(swept, [&] { removeStale(temp, "frob-compile"); });  // left by a frob that was killed while it compiled
  removeStale(fs::absolute(setup.cacheDir), "build");
  Result<Scratch> folder = Scratch::make(temp, "frob-compile");
  if (!folder) return graderFailure("cannot make a folder to compile in: " + folder.error());
  const fs::path work = folder.value().path() / "work";
  fs::permissions(folder.value().path(), fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec, ec);  // its user passes through
  if (!fs::create_directory(work, ec)) return graderFailure("cannot make " + work.string() + ": " + ec.message());
  const auto copy = [&](const fs::path& name, const std::string& bytes) {
    std::ofstream out(work / name, std::ios::binary);
    return static_cast<bool>(out << bytes << std::flush);
  };
  if (!copy(shown.filename(), marked(text, shown))) return graderFailure("cannot copy '" + source.string() + "' to compile it (a full disk?)");
  for (const Companion& c : companions) {
    if (!copy(c.file.filename(), marked(c.text, c.file))) return graderFailure("cannot copy '" + c.file.string() + "' to compile it (a full disk?)");
  }
  const fs::path partial = work / "module.so";
  SandboxedDef program{.command = {onPath(setup.compiler)},
                       .limits = {.cpuSeconds = static_cast<std::uint64_t>(setup.seconds),
                                  .memoryBytes = setup.memoryBytes,
                                  .fileBytes = setup.fileBytes,
                                  .openFiles = 256,
                                  .stackBytes = kCompilerStackBytes},
                       .namespaces = {.tasks = 64},
                       .files = {.read = compilerReads(setup, pch), .write = {work.string()}, .execute = {"/usr", "/bin"}},
                       .cwd = work.string(),
                       .env = {"PATH=/usr/bin:/bin", "TMPDIR=" + work.string()},
                       .own = {work.string()},
                       .rootIfUnreadable = true,
                       .noNetwork = true};
  program.command.insert(program.command.end(), setup.flags.begin(), setup.flags.end());
  if (pch) program.command.insert(program.command.end(), {"-include-pch", setup.precompiledHeader});
  if (*FROB_CONTROLLER_LINKER != '\0') program.command.push_back(FROB_CONTROLLER_LINKER);  // gold where there is one
  // Its debug information names the files without the folder (what a checked run's stacks show).
  program.command.push_back("-fdebug-prefix-map=" + work.string() + "=");
  // Where clang leaves its reproducer when it crashes: the one sign of a crash the source cannot
  // print (its messages may quote any line of it, "PLEASE submit a bug report" too).
  const fs::path crashReport = work / "crash";
  program.command.push_back("-fcrash-diagnostics-dir=" + crashReport.filename().string());
  // Inputs as paths ("./-x.cpp"), never options or response files.
  program.command.insert(program.command.end(), {"-shared", "-o", partial.filename().string(), "./" + shown.filename().string()});
  for (const Companion& c : companions) {
    if (c.file.extension() == ".cpp") program.command.push_back("./" + c.file.filename().string());
  }
  Result<SandboxedRun> run = runSandboxed(std::move(program), setup.seconds, 1 << 20);
  const auto cleanUp = [&] { folder = Scratch(); };
  if (!run) return cleanUp(), run.status();
  warnIfRoot(run.value().layers);
  // Students read these messages: the grader's folders (a crash prints the whole command) go by name only.
  for (const auto& [grader, alias] : {std::pair{work.string() + "/", std::string()}, std::pair{work.string(), std::string(".")},
                                      std::pair{fs::absolute(setup.cacheDir).string(), std::string("$FROB_CACHE_DIR")},
                                      std::pair{setup.precompiledHeader, std::string("frob.pch")}}) {
    for (std::size_t at = 0; !grader.empty() && (at = run.value().output.find(grader, at)) != std::string::npos; at += alias.size())
      run.value().output.replace(at, grader.size(), alias);
  }
  show(run.value().output);
  if (run.value().timedOut) {
    cleanUp();
    return Status::failure("compiling '" + source.string() + "' took longer than " + std::to_string(static_cast<int>(setup.seconds)) +
                           " s, so it was stopped (an #include or a macro that never ends?)");
  }
  const int status = run.value().status;
  // A compiler that ran into its limits of time, memory or file size failed on the submission's
  // account, however it ended: killed by the limit's signal; a "crash" in which clang names the limit
  // (words a source could print too, but only to fail itself); or one with half its memory in use (a
  // stack grown by nesting until the memory ran out). Otherwise it crashed (another signal, or it left
  // a reproducer), or could not be run: no fault of the submission's, and no grade. Its output's end,
  // where a crash is described, is kept (runSandboxed).
  const int signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  const bool reproduced = !fs::is_empty(crashReport, ec) && !ec;
  const std::string& said = run.value().output;
  const bool limited = signal == SIGXCPU || signal == SIGXFSZ || signal == SIGKILL ||
                       ((signal != 0 || reproduced) && ((setup.memoryBytes > 0 && run.value().peakMemoryBytes >= setup.memoryBytes / 2) ||
                                                        std::any_of(std::begin(kLimitWords), std::end(kLimitWords),
                                                                    [&](const char* w) { return said.find(w) != std::string::npos; })));
  const bool crashed = !limited && (signal != 0 || reproduced);
  if (crashed || (WIFEXITED(status) && WEXITSTATUS(status) == 127)) {
    cleanUp();
    return graderFailure(std::string(crashed ? "the compiler crashed" : "the compiler could not be run") + " compiling '" + source.string() + "' (" +
                         onPath(setup.compiler) + (messages != nullptr ? "; its messages follow)" : "; its messages are above)"));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    cleanUp();
    return Status::failure(
        "could not compile '" + source.string() + "' " +
        (limited ? "within the compiler's limits of time, memory and file size (" + std::to_string(setup.fileBytes >> 20) + " MB a file)"
         : messages != nullptr ? "(the compiler's messages follow)"  // the caller puts them after this line
                               : "(the compiler's messages are above)"));
  }
  if (const std::uintmax_t bytes = fs::file_size(partial, ec); ec || bytes > kModuleBytes) {
    cleanUp();
    return Status::failure("could not compile '" + source.string() + "': " +
                           (ec ? "the compiler made no module"
                               : "the compiled controller is " + std::to_string(bytes >> 20) + " MB, more than the " +
                                     std::to_string(kModuleBytes >> 20) + " MB allowed (a huge array, or a file pulled in with .incbin?)"));
  }
  // Stored through a folder in the cache, by renames: a concurrent run sees the whole module or none.
  Result<Scratch> store = Scratch::make(fs::absolute(setup.cacheDir), "build");
  if (!store) return cleanUp(), graderFailure("cannot store the compiled controller in '" + setup.cacheDir.string() + "'");
  const fs::path stored = store.value().path() / "module.so", storedWarnings = store.value().path() / "module.warnings";
  if (!run.value().output.empty()) {  // first, so that a module in the cache always has its warnings
    std::ofstream(storedWarnings, std::ios::binary) << run.value().output;
    fs::rename(storedWarnings, warnings, ec);
  }
  if (!ec) fs::copy_file(partial, stored, ec);
  if (!ec) fs::rename(stored, module, ec);
  cleanUp();
  if (ec) return graderFailure("cannot store the compiled controller in '" + module.string() + "': " + ec.message());
  return compiled;
}

}  // namespace

bool holdsController(std::string_view text) {
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    line.remove_prefix(std::min(line.size(), line.find_first_not_of(" \t")));
    constexpr std::string_view kMacro = "FROB_CONTROLLER";
    if (line.starts_with(kMacro)) {
      line.remove_prefix(kMacro.size());
      line.remove_prefix(std::min(line.size(), line.find_first_not_of(" \t")));
      if (line.starts_with('(')) return true;
    }
    at = end + 1;
  }
  return false;
}

std::vector<fs::path> companionsOf(const fs::path& source) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const fs::path& f : filesIn(source.parent_path(), {".cpp"}, SIZE_MAX, kSourceBytes)) {
    if (!fs::equivalent(f, source, ec) && !holdsController(textOf(f))) found.push_back(f);
  }
  return found;
}

Result<CompiledController> compileControllerFile(const fs::path& source, const CompilerSetup& setup, std::string* messages) {
  Result<std::string> text = readControllerFile(source, true);
  if (!text) return text.status();
  const std::vector<fs::path> sources = companionsOf(source);
  if (sources.size() > kCompanions) return Status::failure(tooMany(source.parent_path(), sources.size()));
  if (Status s = namesNoOption(source, sources); !s) return s;
  // Messages name the files as they were given.
  std::vector<Companion> companions = companionsBeside(source, sources);
  for (Companion& c : companions) c.file = source.parent_path() / c.file.filename();
  return compile(source, text.value(), companions, source, setup, messages);
}

Result<CompiledController> compileSubmission(const fs::path& submission, const CompilerSetup& setup, std::string* messages) {
  fs::path source = submission;
  std::vector<fs::path> sources;
  std::error_code ec;
  if (fs::is_symlink(submission, ec)) {
    return Status::failure("'" + submission.string() + "' is a symbolic link, and a submission's links are never followed: submit the file itself");
  }
  if (fs::is_directory(submission)) {  // a submission of several files: its one controller, and the rest
    std::vector<fs::path> controllers;
    for (const fs::path& f : filesIn(submission, {".cpp"}, SIZE_MAX, kSourceBytes)) (holdsController(textOf(f)) ? controllers : sources).push_back(f);
    if (controllers.size() != 1) {
      return Status::failure(controllers.empty() ? "none of the .cpp files of '" + submission.string() +
                                                       "' has a FROB_CONTROLLER(...) line: submit the file that holds your controller"
                                                 : std::to_string(controllers.size()) + " .cpp files of '" + submission.string() +
                                                       "' have a FROB_CONTROLLER(...) line: a submission holds one controller");
    }
    if (sources.size() > kCompanions) return Status::failure(tooMany(submission, sources.size()));
    source = controllers.front();
  }
  Result<std::string> text = readControllerFile(source, false);
  if (!text) return text.status();
  if (Status s = namesNoOption(source, sources); !s) return s;
  // Compiled as a copy, with its headers, and messages name them by name alone.
  std::vector<Companion> companions = companionsBeside(source, sources);
  for (Companion& c : companions) c.file = c.file.filename();
  return compile(submission, text.value(), companions, source.filename(), setup, messages);
}

}  // namespace frob::course
