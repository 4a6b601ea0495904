// The controller host: student controllers in a sandboxed process of their own. A well-behaved
// controller drives exactly as it does in this process; a hostile one fails its robot with a reason
// a student can act on, and never the process that holds the world.
#include "frob/run/host.hpp"

#include "../../support/unloadable_program.hpp"
#include "../sandbox/hostile.hpp"
#include "frob/frob.hpp"
#include "frob/run/run_cores.hpp"
#include "frob/worlds/registry.hpp"
#include "frob/worlds/world_file.hpp"
#include "host_testing.hpp"
#include "sandbox_user.hpp"

#include <dlfcn.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

// Loads a module into this process, as `frob run` without host does.
Controller inProcess(const fs::path& module) {
  void* handle = ::dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
  EXPECT_NE(handle, nullptr) << ::dlerror();
  using Entry = const ControllerEntry* (*)();
  return reinterpret_cast<Entry>(::dlsym(handle, "frob_controller_v1"))()->make;
}

TEST(Sandbox, AWellBehavedControllerDrivesBitIdenticallyInAndOutOfTheSandbox) {
  const worlds::WorldDef world = *worlds::loadReferenceWorld("obstacles");
  const fs::path bug = testing::exampleModule("06_bug");
  worlds::Run here(world, {}, {inProcess(bug)}, {.keepSteps = false});
  here.runUntil(20.0);
  std::shared_ptr<ControllerHost> host = startHost({bug});
  ASSERT_NE(host, nullptr);
  ASSERT_EQ(host->entries().size(), 1u);
  EXPECT_EQ(host->entries()[0].name, "bugToGoal");
  EXPECT_EQ(host->entries()[0].options.world, "obstacles");
  worlds::Run there(world, {}, host->driver({0}, false), {.keepSteps = false});
  there.runUntil(20.0);
  EXPECT_TRUE(here.failures().empty());
  EXPECT_TRUE(there.failures().empty()) << there.failures()[0].message;
  EXPECT_EQ(there.recorder().count(), 2000);
  EXPECT_EQ(there.recorder().trajectoryHash(), here.recorder().trajectoryHash());
  // The task timeline comes back too: the same tasks, ended the same way at the same times.
  const std::deque<TaskRecord>& a = here.timeline(0).ended();
  const std::deque<TaskRecord>& b = there.timeline(0).ended();
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 2u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(b[k].name, a[k].name);
    EXPECT_EQ(b[k].end, a[k].end);
    EXPECT_EQ(b[k].how, a[k].how);
  }
  EXPECT_EQ(there.timeline(0).current(), here.timeline(0).current());
}

// A controller whose task has returned stands still for ever, so its host is asked only every 64
// steps (whatever it still does is checked then): the run is bit-identical to one that samples it
// at every step, and a host killed after is missed until the next time it is asked.
TEST(Sandbox, AControllerWhoseTaskReturnedIsAskedOnlyNowAndThen) {
  const worlds::WorldDef world = *worlds::loadReferenceWorld("empty");
  const fs::path visit = testing::exampleModule("04_drive_to");  // its task returns at 20.34 s
  worlds::Run here(world, {}, {inProcess(visit)}, {.keepSteps = false});
  here.runUntil(25.0);
  std::shared_ptr<ControllerHost> host = startHost({visit});
  ASSERT_NE(host, nullptr);
  worlds::Run there(world, {}, host->driver({0}, true), {.keepSteps = false});
  there.runUntil(25.0);
  EXPECT_TRUE(there.finished(0));
  EXPECT_TRUE(there.failures().empty()) << there.failures()[0].message;
  EXPECT_EQ(there.recorder().trajectoryHash(), here.recorder().trajectoryHash());
  ASSERT_EQ(::kill(host->processId(), SIGKILL), 0);
  there.runUntil(30.0);
  ASSERT_EQ(there.failures().size(), 1u);
  EXPECT_NEAR(there.failures()[0].time, 25.6, 1e-9) << there.failures()[0].message;  // step 2560, the first of 64 after
}

struct Case {
  std::string module;
  std::string reason;  // the failure's whole message
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.module; }

class Hostile : public ::testing::TestWithParam<Case> {};

