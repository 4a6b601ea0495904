// frob-controller-host: runs student controllers for a grader that never lets them near its world.
// Started by frob-sandbox with its channel on fd 3 and the write end of a wake-up pipe on fd 4; it adds its own
// system-call filter, loads the controller modules named on its command line, builds one controller
// per robot as asked, then each step reads the robots' frames and answers their wheels.
#include "frob/controller.hpp"
#include "frob/sandbox/channel.hpp"
#include "frob/sandbox/layers.hpp"
#include "frob/sandbox/wire.hpp"
#include "refusals.hpp"

#include <dlfcn.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace frob;
using namespace frob::sandbox;

#define FROB_STRINGIFY2(x) #x
#define FROB_STRINGIFY(x) FROB_STRINGIFY2(x)

Header* header = nullptr;
std::uintptr_t stackTop = 0;
std::uintptr_t stackLimit = 0;

// Notes a crash's signal, and whether it hit just past the stack, before the default action kills.
void onFault(int sig, siginfo_t* info, void*) {
  const auto at = reinterpret_cast<std::uintptr_t>(info->si_addr);
  header->faultSignal = sig;
  header->stackOverflow = stackTop - at <= stackLimit + (1u << 20) && at < stackTop;
  ::signal(sig, SIG_DFL);
}

void installFaultReporter() {
  static char altStack[1 << 16];
  const stack_t ss{.ss_sp = altStack, .ss_flags = 0, .ss_size = sizeof altStack};
  ::sigaltstack(&ss, nullptr);
  int here = 0;
  stackTop = reinterpret_cast<std::uintptr_t>(&here);
  rlimit r{};
  ::getrlimit(RLIMIT_STACK, &r);
  stackLimit = r.rlim_cur == RLIM_INFINITY ? (8u << 20) : r.rlim_cur;
  struct sigaction sa {};
  sa.sa_sigaction = onFault;
  sa.sa_flags = SA_SIGINFO | SA_ONSTACK;
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) ::sigaction(sig, &sa, nullptr);
}

// One robot's controller and what it reported since the last reply.
struct Driven {
  std::shared_ptr<SensorFrame> frame = std::make_shared<SensorFrame>();
  std::unique_ptr<RunningController> controller;
  std::vector<TaskRecord> records;  // timeline starts and ends not yet sent
  bool reported = false;            // its failure has been sent
};

// Loads every module and writes what each declared (or why it could not) to the setup area.
std::vector<const ControllerEntry*> load(const Channel& channel, int argc, char** argv, const Layer& seccomp) {
  header->activity = Activity::Loading;
  LoadReply reply{.seccomp = seccomp};
  std::vector<const ControllerEntry*> entries;
  for (int m = 1; m < argc; ++m) {
    header->robot = static_cast<std::uint32_t>(m - 1);
    void* handle = ::dlopen(argv[m], RTLD_NOW | RTLD_LOCAL);  // global constructors run here
    using Entry = const ControllerEntry* (*)();
    auto entry = handle == nullptr ? nullptr : reinterpret_cast<Entry>(::dlsym(handle, FROB_STRINGIFY(FROB_CONTROLLER_SYMBOL)));
    const ControllerEntry* e = entry == nullptr ? nullptr : entry();
    entries.push_back(e);
    if (e == nullptr) {
      reply.modules.push_back({.error = handle == nullptr ? std::string(::dlerror()) : std::string()});  // empty: no FROB_CONTROLLER line
    } else {
      reply.modules.push_back(
          {.loaded = true, .name = e->name, .world = e->options.world, .summary = e->options.summary, .seconds = e->options.seconds});
    }
  }
  writeFramed(channel.setup(), reply);  // one too large for the area is cut: the trusted side reports it
  return entries;
}

// Builds one controller per robot as the setup area asks.
std::vector<Driven> build(const Channel& channel, const std::vector<const ControllerEntry*>& entries) {
  header->activity = Activity::Building;
  Reader r(channel.setup());
  BuildRequest request;
  if (!read(r, request) || request.robots.size() > channel.header().robots) std::_Exit(3);
  std::vector<Driven> driven(request.robots.size());
  for (std::uint32_t i = 0; i < driven.size(); ++i) {
    const BuildRequest::Robot& asked = request.robots[i];
    if (asked.module >= entries.size() || entries[asked.module] == nullptr) std::_Exit(3);
    header->robot = i;
    Driven& d = driven[i];
    const Robot robot(asked.spec, std::shared_ptr<const SensorFrame>(d.frame));
    robot.debugChannel()->timeline().observe([&d](const TaskRecord& t) { d.records.push_back(t); });
    d.controller = std::make_unique<RunningController>(entries[asked.module]->make, robot);
  }
  return driven;
}

