// Starting a program under frob-sandbox: its descriptors are the ones given, and the sandbox's report
// of its layers arrives, whatever numbers the caller's descriptors have.
#include "sandboxed.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

namespace frob::course {
namespace {

// Starts echo with `fds` as its descriptors and returns the line it wrote on descriptor 1 (`out`).
std::string echoed(std::vector<int> fds, sandbox::Pipe& out) {
  const SandboxedDef def{.command = {"/usr/bin/echo", "started"},
                         .limits = {.cpuSeconds = 10, .openFiles = 32},
                         .files = {.read = {"/usr", "/lib", "/lib64", "/etc/ld.so.cache"}},
                         .cwd = "/",
                         .fds = std::move(fds)};
  Result<Sandboxed> started = Sandboxed::start(def);
  out.write.reset();
  EXPECT_TRUE(started.ok()) << started.error();
  if (!started) return "";
  EXPECT_FALSE(started.value().layers().empty());
  EXPECT_EQ(started.value().wait(), 0);
  // It has ended, so all it wrote is in the pipe: read without waiting for more (copies of the write end may be open).
  ::fcntl(out.read.get(), F_SETFL, O_NONBLOCK);
  std::string said;
  char buf[256];
  for (ssize_t n; (n = ::read(out.read.get(), buf, sizeof buf)) > 0;) said.append(buf, static_cast<std::size_t>(n));
  return said;
}

// Another thread's descriptors closed just before a start leave low numbers free: the report's pipe
// takes them, below the descriptors the program is given, and must still be the report.
TEST(Sandboxed, TheReportArrivesWhenItsPipeTakesANumberTheProgramIsGiven) {
  sandbox::Pipe out;
  {  // at 30 and up, clear of the numbers below
    Result<sandbox::Pipe> made = sandbox::openPipe("test");
    ASSERT_TRUE(made.ok());
    out.read.reset(::fcntl(made.value().read.get(), F_DUPFD_CLOEXEC, 30));
    out.write.reset(::fcntl(made.value().write.get(), F_DUPFD_CLOEXEC, 30));
  }
  // Hold every number up to 19 that is free, then free the two lowest of them: the report's pipe
  // takes those two, below the 20 descriptors the program is given.
  std::vector<sandbox::Fd> held;
  while (held.empty() || held.back().get() < 19) {
    held.emplace_back(::open("/dev/null", O_RDONLY | O_CLOEXEC));
    ASSERT_TRUE(held.back().valid());
  }
  ASSERT_GE(held.size(), 3u) << "this test's process holds most numbers below 20 already";
  held[0].reset(), held[1].reset();
  const int w = out.write.get(), null = held.back().get();
  std::vector<int> fds(20, null);
  fds[0] = -1, fds[1] = fds[2] = w;
  EXPECT_EQ(echoed(fds, out), "started\n");
}

// Descriptors given at high numbers, where copies are made on the way, arrive as themselves.
TEST(Sandboxed, DescriptorsGivenAtHighNumbersArriveAsThemselves) {
  Result<sandbox::Pipe> out = sandbox::openPipe("test");
  ASSERT_TRUE(out.ok());
  sandbox::Fd high(::fcntl(out.value().write.get(), F_DUPFD_CLOEXEC, 200));
  ASSERT_GE(high.get(), 200);
  sandbox::Fd low(::fcntl(out.value().write.get(), F_DUPFD_CLOEXEC, 0));
  EXPECT_EQ(echoed({-1, high.get(), low.get()}, out.value()), "started\n");
}

}  // namespace
}  // namespace frob::course