TEST_P(Hostile, FailsItsRobotWithAReasonAndNothingElse) {
  const Outcome o = runHostile({GetParam().module});
  ASSERT_EQ(o.startError, "");
  ASSERT_EQ(o.failures.size(), 1u);
  EXPECT_EQ(o.failures[0].robot, 0u);
  EXPECT_EQ(o.failures[0].message, GetParam().reason);
  EXPECT_DOUBLE_EQ(o.failures[0].time, 0.5);
}

INSTANTIATE_TEST_SUITE_P(
    Sandbox, Hostile,
    ::testing::Values(
        Case{"segfault", "ada: crashed with SIGSEGV (a bad pointer, or an index out of range?) at t = 0.50 s"},
        Case{"abort", "ada: crashed with SIGABRT (abort(), a failed assert, or an exception nothing caught) at t = 0.50 s"},
        Case{"stack_overflow", "ada: crashed with SIGSEGV: its stack overflowed (a recursion that never ends?) at t = 0.50 s"},
        Case{"endless_loop", "ada: used more than 1 s of CPU in one step (an endless loop?) at t = 0.50 s"},
        Case{"sleeps", "ada: did not answer within 1 s in one step (it waited or slept) at t = 0.50 s"},
        Case{"forks", "ada: tried to start another process (not allowed) at t = 0.50 s"},
        Case{"runs_shell", "ada: tried to start another process (not allowed) at t = 0.50 s"},
        Case{"opens_socket", "ada: tried to open a network socket (not allowed) at t = 0.50 s"},
        Case{"signals_parent", "ada: tried to signal another process (not allowed) at t = 0.50 s"},
        Case{"renices_others", "ada: tried to change the scheduling, priority or limits of another process (not allowed) at t = 0.50 s"},
        Case{"repins_itself", "ada: tried to choose the cores it runs on (not allowed) at t = 0.50 s"},
        Case{"shares_memory",
             "ada: tried to make a kernel object shared between processes (System V IPC or a POSIX message queue) (not "
             "allowed) at t = 0.50 s"},
        Case{"signals_by_file", "ada: tried to ask for signals on a file (fcntl F_SETOWN, F_SETSIG or F_SETLEASE) (not allowed) at t = 0.50 s"},
        Case{"reads_outside", "ada: tried to read /etc/passwd (not allowed) at t = 0.50 s"},
        Case{"leaves_a_note_in_usr", "ada: tried to read /usr/include/stdio.h (not allowed) at t = 0.50 s"},
        Case{"writes_outside", "ada: tried to write /tmp/frob-hostile-was-here (not allowed) at t = 0.50 s"},
        Case{"forged_exit",
             "ada: ended its program with exit status 0 (a controller must not call exit; its results would "
             "not count) at t = 0.50 s"},
        Case{"throws_int", "ada: an exception of unknown type"},
        Case{"draws_too_much",
             "ada: drew a picture too large to send in one step (5 shapes, 20480 points; a step's reply holds 256 KB): draw fewer points, "
             "such as a trail of the last few seconds, at t = 0.50 s"},
        Case{"commands_nan", "ada: the controller commanded non-finite wheels {forward nan m/s, turn 0.000 rad/s} at t = 0.500 s"}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.module; });

// A host that closes its output makes the pipe poll ready for ever: the grader still waits for the
// step without spinning (so the memory and CPU watch runs on its timer), and fails it as a sleeper.
TEST(Sandbox, AHostThatClosesItsOutputIsWaitedForWithoutSpinning) {
  rusage before{}, after{};
  ::getrusage(RUSAGE_SELF, &before);
  const Outcome o = runHostile({"closes_output"});
  ::getrusage(RUSAGE_SELF, &after);
  ASSERT_EQ(o.failures.size(), 1u);
  EXPECT_EQ(o.failures[0].message, "ada: did not answer within 1 s in one step (it waited or slept) at t = 0.50 s");
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  const double cpu = seconds(after.ru_utime) - seconds(before.ru_utime) + seconds(after.ru_stime) - seconds(before.ru_stime);
  // The step's 1 s wait: a busy loop spends most of it on the CPU, a poll with a timer next to none.
  EXPECT_LT(cpu, 0.4) << "the grader spun while it waited";
}

