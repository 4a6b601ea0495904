#include "frob/course/controller_file.hpp"

#include "controller_setup.inc"

#include <cxxabi.h>
#include <dlfcn.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

extern char** environ;

namespace frob::course {

namespace fs = std::filesystem;

namespace {

#define FROB_STRINGIFY2(x) #x
#define FROB_STRINGIFY(x) FROB_STRINGIFY2(x)
constexpr const char* kEntrySymbol = FROB_STRINGIFY(FROB_CONTROLLER_SYMBOL);

// FNV-1a 64 over `text`, continuing from `hash`.
std::uint64_t fnv(std::uint64_t hash, std::string_view text) {
  for (unsigned char c : text) hash = (hash ^ c) * 0x100000001b3ULL;
  return hash;
}

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

// Runs `args` (args[0] on PATH) with this process's stdout and stderr; returns its exit status or an error.
Result<int> runProgram(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (int err = ::posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ); err != 0) {
    return Status::failure("cannot run the compiler '" + args[0] + "': " + std::strerror(err));
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return Status::failure(std::string("waiting for the compiler failed: ") + std::strerror(errno));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

CompilerSetup compilerSetup() {
  CompilerSetup s{.compiler = FROB_CONTROLLER_COMPILER, .precompiledHeader = FROB_CONTROLLER_PCH};
  std::stringstream flags(FROB_CONTROLLER_FLAGS);
  for (std::string f; std::getline(flags, f);) {
    if (!f.empty()) s.flags.push_back(f);
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

Result<LoadedController> loadControllerModule(const fs::path& module, const std::string& source) {
  void* handle = ::dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);  // never closed: its code runs the controller
  if (handle == nullptr) return Status::failure("cannot load the controller '" + source + "': " + demangled(::dlerror()));
  using Entry = const ControllerEntry* (*)();
  auto entry = reinterpret_cast<Entry>(::dlsym(handle, kEntrySymbol));
  if (entry == nullptr) {
    return Status::failure("'" + source + "' names no controller: end it with a line FROB_CONTROLLER(yourFunction)");
  }
  return LoadedController{.entry = *entry(), .source = source};
}

Result<LoadedController> loadControllerFile(const fs::path& source, const CompilerSetup& setup) {
  std::ifstream in(source, std::ios::binary);
  if (!in || fs::is_directory(source)) return Status::failure("controller file '" + source.string() + "' cannot be read: " + (fs::exists(source) ? "not a readable file" : "it does not exist"));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};

  // The cache key: the source, how it is compiled, and the headers and program it is compiled for.
  const bool pch = !setup.precompiledHeader.empty() && fs::exists(setup.precompiledHeader);
  std::uint64_t key = fnv(0xcbf29ce484222325ULL, text);
  key = fnv(key, setup.compiler);
  for (const std::string& f : setup.flags) key = fnv(fnv(key, "\n"), f);
  key = fnv(key, pch ? fileStamp(setup.precompiledHeader) : "no pch");
  key = fnv(key, fileStamp("/proc/self/exe"));
  char name[32];
  std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(key));
  const fs::path module = setup.cacheDir / (source.stem().string() + "-" + name + ".so");
  if (fs::exists(module)) return loadControllerModule(module, source.string());

  std::error_code ec;
  fs::create_directories(setup.cacheDir, ec);
  if (ec) return Status::failure("cannot create the controller cache '" + setup.cacheDir.string() + "': " + ec.message());
  const fs::path partial = module.string() + "." + std::to_string(::getpid()) + ".partial";
  std::vector<std::string> args{setup.compiler};
  args.insert(args.end(), setup.flags.begin(), setup.flags.end());
  if (pch) args.insert(args.end(), {"-include-pch", setup.precompiledHeader});
  args.insert(args.end(), {"-shared", "-o", partial.string(), source.string()});
  Result<int> status = runProgram(args);
  if (!status) return status.status();
  if (status.value() != 0) {
    fs::remove(partial, ec);
    return Status::failure("could not compile '" + source.string() + "' (the compiler's messages are above)");
  }
  fs::rename(partial, module, ec);  // atomic: a concurrent run sees the whole module or none
  if (ec) {
    fs::remove(partial, ec);
    return Status::failure("cannot store the compiled controller in '" + module.string() + "': " + ec.message());
  }
  Result<LoadedController> loaded = loadControllerModule(module, source.string());
  if (loaded) loaded.value().compiled = true;
  return loaded;
}

}  // namespace frob::course
