// Starting a controller host: its scratch folder, its sealed channel, the sandbox around it, and the
// modules it loaded (host_driver.cpp drives runs with it).
#include "frob/base/layout.hpp"
#include "frob/sandbox/wire.hpp"
#include "host_impl.hpp"
#include "load_error.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>

namespace frob::course {

namespace {

constexpr std::size_t kSetupBytes = 1 << 20;
constexpr std::size_t kFrameBytes = 64 << 10;   // a frame: its sonars, bumps and keys
constexpr std::size_t kReplyBytes = 256 << 10;  // a reply: wheels, task records, a picture

// The files the dynamic loader maps for `program` (after `preload`, if any), as it lists them when
// asked to trace (what ldd shows): all a host may read of the system, with the loader's cache. Not
// /usr whole: the first read of a file whose access time is older than its change moves that time,
// a note that outlives the run for a later host (another student's) to read. Empty if the loader
// would not say.
std::vector<std::string> loadedFiles(const std::string& program, const std::string& preload) {
  static std::mutex guard;
  static std::map<std::pair<std::string, std::string>, std::vector<std::string>> known;
  const std::lock_guard<std::mutex> lock(guard);
  if (const auto k = known.find({program, preload}); k != known.end()) return k->second;
  std::vector<std::string> files;
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return files;
  sandbox::Fd read(fds[0]), write(fds[1]);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, write.get(), STDOUT_FILENO);
  std::string trace = "LD_TRACE_LOADED_OBJECTS=1", preloaded = "LD_PRELOAD=" + preload;
  std::vector<char*> env{trace.data()};
  if (!preload.empty()) env.push_back(preloaded.data());
  env.push_back(nullptr);
  std::string name = program;
  char* argv[] = {name.data(), nullptr};
  pid_t pid = 0;
  const bool spawned = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv, env.data()) == 0;
  posix_spawn_file_actions_destroy(&actions);
  write.reset();
  std::string out;
  for (char buffer[4096]; spawned;) {
    const ssize_t n = ::read(read.get(), buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    out.append(buffer, static_cast<std::size_t>(n));
  }
  int status = 0;
  pid_t reaped = -1;
  while (spawned && (reaped = ::waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
  }
  if (reaped != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return files;
  // Lines such as "libc.so.6 => /lib/x86_64-linux-gnu/libc.so.6 (0x...)" and "/lib64/ld-linux-x86-64.so.2 (0x...)".
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t at = line.find(" => /") != std::string::npos ? line.find(" => /") + 4 : line.find_first_not_of(" \t");
    const std::size_t end = line.find(" (0x", at);
    if (at != std::string::npos && end != std::string::npos && line[at] == '/') files.push_back(line.substr(at, end - at));
  }
  return known[{program, preload}] = files;
}

}  // namespace

namespace {
std::atomic<std::uint64_t> hostsStarted{0};
}  // namespace

std::uint64_t ControllerHost::started() { return hostsStarted.load(std::memory_order_relaxed); }

Result<std::shared_ptr<ControllerHost>> ControllerHost::start(const std::vector<fs::path>& modules, const std::vector<std::string>& sources,
                                                              HostDef def) {
  auto impl = std::make_unique<Impl>();
  impl->def = std::move(def);
  impl->sources = sources;
  const auto failure = [](const std::string& what) { return graderFailure("cannot start the controller host: " + what); };

  // A scratch folder of its own: a copy of each module, which it may read, and `work`, its working
  // folder and the only one it may write (a tmpfs of its own where the kernel allows), and in a
  // checked run `reports`, where the sanitizers write. Folders a killed frob left are removed first.
  std::error_code ec;
  const fs::path temp = fs::temp_directory_path(ec);
  static std::once_flag swept;
  std::call_once(swept, [&] { removeStale(temp, "frob-host"); });
  Result<Scratch> scratch = Scratch::make(temp, "frob-host");
  if (!scratch) return failure(scratch.error());
  impl->scratch = std::move(scratch.value());
  const fs::path& folder = impl->scratch.path();
  const fs::path work = folder / "work", reports = folder / "reports";
  fs::permissions(folder, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec, ec);  // nobody passes through
  std::vector<std::string> command{(impl->def.program.empty() ? layout().controllerHost : impl->def.program).string()};
  for (std::size_t m = 0; m < modules.size(); ++m) {
    const fs::path copy = folder / ("m" + std::to_string(m) + ".so");
    if (!fs::copy_file(modules[m], copy, ec)) return failure("cannot copy " + modules[m].string() + ": " + ec.message());
    fs::permissions(copy, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read, ec);
    command.push_back(copy.string());
  }
  for (const fs::path& f : {work, reports}) {
    if ((f != reports || impl->def.checked) && !fs::create_directory(f, ec)) return failure("cannot make " + f.string());
  }

  if (Status s = impl->channel.create(kSetupBytes, std::max<std::uint32_t>(impl->def.robots, 1), kFrameBytes, kReplyBytes); !s)
    return failure(s.error());
  impl->header().hostSpinNanoseconds = impl->def.hostSpinNanoseconds;
  // The wake-up is a pipe, not an object both sides hold: the grader's end is an open file of its
  // own, whose non-blocking flag nothing in the host can clear (fcntl, ioctl FIONBIO), nor can it read
  // the wake-ups meant for the grader.
  Result<sandbox::Pipe> wake = sandbox::openPipe("its wake-up pipe");
  if (!wake) return failure(wake.error());
  impl->wake = std::move(wake.value().read);
  ::fcntl(impl->wake.get(), F_SETFL, O_NONBLOCK);
  ::fcntl(wake.value().write.get(), F_SETFL, O_NONBLOCK);  // a host that rings a full pipe goes on
  Result<sandbox::Pipe> out = sandbox::openPipe("its output's pipe");
  if (!out) return failure(out.error());
  impl->output = std::move(out.value().read);
  ::fcntl(impl->output.get(), F_SETFL, O_NONBLOCK);

  const HostDef& d = impl->def;
  SandboxedDef program{.command = command,
                       .limits = {.cpuSeconds = static_cast<std::uint64_t>(std::ceil(d.runSeconds)),
                                  .memoryBytes = d.memoryBytes,
                                  .fileBytes = d.fileBytes,
                                  .openFiles = 64},
                       .namespaces = {.tasks = d.tasks, .scratch = work.string(), .scratchBytes = d.scratchBytes},
                       .files = {.read = {"/etc/ld.so.cache", folder.string()}, .write = {work.string()}},
                       .cwd = work.string(),
                       .own = {work.string()},
                       .fds = {-1, out.value().write.get(), out.value().write.get(), impl->channel.fd(), wake.value().write.get()}};
  if (d.checked) {
    // The sanitizers' runtime (unless this program has its own), reporting into their own folder.
    program.env = sanitizerEnvironment(reports);
    program.files.write.push_back(reports.string());
    program.own.push_back(reports.string());
    if (!kSanitizedBuild) {
      if (!fs::exists(sanitizerRuntime()))
        return failure("a checked controller needs clang's AddressSanitizer runtime " + sanitizerRuntime() + " (Debian package libclang-rt-16-dev)");
      program.env.push_back("LD_PRELOAD=" + sanitizerRuntime());
    }
  } else if constexpr (kSanitizedBuild) {
    // Crashes are left to the kernel so that they read as the signals they are.
    // Real stacks (no fake ones for use-after-return), so that an overflow faults next to the stack.
    program.env = {
        "ASAN_OPTIONS=detect_leaks=0:handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_abort=0:symbolize=0:"
        "detect_stack_use_after_return=0"};
  }
  // Of the system, it reads only what the loader maps for it (else, if the loader would not say, the system's folders).
  std::string preload;
  for (const std::string& e : program.env) {
    if (e.starts_with("LD_PRELOAD=")) preload = e.substr(11);
  }
  std::vector<std::string> system = loadedFiles(command.front(), preload);
  const bool listed = !system.empty();
  if (!listed) system = {"/usr", "/lib", "/lib64"};
  program.files.read.insert(program.files.read.begin(), system.begin(), system.end());
  // AddressSanitizer reserves terabytes of address space: then memory is watched by its size instead of limited.
  impl->memoryLimited = !kSanitizedBuild && !d.checked;
  if (!impl->memoryLimited) program.limits.memoryBytes = 0, program.files.read.push_back("/proc");
  Result<Sandboxed> process = Sandboxed::start(program);
  out.value().write.reset();  // the host holds its own copies
  wake.value().write.reset();
  if (!process) return process.status();  // frob's failure, never the controller's (sandboxed.hpp)
  impl->process = std::move(process.value());
  hostsStarted.fetch_add(1, std::memory_order_relaxed);
  impl->layers = impl->process.layers();
  for (sandbox::Layer& l : impl->layers) {
    if (l.name == "landlock" && !listed) l.note += "; the system's folders whole (the loader did not list the host's libraries)";
  }
  impl->runDeadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(d.runSeconds));