// A value a task plots (withPlot) crosses from the host with the pictures, as it is in this process.
TEST(Sandbox, PlottedValuesComeBackWithThePictures) {
  const worlds::WorldDef world = *worlds::loadReferenceWorld("corridor");
  const fs::path module = testing::hostileModule("plots_a_value");
  std::shared_ptr<ControllerHost> host = startHost({module});
  ASSERT_NE(host, nullptr);
  worlds::Run there(world, {}, host->driver({0}, true));
  worlds::Run here(world, {}, {inProcess(module)});
  there.runUntil(0.5), here.runUntil(0.5);
  const Picture& plotted = there.recorder().steps().back().robots[0].picture;
  ASSERT_EQ(plotted.shapes().size(), 1u);
  EXPECT_EQ(plotted.shapes()[0].kind, Shape::Kind::Value);
  EXPECT_EQ(plotted.shapes()[0].text, "left");
  EXPECT_EQ(plotted.shapes()[0].value, there.recorder().steps().back().robots[0].sonar[4]);
  EXPECT_EQ(plotted, here.recorder().steps().back().robots[0].picture);
}

// The channel is sealed: cutting or growing it fails, and the grader reads on as before.
TEST(Sandbox, AHostCannotCutTheMemoryItSharesWithTheGrader) {
  const Outcome o = runHostile({"truncates_channel"});
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  EXPECT_EQ(o.lastWheels, (Wheels{0.1, 0.0}));
}

// A host that answers the protocol itself with task records past the caps fails its robot with the
// cap named, at the first such reply: the trusted side keeps nothing of it.
TEST(Sandbox, ForgedRecordsPastTheirCapsFailTheRobot) {
  const Outcome o = runHostile({"forges_records"});
  ASSERT_EQ(o.failures.size(), 1u);
  EXPECT_EQ(o.failures[0].message, "ada: its controller host sent a reply that cannot be read: a task's name longer than 256 bytes");
  EXPECT_DOUBLE_EQ(o.failures[0].time, 0.5);
}

// A host that makes the wake-up channel blocking, by either call that can, and tries to take the
// grader's wake-ups, holds no end of it the grader reads: the step that never answers fails at its
// deadline. (Were the grader's end shared with the host, the grader could block in a read for ever:
// ctest's timeout.)
TEST(Sandbox, NoFlagAHostSetsMakesTheGraderBlock) {
  for (const std::string name : {"clears_wake_flag_fcntl", "clears_wake_flag_ioctl"}) {
    const Outcome o = runHostile({name});
    EXPECT_EQ(o.output.find("took a wake-up"), std::string::npos) << name << ": " << o.output;
    ASSERT_EQ(o.failures.size(), 1u) << name;
    const std::string& why = o.failures[0].message;
    EXPECT_TRUE(why == "ada: did not answer within 1 s in one step (it waited or slept) at t = 0.50 s" ||
                why == "ada: used more than 1 s of CPU in one step (an endless loop?) at t = 0.50 s")
        << name << ": " << why;
  }
}

// A host program that cannot be run, or that dies before its first instruction, is frob's failure
// (kGraderFailure: no grade may rest on it), never the controller's; a controller that ends its
// program the same way in a global constructor is the controller's.
TEST(Sandbox, AHostProgramThatCannotStartIsTheGradersFailure) {
  const fs::path dir = fs::path(::testing::TempDir()) / "host_test_unstartable";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "not_a_program") << "#!/bin/sh\n";  // not executable
  fs::permissions(dir / "not_a_program", fs::perms::owner_read | fs::perms::owner_write | fs::perms::others_read);
  const auto start = [](const fs::path& program) {
    return ControllerHost::start({testing::hostileModule("segfault")}, {"segfault"}, {.program = program});
  };
  const Result<std::shared_ptr<ControllerHost>> missing = start(dir / "missing"), denied = start(dir / "not_a_program");
  const Result<std::shared_ptr<ControllerHost>> unloadable = start(frob::testing::unloadableProgram(dir));
  for (const Status& s : {missing.status(), denied.status(), unloadable.status()}) EXPECT_TRUE(isGraderFailure(s)) << s.error();
  EXPECT_NE(missing.error().find("No such file or directory"), std::string::npos) << missing.error();
  EXPECT_NE(denied.error().find("Permission denied"), std::string::npos) << denied.error();
  EXPECT_NE(unloadable.error().find("the controller host could not start: exit status 127: "), std::string::npos) << unloadable.error();
  EXPECT_NE(unloadable.error().find("libq.so.6"), std::string::npos) << unloadable.error();
  const Outcome own = runHostile({"exits_127_in_constructor"});
  EXPECT_EQ(own.startError,
            "the controller 'exits_127_in_constructor' failed: ended its program with exit status 127 (a controller must not call exit; its "
            "results would not count) at t = 0.00 s (in a global constructor)");
}

