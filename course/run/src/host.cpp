#include "frob/run/host.hpp"

#include "frob/base/layout.hpp"
#include "frob/sandbox/channel.hpp"
#include "frob/sandbox/wire.hpp"
#include "load_error.hpp"
#include "sandboxed.hpp"
#include "sanitizer_report.hpp"
#include "scratch.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/eventfd.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <numeric>
#include <optional>

namespace frob::course {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using sandbox::Activity;

namespace {

constexpr std::size_t kSetupBytes = 1 << 20;
constexpr std::size_t kFrameBytes = 64 << 10;   // a frame: its sonars, bumps and keys
constexpr std::size_t kReplyBytes = 256 << 10;  // a reply: wheels, task records, a picture
constexpr std::uint32_t kNobody = 65534;
constexpr std::size_t kTailBytes = 4096;              // of the host's output kept for a checked run's report
constexpr std::chrono::milliseconds kWatchEvery{20};  // how often a waiting step's memory and CPU are looked at

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

std::string megabytes(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MB"; }

// Where a crash happened, in words: " at t = 1.23 s", and what the host was doing when not stepping.
std::string when(double time, Activity activity) {
  char at[48];
  std::snprintf(at, sizeof at, " at t = %.2f s", time);
  switch (activity) {
    case Activity::Starting:
    case Activity::Loading:
      return std::string(at) + " (in a global constructor)";
    case Activity::Building:
      return std::string(at) + " (while building its controller)";
    default:
      return at;
  }
}

double cpuSeconds(pid_t pid) {
  clockid_t clock{};
  timespec ts{};
  if (::clock_getcpuclockid(pid, &clock) != 0 || ::clock_gettime(clock, &ts) != 0) return 0.0;
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::uint64_t residentBytes(pid_t pid) {
  std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
  std::uint64_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

}  // namespace

struct ControllerHost::Impl {
  HostDef def;
  Scratch scratch;
  sandbox::Channel channel;
  Sandboxed process;
  sandbox::Fd wake;    // eventfd the host writes when it answers and we sleep
  sandbox::Fd output;  // read end of its stdout and stderr
  std::uint64_t outputSeen = 0;
  std::string outputTail;  // the last of what it printed, where a failed assertion's message is
  std::vector<std::string> sources;
  std::vector<ControllerEntry> entries;
  std::vector<sandbox::Layer> layers;
  std::uint32_t sequence = 1;  // the host's last reply
  Clock::time_point runDeadline;
  double waited = 0.0;         // seconds the grader has waited for the run's replies
  double simulated = 0.0;      // simulated seconds of the run so far
  bool memoryLimited = false;  // whether the address-space limit holds (not under AddressSanitizer)
  bool driving = false;

  ~Impl() {
    process.kill();
    process.wait();
    drainOutput();
  }

  sandbox::Header& header() const { return channel.header(); }

  // Passes on what the host printed, up to the limit.
  void drainOutput() {
    char buf[1 << 16];
    while (output.valid()) {
      const ssize_t n = ::read(output.get(), buf, sizeof buf);
      if (n == 0) return output.reset();  // the host closed its output: nothing more to read or to poll
      if (n < 0) return;
      const std::uint64_t room = def.outputBytes > outputSeen ? def.outputBytes - outputSeen : 0;
      const std::string_view text(buf, std::min<std::uint64_t>(room, static_cast<std::uint64_t>(n)));
      outputSeen += static_cast<std::uint64_t>(n);
      outputTail.append(buf, static_cast<std::size_t>(n));
      if (outputTail.size() > kTailBytes) outputTail.erase(0, outputTail.size() - kTailBytes);
      if (!text.empty()) say(text);
    }
  }

  // Passes on `text` as the host's output is.
  void say(std::string_view text) const {
    if (def.output) {
      def.output(text);
    } else {
      std::fwrite(text.data(), 1, text.size(), stderr);
    }
  }

  // Why the host ended, from its sanitizers' report when checked, else its wait status and what it claimed it was doing.
  std::string death(int status) const {
    if (def.checked) {
      if (std::optional<SanitizerFinding> f = readSanitizerReport(scratch.path() / "reports", outputTail, scratch.path())) {
        say("frob --check: " + f->reason + "\n" + f->stack);
        return f->reason;
      }
    }
    const sandbox::Header& h = header();
    if (WIFEXITED(status)) {
      return "ended its program with exit status " + std::to_string(WEXITSTATUS(status)) +
             " (a controller must not call exit; its results would not count)";
    }
    const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    switch (sig) {
      case SIGSYS:
        return "tried to " + (h.trappedSyscall >= 0 ? sandbox::describeSyscall(h.trappedSyscall) : std::string("make a forbidden system call")) +
               " (not allowed)";
      case SIGSEGV:
        return h.stackOverflow != 0 ? "crashed with SIGSEGV: its stack overflowed (a recursion that never ends?)"
                                    : "crashed with SIGSEGV (a bad pointer, or an index out of range?)";
      case SIGFPE:
        return "crashed with SIGFPE (an integer division by zero?)";
      case SIGABRT:
        return "crashed with SIGABRT (abort(), a failed assert, or an exception nothing caught)";
      case SIGXCPU:
        return "used more than " + seconds(def.runSeconds) + " of CPU in the run";
      case SIGXFSZ:
        return "wrote a file larger than " + megabytes(def.fileBytes) + " (not allowed)";
      case SIGKILL:
        return "was killed (SIGKILL): out of memory?";
      default:
        return "crashed with signal " + std::to_string(sig) + " (" + ::strsignal(sig) + ")";
    }
  }

  // Waits up to `limit` seconds for the host's reply `seq`; fails with why not (the host is then killed).
  Status await(std::uint32_t seq, double limit, bool starting) {
    sandbox::Doorbell& bell = header().reply;
    if (sandbox::spinUntil(bell, seq, def.spinNanoseconds)) return {};
    const Clock::time_point start = Clock::now();
    const auto after = [&](double seconds) { return start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds)); };
    const double paceLeft = def.paceAllowance + def.pacePerSecond * simulated - waited;
    const Clock::time_point paceDeadline = after(std::max(0.0, paceLeft));
    const Clock::time_point deadline = std::min({runDeadline, after(limit), paceDeadline});
    struct Tally {  // adds the wait to the run's, however it ends
      double& waited;
      Clock::time_point start;
      ~Tally() { waited += std::chrono::duration<double>(Clock::now() - start).count(); }
    } tally{waited, start};
    bell.sleeping.store(1, std::memory_order_seq_cst);
    std::optional<std::pair<Clock::time_point, double>> cpuFrom;  // when the step had run a while, and its CPU then
    Clock::time_point watched = start;                            // the memory and CPU watch's last look
    std::string why;
    for (;;) {
      if (bell.sequence.load(std::memory_order_seq_cst) == seq) break;
      if (channel.cut()) {
        why = "cut short the memory it shares with the grader (not allowed)";
        break;
      }
      const Clock::time_point now = Clock::now();
      if (now >= deadline) {
        // A sleeper uses next to no CPU; a loop gets its share of a core even on a crowded machine.
        const bool busy = cpuFrom && cpuSeconds(process.pid()) - cpuFrom->second > 0.1 * std::chrono::duration<double>(now - cpuFrom->first).count();
        if (deadline == runDeadline) {
          why = "the run took longer than " + seconds(def.runSeconds) + " of wall-clock time";
        } else if (deadline == paceDeadline && !starting) {
          char text[160];
          std::snprintf(text, sizeof text,
                        "fell behind: it took %.1f s of wall-clock time for %.2f s of simulated time (at most %g s + %g s per simulated second",
                        waited + std::chrono::duration<double>(now - start).count(), simulated, def.paceAllowance, def.pacePerSecond);
          why = std::string(text) + (busy ? "; an endless loop?)" : "; it waited or slept?)");
        } else if (starting) {
          why = "did not finish starting within " + seconds(limit) + (busy ? " (an endless loop?)" : " (it waited or slept)");
        } else {
          why = busy ? "used more than " + seconds(limit) + " of CPU in one step (an endless loop?)"
                     : "did not answer within " + seconds(limit) + " in one step (it waited or slept)";
        }
        break;
      }
      pollfd fds[3] = {{wake.get(), POLLIN, 0}, {output.get(), POLLIN, 0}, {process.pidfd(), POLLIN, 0}};
      const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count() + 1;
      ::poll(fds, 3, static_cast<int>(std::min<long long>(ms, 20)));
      if (fds[0].revents != 0) {
        std::uint64_t count = 0;
        [[maybe_unused]] const ssize_t n = ::read(wake.get(), &count, sizeof count);
      }
      if (fds[1].revents != 0) drainOutput();
      if (fds[2].revents != 0) {
        drainOutput();
        why = death(process.wait());
        break;
      }
      // On a timer, whatever the output pipe does (a flood, or a hang-up that polls ready for ever).
      if (const Clock::time_point t = Clock::now(); t - watched >= kWatchEvery) {
        watched = t;
        if (!cpuFrom) cpuFrom.emplace(t, cpuSeconds(process.pid()));
        if (!memoryLimited && residentBytes(process.pid()) > def.memoryBytes) {
          why = "used more than " + megabytes(def.memoryBytes) + " of memory";
          break;
        }
      }
    }
    bell.sleeping.store(0, std::memory_order_relaxed);
    if (why.empty()) return {};
    process.kill();
    return Status::failure(why);
  }

  // Fails with the file the host's refusal notes say a controller was refused, if it was.
  Status refusal() const {
    const sandbox::Header& h = header();
    if (h.deniedPath[0] == 0) return {};
    std::string path;
    for (std::size_t i = 0; i < sizeof h.deniedPath && h.deniedPath[i] != 0; ++i) {
      const char c = h.deniedPath[i];
      path += (c >= 32 && c < 127) ? c : '?';
    }
    return Status::failure(std::string("tried to ") + (h.deniedWrite != 0 ? "write " : "read ") + path + " (not allowed)");
  }
};

Result<std::shared_ptr<ControllerHost>> ControllerHost::start(const std::vector<fs::path>& modules, const std::vector<std::string>& sources,
                                                              HostDef def) {
  auto impl = std::make_unique<Impl>();
  impl->def = std::move(def);
  impl->sources = sources;
  const auto failure = [](const std::string& what) { return Status::failure("cannot start the controller host: " + what); };

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
  std::vector<std::string> command{layout().controllerHost.string()};
  for (std::size_t m = 0; m < modules.size(); ++m) {
    const fs::path copy = folder / ("m" + std::to_string(m) + ".so");
    if (!fs::copy_file(modules[m], copy, ec)) return failure("cannot copy " + modules[m].string() + ": " + ec.message());
    fs::permissions(copy, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read, ec);
    command.push_back(copy.string());
  }
  for (const fs::path& f : {work, reports}) {
    if (f == reports && !impl->def.checked) continue;
    if (!fs::create_directory(f, ec) || (::geteuid() == 0 && ::chown(f.c_str(), kNobody, kNobody) != 0))
      return failure("cannot make " + f.string() + " for nobody");
  }

  if (Status s = impl->channel.create(kSetupBytes, std::max<std::uint32_t>(impl->def.robots, 1), kFrameBytes, kReplyBytes); !s)
    return failure(s.error());
  impl->header().spinNanoseconds = impl->def.spinNanoseconds;
  impl->wake.reset(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK));
  if (!impl->wake.valid()) return failure(std::string("eventfd: ") + std::strerror(errno));
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
                       .files = {.read = {"/usr", "/lib", "/lib64", "/etc/ld.so.cache", folder.string()}, .write = {work.string()}},
                       .cwd = work.string(),
                       .fds = {-1, out.value().write.get(), out.value().write.get(), impl->channel.fd(), impl->wake.get()}};
  if (d.checked) {
    // The sanitizers' runtime (unless this program has its own), reporting into their own folder.
    program.env = sanitizerEnvironment(reports);
    program.files.write.push_back(reports.string());
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
  // AddressSanitizer reserves terabytes of address space: then memory is watched by its size instead of limited.
  impl->memoryLimited = !kSanitizedBuild && !d.checked;
  if (!impl->memoryLimited) program.limits.memoryBytes = 0, program.files.read.push_back("/proc");
  Result<Sandboxed> process = Sandboxed::start(program);
  out.value().write.reset();  // the host holds its own copy
  if (!process) return failure(process.error());
  impl->process = std::move(process.value());
  impl->layers = impl->process.layers();
  impl->runDeadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(d.runSeconds));