  // It loads the modules at once and answers what they declared.
  const auto named = [&](const std::string& why) {
    const std::uint32_t m = impl->header().robot;
    return Status::failure("the controller " + (m < sources.size() ? "'" + sources[m] + "' " : "") + "failed: " + why);
  };
  if (Status s = impl->await(1, d.startSeconds, true); !s) return isGraderFailure(s) ? s : named(s.error() + when(0.0, impl->header().activity));
  if (Status s = impl->refusal(); !s) return named(s.error() + when(0.0, Activity::Loading));
  // Its setup area is the controller's to overwrite: the answer is read from a copy, and checked.
  std::vector<std::byte> copy;
  sandbox::LoadReply reply;
  if (const Status s = sandbox::readFramed(impl->channel.setup(), copy, reply); !s || reply.modules.size() != modules.size())
    return named("its host's answer to loading was not understood" + (s ? std::string() : ": " + s.error()));
  impl->layers.push_back({reply.seccomp.name, reply.seccomp.applied, true, reply.seccomp.note});
  for (std::size_t m = 0; m < reply.modules.size(); ++m) {
    sandbox::LoadReply::Module& e = reply.modules[m];
    if (!e.loaded) return Status::failure(loadError(sources.at(m), e.error));
    impl->entries.push_back(
        {.name = std::move(e.name), .options = {.world = std::move(e.world), .seconds = e.seconds, .summary = std::move(e.summary)}});
  }
  return std::shared_ptr<ControllerHost>(new ControllerHost(std::move(impl)));
}

