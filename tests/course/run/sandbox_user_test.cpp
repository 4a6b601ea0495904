// The user ids sandboxed programs run as while frob is root: none held twice at once, in one process
// or two, and free again when released, with no process left running as them.
#include "sandbox_user.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <optional>

namespace frob::course {
namespace {

std::uint32_t take() {
  Result<SandboxUser> user = SandboxUser::take();
  EXPECT_TRUE(user.ok()) << user.error();
  return user.ok() ? user.value().uid() : 0;
}

TEST(SandboxUser, NoIdIsHeldTwiceAtOnceInOneProcessOrTwo) {
  if (::geteuid() != 0) {
    Result<SandboxUser> user = SandboxUser::take();
    ASSERT_TRUE(user.ok()) << user.error();
    EXPECT_FALSE(user.value().held()) << "only root changes the user";
    return;
  }
  Result<SandboxUser> first = SandboxUser::take(), second = SandboxUser::take();
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_GE(first.value().uid(), kFirstSandboxUid);
  EXPECT_LT(second.value().uid(), kEndSandboxUid);
  EXPECT_NE(first.value().uid(), second.value().uid());
  // Another process (a second frob) takes neither.
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    Result<SandboxUser> mine = SandboxUser::take();
    const std::uint32_t uid = mine.ok() ? mine.value().uid() : 0;
    _exit(::write(ends[1], &uid, sizeof uid) == sizeof uid ? 0 : 1);
  }
  std::uint32_t theirs = 0;
  ASSERT_EQ(::read(ends[0], &theirs, sizeof theirs), static_cast<ssize_t>(sizeof theirs));
  ::waitpid(child, nullptr, 0);
  ::close(ends[0]), ::close(ends[1]);
  EXPECT_GE(theirs, kFirstSandboxUid);
  EXPECT_NE(theirs, first.value().uid());
  EXPECT_NE(theirs, second.value().uid());
  // Released, an id is free again: the lowest free one is it or a lower one.
  const std::uint32_t freed = first.value().uid();
  first.value() = SandboxUser();
  EXPECT_LE(take(), freed);
}

// A process of the id that left its process group and session (as a daemon does) is beyond the
// group kill of its sandbox: releasing the id kills and reaps it, and every other such process.
TEST(SandboxUser, ReleasingAnIdEndsEveryProcessStillRunningAsIt) {
  if (::geteuid() != 0) GTEST_SKIP() << "only root changes the user";
  Result<SandboxUser> user = SandboxUser::take();
  ASSERT_TRUE(user.ok() && user.value().held()) << user.error();
  const std::uint32_t uid = user.value().uid();
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    if (::setgid(uid) != 0 || ::setuid(uid) != 0) _exit(2);
    const pid_t grandchild = ::fork();
    if (grandchild == 0) {
      ::setsid();
      for (;;) ::pause();
    }
    _exit(::write(ends[1], &grandchild, sizeof grandchild) == sizeof grandchild ? (::pause(), 0) : 1);
  }
  pid_t grandchild = 0;
  ASSERT_EQ(::read(ends[0], &grandchild, sizeof grandchild), static_cast<ssize_t>(sizeof grandchild));
  ::close(ends[0]), ::close(ends[1]);
  user.value() = SandboxUser();
  // Both are gone, reaped: no process of that id is left (and none is left behind by this test).
  const auto gone = [](pid_t pid) {
    if (::kill(pid, 0) != 0 && errno == ESRCH) return true;
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    return false;
  };
  EXPECT_TRUE(gone(child));
  EXPECT_TRUE(gone(grandchild)) << "the process that left its session outlived the release of its user";
}

}  // namespace
}  // namespace frob::course