  // It loads the modules at once and answers what they declared.
  const auto named = [&](const std::string& why) {
    const std::uint32_t m = impl->header().robot;
    return Status::failure("the controller " + (m < sources.size() ? "'" + sources[m] + "' " : "") + "failed: " + why);
  };
  if (Status s = impl->await(1, d.startSeconds, true); !s) return named(s.error() + when(0.0, impl->header().activity));
  if (Status s = impl->refusal(); !s) return named(s.error() + when(0.0, Activity::Loading));
  std::vector<std::byte> setup(impl->channel.setup().begin(), impl->channel.setup().end());
  sandbox::Reader r(setup);
  sandbox::LoadReply reply;
  if (!sandbox::read(r, reply) || reply.modules.size() != modules.size()) {
    return failure("its answer was not understood" + (r.why().empty() ? std::string() : ": " + r.why()));
  }
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

namespace {

// Controllers sampled in the host: each step the frames go out and the replies come back. It drives
// the robots `robots` of the run (their indices in it), robot k of them with module modules[k].
class HostDriver final : public worlds::ControllerDriver {
 public:
  HostDriver(std::shared_ptr<ControllerHost> owner, ControllerHost::Impl& host, const worlds::Simulation& sim, std::vector<std::uint32_t> robots,
             const std::vector<std::size_t>& modules, bool pictures)
      : owner_(std::move(owner)),
        host_(host),
        sim_(sim),
        robots_(std::move(robots)),
        pictures_(pictures),
        timelines_(robots_.size()),
        budgets_(robots_.size()),
        stopped_(robots_.size(), false) {
    const auto n = static_cast<std::uint32_t>(robots_.size());
    FROB_ASSERT(!host.driving, "a controller host drives one run");
    FROB_ASSERT(modules.size() == 1 || modules.size() == n, "give one module per robot, or one for all");
    FROB_ASSERT(n <= std::max<std::uint32_t>(host.def.robots, 1), "a controller host drives at most the robots its HostDef names");
    host.driving = true;
    sandbox::BuildRequest request;
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::size_t m = modules.size() == 1 ? modules.front() : modules[k];
      FROB_ASSERT(m < host.entries.size(), "no such module in this host");
      request.robots.push_back({static_cast<std::uint32_t>(m), sim.spec(robots_[k])});
    }
    sandbox::Writer w(host.channel.setup());
    sandbox::write(w, request);
    FROB_ASSERT(w.ok(), "a build request larger than the channel's setup area");
    sandbox::Header& h = host.header();
    h.dt = sim.dt();
    h.command = sandbox::Command::Build;
    host.waited = 0.0;  // the run's pace counts from here: loading had its own limit
    sandbox::ring(h.request, host.sequence, -1);
    lost_ = host.await(++host.sequence, host.def.startSeconds, true);
    if (lost_) lost_ = host.refusal();
    if (!lost_) lost_ = Status::failure(lost_.error() + when(0.0, host.header().activity));
  }