// Samples every robot at `now` (its pictures too, in every run, so that a controller cannot tell a
// filmed run from a graded one) and writes its reply.
void step(const Channel& channel, std::vector<Driven>& driven, const Instant& now) {
  StepReply reply;
  for (std::uint32_t i = 0; i < driven.size(); ++i) {
    Driven& d = driven[i];
    Reader in(channel.frameArea(i));
    if (!read(in, *d.frame)) std::_Exit(3);
    header->robot = i;
    const bool wasFailed = d.controller->failed();
    reply.picture = Picture();
    reply.wheels = d.controller->step(now, &reply.picture);
    const bool failed = d.controller->failed() && !d.reported;
    d.reported = d.controller->failed();
    reply.failure = failed ? d.controller->failure() : std::string();
    // At most a step's worth of records; the rest go with the next reply.
    const std::size_t sent = std::min<std::size_t>(d.records.size(), kRecordsPerStep);
    reply.records.assign(d.records.begin(), d.records.begin() + static_cast<std::ptrdiff_t>(sent));
    d.records.erase(d.records.begin(), d.records.begin() + static_cast<std::ptrdiff_t>(sent));
    const bool done = d.controller->finished() && d.records.empty();
    reply.state = failed      ? StepReply::State::FailedNow
                  : wasFailed ? StepReply::State::FailedBefore
                  : done      ? StepReply::State::Done
                              : StepReply::State::Running;
    reply.hasPicture = true;
    if (!writeFramed(channel.replyArea(i), reply) && !wasFailed && reply.failure.empty() && !reply.picture.shapes().empty()) {
      // A picture too large for the reply fails its robot, saying so (a reply still too large without it,
      // its task records, is cut, and the trusted side reports it).
      std::size_t points = 0;
      for (const Shape& shape : reply.picture.shapes()) points += shape.points.size();
      char why[320];
      std::snprintf(why, sizeof why,
                    "drew a picture too large to send in one step (%zu shapes, %zu points; a step's reply holds %zu KB): draw fewer "
                    "points, such as a trail of the last few seconds, at t = %.2f s",
                    reply.picture.shapes().size(), points, channel.replyArea(i).size() >> 10, now.time);
      reply.picture = Picture();
      reply.state = StepReply::State::FailedNow;
      reply.failure = why;
      d.reported = true;
      writeFramed(channel.replyArea(i), reply);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  // First of all, a byte on the wake-up pipe: this program started. A host that dies without it
  // never ran a controller's code (its loader failed), which is frob's failure, not the student's.
  [[maybe_unused]] const ssize_t started = ::write(kWakeFd, "s", 1);
  Channel channel;
  if (Status s = channel.attach(kChannelFd); !s) {
    std::fprintf(stderr, "frob-controller-host: %s\n", s.error().c_str());
    return 3;
  }
  header = &channel.header();
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a student's prints arrive as they are made
  installTrapReporter(&header->trappedSyscall);
  installFaultReporter();
  noteRefusedCalls(header);
  const Layer seccomp = restrictSyscalls(SyscallPolicy::Controller);
  const std::vector<const ControllerEntry*> entries = load(channel, argc, argv, seccomp);

  std::uint32_t sequence = 1;
  header->activity = Activity::Waiting;
  ring(header->reply, sequence, kWakeFd);
  std::vector<Driven> driven;
  Clock clock(1.0);
  for (;;) {
    waitFutex(header->request, sequence, header->hostSpinNanoseconds);
    if (header->command == Command::Build) {
      clock = Clock(header->dt);
      driven = build(channel, entries);
    } else {
      // The step asked for: the next one, or a later first one (a run forked from an instant of another).
      while (clock.now().step < header->step) clock.advance();
      const Instant& now = clock.now();
      header->activity = Activity::Stepping;
      step(channel, driven, now);
    }
    header->activity = Activity::Waiting;
    ring(header->reply, ++sequence, kWakeFd);
  }
}
