// Owned file descriptors: each closed once, by its one owner, and never leaked.
#include "frob/sandbox/fd.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cerrno>

namespace frob::sandbox {
namespace {

bool isOpen(int fd) { return ::fcntl(fd, F_GETFD) != -1 || errno != EBADF; }

TEST(Fd, ClosesWhatItOwnsWhenItGoes) {
  int raw = -1;
  {
    const Fd fd(::open("/dev/null", O_RDONLY | O_CLOEXEC));
    raw = fd.get();
    ASSERT_TRUE(fd.valid());
    EXPECT_TRUE(isOpen(raw));
  }
  EXPECT_FALSE(isOpen(raw));
}

TEST(Fd, AMoveHandsOwnershipOverAndReleaseHandsItOut) {
  Fd a(::open("/dev/null", O_RDONLY | O_CLOEXEC));
  const int raw = a.get();
  Fd b = std::move(a);
  EXPECT_FALSE(a.valid());  // NOLINT(bugprone-use-after-move): a moved-from Fd holds nothing
  EXPECT_EQ(b.get(), raw);
  const int out = b.release();
  EXPECT_FALSE(b.valid());
  EXPECT_TRUE(isOpen(out));  // released: the caller closes it
  ::close(out);
}

TEST(Fd, ResetClosesTheOldOneButNotTheSameOneAgain) {
  Fd fd(::open("/dev/null", O_RDONLY | O_CLOEXEC));
  const int first = fd.get();
  fd.reset(first);  // a channel attached again on its own descriptor keeps it
  EXPECT_TRUE(isOpen(first));
  fd.reset(::open("/dev/null", O_RDONLY | O_CLOEXEC));  // opened while `first` is, so another number
  EXPECT_NE(fd.get(), first);
  EXPECT_FALSE(isOpen(first));
}

TEST(Fd, APipeHasTwoOwnedCloseOnExecEnds) {
  Result<Pipe> pipe = openPipe("test pipe");
  ASSERT_TRUE(pipe.ok()) << pipe.error();
  for (const Fd* end : {&pipe.value().read, &pipe.value().write}) {
    ASSERT_TRUE(end->valid());
    EXPECT_EQ(::fcntl(end->get(), F_GETFD) & FD_CLOEXEC, FD_CLOEXEC);
  }
  ASSERT_EQ(::write(pipe.value().write.get(), "x", 1), 1);
  char c = 0;
  EXPECT_EQ(::read(pipe.value().read.get(), &c, 1), 1);
  EXPECT_EQ(c, 'x');
}

}  // namespace
}  // namespace frob::sandbox