  void decide(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures,
              std::vector<std::pair<std::size_t, std::string>>& failed) override {
    send(now);
    receive(now, wheels, pictures, failed);
  }

  // Hands the host its robots' frames and asks it for their wheels.
  void send(const Instant& now) {
    if (!lost_ || dead_) return;
    sandbox::Header& h = host_.header();
    for (std::uint32_t k = 0; k < robots_.size(); ++k) {
      sandbox::Writer w(host_.channel.frameArea(k));
      sandbox::write(w, sim_.frame(robots_[k]));
      FROB_ASSERT(w.ok(), "a sensor frame larger than its area of the channel");
    }
    h.command = sandbox::Command::Step;
    h.step = now.step;
    host_.simulated = now.time;
    sandbox::ring(h.request, host_.sequence, -1);
  }

  // Waits for the host's answer and takes its robots' wheels (and pictures) from it.
  void receive(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures, std::vector<std::pair<std::size_t, std::string>>& failed) {
    if (!lost_) return fail(failed, lost_.error());
    if (dead_) return;
    char at[48];
    std::snprintf(at, sizeof at, " at t = %.2f s", now.time);
    if (Status s = host_.await(++host_.sequence, host_.def.stepSeconds, false); !s) return fail(failed, s.error() + at);
    if (Status s = host_.refusal(); !s) return fail(failed, s.error() + at);
    for (std::uint32_t k = 0; k < robots_.size(); ++k) {
      if (stopped_[k]) continue;
      const std::uint32_t i = robots_[k];
      if (Status s = readReply(k, wheels[i], pictures[i], failed); !s) {
        stopped_[k] = true;
        wheels[i] = Wheels{};
        failed.emplace_back(i, "its controller host sent a reply that cannot be read: " + s.error());
      }
    }
    if (++steps_ % 64 == 0) host_.drainOutput();  // a student's prints appear as the run goes
  }

