// frob-controller-host: runs student controllers for a grader that never lets them near its world.
// Started by frob-sandbox with its channel on fd 3 and a wake-up eventfd on fd 4; it adds its own
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
  Writer w(channel.setup());
  w.put(std::uint32_t{1});
  w.put(seccomp.name), w.put(static_cast<std::uint8_t>(seccomp.applied)), w.put(seccomp.note);
  w.put(static_cast<std::uint32_t>(argc - 1));
  std::vector<const ControllerEntry*> entries;
  for (int m = 1; m < argc; ++m) {
    header->robot = static_cast<std::uint32_t>(m - 1);
    void* handle = ::dlopen(argv[m], RTLD_NOW | RTLD_LOCAL);  // global constructors run here
    using Entry = const ControllerEntry* (*)();
    auto entry = handle == nullptr ? nullptr : reinterpret_cast<Entry>(::dlsym(handle, FROB_STRINGIFY(FROB_CONTROLLER_SYMBOL)));
    const ControllerEntry* e = entry == nullptr ? nullptr : entry();
    entries.push_back(e);
    w.put(static_cast<std::uint8_t>(e != nullptr));
    if (e == nullptr) {
      w.put(handle == nullptr ? std::string(::dlerror()) : std::string());  // empty: no FROB_CONTROLLER line
      continue;
    }
    w.put(e->name), w.put(e->options.world), w.put(e->options.seconds), w.put(e->options.summary);
  }
  return entries;
}

// Builds one controller per robot as the setup area asks.
std::vector<Driven> build(const Channel& channel, const std::vector<const ControllerEntry*>& entries) {
  header->activity = Activity::Building;
  Reader r(channel.setup());
  std::uint32_t robots = 0;
  r.count(robots, channel.header().robots);
  std::vector<Driven> driven(robots);
  for (std::uint32_t i = 0; i < robots; ++i) {
    std::uint32_t module = 0;
    RobotSpec spec;
    if (!r.get(module) || !read(r, spec) || module >= entries.size() || entries[module] == nullptr) std::_Exit(3);
    header->robot = i;
    Driven& d = driven[i];
    const Robot robot(spec, std::shared_ptr<const SensorFrame>(d.frame));
    robot.debugChannel()->timeline().observe([&d](const TaskRecord& t) { d.records.push_back(t); });
    d.controller = std::make_unique<RunningController>(entries[module]->make, robot);
  }
  return driven;
}

// Samples every robot at `now` and writes its reply.
void step(const Channel& channel, std::vector<Driven>& driven, const Instant& now, bool pictures) {
  Picture picture;
  for (std::uint32_t i = 0; i < driven.size(); ++i) {
    Driven& d = driven[i];
    Reader in(channel.frameArea(i));
    if (!read(in, *d.frame)) std::_Exit(3);
    header->robot = i;
    const bool wasFailed = d.controller->failed();
    const Wheels wheels = d.controller->step(now, pictures ? &picture : nullptr);
    const std::span<std::byte> area = channel.replyArea(i);
    Writer w(area.subspan(sizeof(std::uint32_t)));
    const bool failed = d.controller->failed() && !d.reported;
    d.reported = d.controller->failed();
    w.put(static_cast<std::uint8_t>(failed ? 1 : wasFailed ? 2 : 0));
    w.put(wheels.forward), w.put(wheels.turn);
    if (failed) w.put(d.controller->failure());
    w.put(static_cast<std::uint32_t>(d.records.size()));
    for (const TaskRecord& t : d.records) write(w, t);
    d.records.clear();
    w.put(static_cast<std::uint8_t>(pictures));
    if (pictures) write(w, picture);
    // A reply too large for its area is cut: the trusted side sees a read fail and reports it.
    const auto length = static_cast<std::uint32_t>(w.size());
    std::memcpy(area.data(), &length, sizeof length);
  }
}

}  // namespace

int main(int argc, char** argv) {
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
    waitFutex(header->request, sequence, header->spinNanoseconds);
    if (header->command == Command::Build) {
      if (!channel.attach(kChannelFd)) return 3;
      clock = Clock(header->dt);
      driven = build(channel, entries);
    } else {
      const Instant& now = header->step == 0 ? clock.now() : clock.advance();
      header->activity = Activity::Stepping;
      step(channel, driven, now, header->pictures != 0);
    }
    header->activity = Activity::Waiting;
    ring(header->reply, ++sequence, kWakeFd);
  }
}
