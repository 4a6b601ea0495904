#pragma once
// Private to frob::run: a controller host process as the trusted side holds it (its channel, output,
// scratch folder and limits) and how it waits for an answer. host.cpp starts hosts; host_driver.cpp
// drives runs with them.

#include "frob/run/host.hpp"
#include "frob/run/scratch.hpp"
#include "frob/run/terminal_text.hpp"
#include "frob/sandbox/channel.hpp"
#include "sandboxed.hpp"
#include "sanitizer_report.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>

namespace frob::course {

namespace host_detail {

using Clock = std::chrono::steady_clock;
using sandbox::Activity;

constexpr std::size_t kTailBytes = 4096;              // of the host's output kept for a checked run's report
constexpr std::chrono::milliseconds kWatchEvery{20};  // how often a waiting step's memory and CPU are looked at

inline std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

inline std::string megabytes(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MB"; }

// Where a crash happened, in words: " at t = 1.23 s", and what the host was doing when not stepping.
inline std::string when(double time, Activity activity) {
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

// How a process ended, from its wait status: "exit status 127", "signal 9 (Killed)".
inline std::string endOf(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return "signal " + std::to_string(sig) + " (" + ::strsignal(sig) + ")";
}

inline double cpuSeconds(pid_t pid) {
  clockid_t clock{};
  timespec ts{};
  if (::clock_getcpuclockid(pid, &clock) != 0 || ::clock_gettime(clock, &ts) != 0) return 0.0;
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

inline std::uint64_t residentBytes(pid_t pid) {
  std::ifstream statm("/proc/" + std::to_string(pid) + "/statm");
  std::uint64_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

}  // namespace host_detail

namespace fs = std::filesystem;
using namespace host_detail;

struct ControllerHost::Impl {
  HostDef def;
  Scratch scratch;
  sandbox::Channel channel;
  Sandboxed process;
  sandbox::Fd wake;      // read end of the pipe the host writes when it answers and we sleep; non-blocking
  bool started = false;  // the host program wrote on the wake-up pipe: it ran (a controller's code may have too)
  sandbox::Fd output;    // read end of its stdout and stderr
  std::uint64_t outputSeen = 0;
  std::string outputTail;    // the last of what it printed, where a failed assertion's message is
  std::string cutCharacter;  // the first bytes of a UTF-8 character the last read cut, shown with the rest
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
      if (n == 0) {  // the host closed its output: nothing more to read or to poll
        if (!cutCharacter.empty()) say("");
        return output.reset();
      }
      if (n < 0) return;
      const std::uint64_t room = def.outputBytes > outputSeen ? def.outputBytes - outputSeen : 0;
      const std::string_view text(buf, std::min<std::uint64_t>(room, static_cast<std::uint64_t>(n)));
      outputSeen += static_cast<std::uint64_t>(n);
      outputTail.append(buf, static_cast<std::size_t>(n));
      if (outputTail.size() > kTailBytes) outputTail.erase(0, outputTail.size() - kTailBytes);
      if (!text.empty()) say(text);
    }
  }

  // Passes on `text` as the host's output is, its control characters made visible (an escape
  // sequence would act on the terminal); a character cut by the end of a read waits for its rest.
  void say(std::string_view text) {
    std::string whole = std::exchange(cutCharacter, "") + std::string(text);
    std::size_t lead = whole.size();
    while (lead > 0 && whole.size() - lead < 3 && (static_cast<unsigned char>(whole[lead - 1]) & 0xC0) == 0x80) --lead;
    if (!text.empty() && lead > 0) {
      const auto b = static_cast<unsigned char>(whole[lead - 1]);
      const std::size_t length = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC0 ? 2 : 1;
      if (length > whole.size() - lead + 1) cutCharacter = whole.substr(lead - 1), whole.resize(lead - 1);
    }
    const std::string shown = terminalSafe(whole, true);
    if (def.output) {
      def.output(shown);
    } else {
      std::fwrite(shown.data(), 1, shown.size(), stderr);
    }
  }

  // Why the host ended, from its sanitizers' report when checked, else its wait status and what it claimed it was doing.
  std::string death(int status) {
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
      if (now >= deadline && starting && !started) {
        process.kill();
        return graderFailure("the controller host did not start within " + seconds(limit) + outputSaid());
      }
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
      if (fds[0].revents != 0) drainWake();
      if (fds[1].revents != 0) drainOutput();
      if (fds[2].revents != 0) {
        drainOutput();
        drainWake();
        if (starting && !started) return graderFailure("the controller host could not start: " + endOf(process.wait()) + outputSaid());
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

  // Empties the wake-up pipe, noting that the host program started if anything was on it.
  void drainWake() {
    char rings[1 << 16];  // a whole pipe's worth: one read empties it, however fast the host rings
    started = ::read(wake.get(), rings, sizeof rings) > 0 || started;
  }

  // What the host said before it started (its loader's complaint), after ": "; "" when nothing.
  std::string outputSaid() const {
    std::string said = outputTail;
    while (!said.empty() && (said.back() == '\n' || said.back() == ' ')) said.pop_back();
    return said.empty() ? "" : ": " + said;
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

}  // namespace frob::course