// What a controller prints reaches the terminal with its control characters shown, not acted on;
// a character cut across two writes arrives whole.
TEST(Sandbox, EscapeSequencesAControllerPrintsAreShownNotActedOn) {
  const Outcome o = runHostile({"prints_escapes"});
  EXPECT_EQ(o.output, "\\x1b[2J\\x1b]52;c;ZXZpbA==\\x07\\x1bPq#0\\x1b\\\\u009b31m\\x0dTotal 7 / 7 \\xe9\ncaf\xc3\xa9\n");
}

// A controller that answers each step just inside its deadline falls behind the run's pace and
// fails within seconds, not after the run's 600 s.
TEST(Sandbox, AControllerThatSleepsInEveryStepFallsBehindAndFails) {
  const Outcome o = runHostile({"sleeps_each_step"}, {.paceAllowance = 1.5});
  ASSERT_EQ(o.failures.size(), 1u);
  const std::string& why = o.failures[0].message;
  EXPECT_EQ(why.rfind("ada: fell behind: it took 2.0 s of wall-clock time for 0.52 s of simulated time", 0), 0u) << why;
  EXPECT_NE(why.find("(at most 1.5 s + 1 s per simulated second; it waited or slept?) at t = 0.52 s"), std::string::npos) << why;
  // Steps at 0.50 and 0.51 s sleep 0.9 s each; at 0.52 s the wait passes 1.5 s + 0.52 s.
  EXPECT_DOUBLE_EQ(o.failures[0].time, 0.52);
}

// Why the namespaces layer was not applied on this machine (a container that forbids user
// namespaces), or "" when it was.
// Where frob runs as root, each host runs as a user and group of its own (#48 item 6): the two robots
// of one run and a run beside them, so that none can signal, renice, re-pin or read another.
TEST(Sandbox, EveryHostRunsAsAUserOfItsOwn) {
  const fs::path module = testing::hostileModule("tells_its_user");
  Result<RobotHosts> hosts = RobotHosts::start({module}, {"tells_its_user"}, {0}, 2);
  ASSERT_TRUE(hosts.ok()) << hosts.error();
  std::shared_ptr<ControllerHost> beside = startHost({module});
  ASSERT_NE(beside, nullptr);
  worlds::Run run(room(2), {}, hosts.value().driver(false)), other(room(), {}, beside->driver({0}, false));
  run.runUntil(0.2), other.runUntil(0.2);
  std::set<long> users;
  for (const Wheels& w : {run.recorder().steps().back().robots[0].wheels, run.recorder().steps().back().robots[1].wheels,
                          other.recorder().steps().back().robots[0].wheels}) {
    const long uid = std::lround(w.forward * 1e6), gid = std::lround(w.turn * 1e6);
    if (::geteuid() != 0) {
      EXPECT_EQ(uid, ::getuid()) << "not root: every host runs as the caller";
      continue;
    }
    EXPECT_GE(uid, kFirstSandboxUid);
    EXPECT_LT(uid, kEndSandboxUid);
    EXPECT_EQ(gid, uid);
    users.insert(uid);
  }
  if (::geteuid() == 0) EXPECT_EQ(users.size(), 3u) << "three hosts at once, three users";
}

// A run gives each robot a host of its own: a global variable of one robot's controller is not
// another's (in one host, both would see two robots).
TEST(Sandbox, RobotsOfOneRunShareNoProcess) {
  const fs::path module = testing::hostileModule("shares_a_global");
  Result<RobotHosts> hosts = RobotHosts::start({module}, {"shares_a_global"}, {0}, 2);
  ASSERT_TRUE(hosts.ok()) << hosts.error();
  worlds::Run run(room(2), {}, hosts.value().driver(false));
  run.runUntil(0.5);
  EXPECT_EQ(run.recorder().steps().back().robots[0].wheels, (Wheels{0.1, 0.0}));
  EXPECT_EQ(run.recorder().steps().back().robots[1].wheels, (Wheels{0.1, 0.0}));
  EXPECT_EQ(hosts.value().layers().size(), 6u);

  std::shared_ptr<ControllerHost> one = startHost({module}, {.robots = 2});
  ASSERT_NE(one, nullptr);
  worlds::Run shared(room(2), {}, one->driver({0}, false));
  shared.runUntil(0.5);
  EXPECT_EQ(shared.recorder().steps().back().robots[1].wheels, (Wheels{0.2, 0.0}));
}