  Timeline& timeline(std::size_t i) override {
    const auto k = std::find(robots_.begin(), robots_.end(), i);
    FROB_ASSERT(k != robots_.end(), "this host does not drive that robot");
    return timelines_[static_cast<std::size_t>(k - robots_.begin())];
  }

 private:
  // The host is gone or lost: the robot it claims it was driving fails, the others stop.
  void fail(std::vector<std::pair<std::size_t, std::string>>& failed, const std::string& why) {
    const std::uint32_t k = host_.header().robot;
    failed.emplace_back(robots_[k < robots_.size() ? k : 0], why);
    stopped_.assign(stopped_.size(), true);
    lost_ = {};
    dead_ = true;
    host_.process.kill();
  }

  // Reads the reply of its robot k (robot robots_[k] of the run), checks it against the caps of a
  // step and of the run, and takes it in.
  Status readReply(std::uint32_t k, Wheels& wheels, Picture& picture, std::vector<std::pair<std::size_t, std::string>>& failed) {
    if (Status s = sandbox::readFramed(host_.channel.replyArea(k), copy_, reply_); !s) return s;
    if (Status s = budgets_[k].take(reply_); !s) return s;
    if (reply_.state == sandbox::StepReply::State::FailedNow) {
      stopped_[k] = true;
      failed.emplace_back(robots_[k], reply_.failure);
    }
    Timeline& timeline = timelines_[k];
    for (TaskRecord& t : reply_.records) {
      if (t.how == TaskEnd::Running) {
        timeline.start(t.parent, std::move(t.name), std::move(t.where), t.start);
      } else {
        timeline.end(t.id, t.end, t.how, std::move(t.detail));
      }
    }
    if (pictures_ && reply_.hasPicture) picture = std::move(reply_.picture);
    // Only the controller's own word stops it.
    wheels = reply_.state == sandbox::StepReply::State::Running && isFinite(reply_.wheels) ? reply_.wheels : Wheels{};
    return {};
  }