ControllerHost::ControllerHost(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
ControllerHost::~ControllerHost() = default;
const std::vector<ControllerEntry>& ControllerHost::entries() const { return impl_->entries; }
const std::vector<sandbox::Layer>& ControllerHost::layers() const { return impl_->layers; }

int ControllerHost::processId() const { return impl_->process.pid(); }

std::vector<std::string> ControllerHost::notes() const {
  impl_->drainOutput();
  if (impl_->outputSeen <= impl_->def.outputBytes) return {};
  return {"the controller wrote " + megabytes(impl_->outputSeen) + " to stdout and stderr; only the first " + megabytes(impl_->def.outputBytes) +
          " were shown"};
}

std::string missingLayers(const std::vector<sandbox::Layer>& layers) {
  std::string out;
  for (const sandbox::Layer& l : layers) {
    if (!l.applied && l.required) out += l.name + ": NOT applied" + (l.note.empty() ? "" : " (" + l.note + ")") + "\n";
  }
  return out;
}

Result<LoadedController> describeInHost(const CompiledController& compiled, HostDef def) {
  def.checked = def.checked || compiled.checked;
  Result<std::shared_ptr<ControllerHost>> host = ControllerHost::start({compiled.module}, {compiled.source}, std::move(def));
  if (!host) return host.status();
  return LoadedController{
      .entry = host.value()->entries().at(0), .source = compiled.source, .module = compiled.module, .compiled = compiled.compiled};
}

}  // namespace frob::course