// Hosts and the grader wait for each other by spinning: where they cannot have a core each, the
// hosts are kept off the grader's (host_cores.hpp), which would otherwise make it wait for its turn.
TEST(Sandbox, HostsThatCannotHaveACoreEachLeaveTheGradersCoreToIt) {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  ASSERT_EQ(::sched_getaffinity(0, sizeof allowed, &allowed), 0);
  const int cores = CPU_COUNT(&allowed);
  const int left = cores >= 2 && cores <= 4 ? cores - 1 : cores;  // four hosts and the grader
  Result<RobotHosts> hosts = RobotHosts::start({testing::hostileModule("counts_its_cores")}, {"counts_its_cores"}, {0}, 4);
  ASSERT_TRUE(hosts.ok()) << hosts.error();
  worlds::Run run(room(4), {}, hosts.value().driver(false));
  run.runUntil(0.1);
  ASSERT_TRUE(run.failures().empty()) << run.failures()[0].message;
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(run.recorder().steps().back().robots[i].wheels.forward, 0.01 * left) << "robot " << i << ", " << cores << " cores";
}

// A run of a class holds a core of its own (run_cores.hpp): its hosts run there alone with its
// grader, sleeping while it simulates, and the grader's thread has its cores back when the hold ends.
TEST(Sandbox, TheHostsOfARunThatHoldsACoreRunOnItAlone) {
  cpu_set_t before, after;
  ASSERT_EQ(::sched_getaffinity(0, sizeof before, &before), 0);
  RunCores cores;
  {
    const RunCores::Held held = cores.take();
    // One host: left to itself, it could run on every core.
    Result<RobotHosts> hosts =
        RobotHosts::start({testing::hostileModule("counts_its_cores")}, {"counts_its_cores"}, {0}, 1, {.hostSpinNanoseconds = 0});
    ASSERT_TRUE(hosts.ok()) << hosts.error();
    worlds::Run run(room(1), {}, hosts.value().driver(false));
    run.runUntil(0.1);
    ASSERT_TRUE(run.failures().empty()) << run.failures()[0].message;
    EXPECT_EQ(run.recorder().steps().back().robots[0].wheels, (Wheels{0.01, 0.001 * (held.core() + 1)}));
  }
  ASSERT_EQ(::sched_getaffinity(0, sizeof after, &after), 0);
  EXPECT_TRUE(CPU_EQUAL(&before, &after));
}

// Saying its task returned, and then driving on, only stops the robot: it is not asked again.
TEST(Sandbox, AHostThatSaysItIsDoneStandsStillWhateverItSaysNext) {
  const Outcome o = runHostile({"claims_done"});
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  EXPECT_EQ(o.lastWheels, (Wheels{}));
}

TEST(Sandbox, ThreadsAreAllowed) {
  const Outcome o = runHostile({"starts_thread"});
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  EXPECT_EQ(o.lastWheels, (Wheels{0.2, 0.0}));
}

TEST(Sandbox, AForgedResultIsOnlyOutputAndTheRunStillFails) {
  const Outcome o = runHostile({"forged_exit"});
  EXPECT_NE(o.output.find("goal_reached"), std::string::npos);
  ASSERT_EQ(o.failures.size(), 1u);
}

TEST(Sandbox, AFloodOfOutputIsCutAtItsLimitAndTheRunGoesOn) {
  const Outcome o = runHostile({"floods_output"}, {.outputBytes = 1 << 20});
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  EXPECT_EQ(o.output.size(), 1u << 20);
  ASSERT_EQ(o.notes.size(), 1u);
  EXPECT_EQ(o.notes[0], "the controller wrote 80 MB to stdout and stderr; only the first 1 MB were shown");
}

TEST(Sandbox, AMemoryBombFailsOnItsLimit) {
  // A generous step deadline: on a crowded machine filling the memory may take more than a second.
  const Outcome o = runHostile({"memory_bomb"}, {.stepSeconds = 60, .memoryBytes = 256 << 20});
  ASSERT_EQ(o.failures.size(), 1u);
  EXPECT_NE(o.failures[0].message.find("memory"), std::string::npos) << o.failures[0].message;
}