  std::shared_ptr<ControllerHost> owner_;
  ControllerHost::Impl& host_;
  const worlds::Simulation& sim_;
  std::vector<std::uint32_t> robots_;
  bool pictures_;
  std::vector<Timeline> timelines_;  // each numbers its tasks as the host's does: the budget checks the order
  std::vector<sandbox::RunBudget> budgets_;
  std::vector<bool> stopped_;
  Status lost_;  // why the host could not build the controllers, reported at the first step
  bool dead_ = false;
  std::int64_t steps_ = 0;
  std::vector<std::byte> copy_;
  sandbox::StepReply reply_;
};

// A host per robot: every host is handed its frame before any answer is awaited, so that they
// think at once, each on whatever core is free.
class PerRobotDriver final : public worlds::ControllerDriver {
 public:
  explicit PerRobotDriver(std::vector<std::unique_ptr<HostDriver>> drivers) : drivers_(std::move(drivers)) {}

  void decide(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures,
              std::vector<std::pair<std::size_t, std::string>>& failed) override {
    for (const auto& d : drivers_) d->send(now);
    for (const auto& d : drivers_) d->receive(now, wheels, pictures, failed);
  }

  Timeline& timeline(std::size_t i) override { return drivers_.at(i)->timeline(i); }

 private:
  std::vector<std::unique_ptr<HostDriver>> drivers_;
};

}  // namespace

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