TEST(Sandbox, AGlobalConstructorThatNeverEndsIsStopped) {
  const Outcome o = runHostile({"endless_constructor"}, {.startSeconds = 0.5});
  EXPECT_EQ(
      o.startError,
      "the controller 'endless_constructor' failed: did not finish starting within 0.5 s (an endless loop?) at t = 0.00 s (in a global constructor)");
}

TEST(Sandbox, AGlobalConstructorThatCrashesIsNamed) {
  const Outcome o = runHostile({"crash_in_constructor"});
  EXPECT_EQ(o.startError,
            "the controller 'crash_in_constructor' failed: crashed with SIGSEGV (a bad pointer, or an index out of range?) at t = 0.00 s "
            "(in a global constructor)");
}

TEST(Sandbox, AMultiRobotRunNamesTheRobotWhoseControllerFailed) {
  const Outcome o = runHostile({"starts_thread", "segfault"});
  ASSERT_EQ(o.failures.size(), 1u);
  EXPECT_EQ(o.failures[0].robot, 1u);
  EXPECT_EQ(o.failures[0].message, "bob: crashed with SIGSEGV (a bad pointer, or an index out of range?) at t = 0.50 s");
}

// A grader's container may hold less memory than the controller's limit: then the kernel's choice
// of what to kill must fall on the controller, never on frob.
TEST(Sandbox, WhenMemoryRunsShortTheKernelKillsTheControllerFirst) {
  Result<std::shared_ptr<ControllerHost>> host = ControllerHost::start({testing::hostileModule("starts_thread")}, {"t"});
  ASSERT_TRUE(host) << host.error();
  std::ifstream score("/proc/" + std::to_string(host.value()->processId()) + "/oom_score_adj");
  std::string adj;
  ASSERT_TRUE(std::getline(score, adj));
  EXPECT_EQ(adj, "1000");
}

TEST(Sandbox, TheHostDiesWithTheProcessThatStartedIt) {
  int pipeFds[2];
  ASSERT_EQ(::pipe(pipeFds), 0);
  const pid_t starter = ::fork();
  if (starter == 0) {  // starts a host, says its pid, and ends without stopping it
    Result<std::shared_ptr<ControllerHost>> host = ControllerHost::start({testing::hostileModule("starts_thread")}, {"t"});
    const int pid = host ? host.value()->processId() : -1;
    [[maybe_unused]] const ssize_t n = ::write(pipeFds[1], &pid, sizeof pid);
    ::_exit(0);
  }
  int hostPid = 0;
  ASSERT_EQ(::read(pipeFds[0], &hostPid, sizeof hostPid), static_cast<ssize_t>(sizeof hostPid));
  ASSERT_GT(hostPid, 0);
  const int pidfd = static_cast<int>(::syscall(SYS_pidfd_open, hostPid, 0));
  ::waitpid(starter, nullptr, 0);
  // Either already gone, or readable (ended) within the time the kernel takes to deliver the signal.
  if (pidfd >= 0) {
    pollfd p{pidfd, POLLIN, 0};
    EXPECT_EQ(::poll(&p, 1, 10'000), 1);
    ::close(pidfd);
  }
  ::close(pipeFds[0]), ::close(pipeFds[1]);
}

TEST(Sandbox, TheHostHoldsNoCodeOfTheWorldTheRendererOrTheGrader) {
  std::ifstream in(FROB_HOST_PATH, std::ios::binary);
  const std::string binary{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  ASSERT_GT(binary.size(), 100'000u);
  EXPECT_NE(binary.find("_ZN4frob"), std::string::npos);  // frob is there, exported to the modules
  for (const char* absent : {"_ZN4frob6worlds", "_ZN4frob6render", "_ZN4frob6course", "b2World", "OSMesa", "avcodec", "libbox2d"}) {
    EXPECT_EQ(binary.find(absent), std::string::npos) << absent;
  }
}

TEST(Sandbox, EveryLayerSaysWhetherItWasApplied) {
  const Outcome o = runHostile({"starts_thread"});
  std::vector<std::string> names;
  for (const sandbox::Layer& l : o.layers) {
    names.push_back(l.name);
    EXPECT_TRUE(l.applied || !l.note.empty()) << l.name;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"resource limits", "unprivileged user", "namespaces", "no new privileges", "landlock", "seccomp"}));
}

}  // namespace
}  // namespace frob::course