worlds::DriverFactory ControllerHost::driver(std::vector<std::size_t> modulePerRobot, bool pictures) {
  return [self = shared_from_this(), modulePerRobot = std::move(modulePerRobot),
          pictures](const worlds::Simulation& sim) -> std::unique_ptr<worlds::ControllerDriver> {
    std::vector<std::uint32_t> all(sim.robotCount());
    std::iota(all.begin(), all.end(), 0u);
    return std::make_unique<HostDriver>(self, *self->impl_, sim, std::move(all), modulePerRobot, pictures);
  };
}

Result<RobotHosts> RobotHosts::start(const std::vector<fs::path>& modules, const std::vector<std::string>& sources,
                                     const std::vector<std::size_t>& modulePerRobot, std::size_t robots, HostDef def) {
  FROB_ASSERT(modulePerRobot.size() == 1 || modulePerRobot.size() == robots, "give one module per robot, or one for all");
  def.robots = 1;
  RobotHosts all;
  for (std::size_t i = 0; i < robots; ++i) {
    const std::size_t m = modulePerRobot.size() == 1 ? modulePerRobot.front() : modulePerRobot[i];
    Result<std::shared_ptr<ControllerHost>> host = ControllerHost::start({modules.at(m)}, {sources.at(m)}, def);
    if (!host) return host.status();
    all.hosts_.push_back(std::move(host.value()));
  }
  return all;
}

worlds::DriverFactory RobotHosts::driver(bool pictures) const {
  return [hosts = hosts_, pictures](const worlds::Simulation& sim) -> std::unique_ptr<worlds::ControllerDriver> {
    FROB_ASSERT(hosts.size() == sim.robotCount(), "these hosts were started for another number of robots");
    std::vector<std::unique_ptr<HostDriver>> drivers;
    for (std::uint32_t i = 0; i < hosts.size(); ++i) {
      drivers.push_back(std::make_unique<HostDriver>(hosts[i], *hosts[i]->impl_, sim, std::vector{i}, std::vector<std::size_t>{0}, pictures));
    }
    return std::make_unique<PerRobotDriver>(std::move(drivers));
  };
}

const std::vector<sandbox::Layer>& RobotHosts::layers() const {
  static const std::vector<sandbox::Layer> none;
  return hosts_.empty() ? none : hosts_.front()->layers();
}

std::vector<std::string> RobotHosts::notes() const {
  std::vector<std::string> all;
  for (const auto& h : hosts_) {
    for (std::string& n : h->notes()) {
      if (std::find(all.begin(), all.end(), n) == all.end()) all.push_back(std::move(n));
    }
  }
  return all;
}

}  // namespace frob::course
