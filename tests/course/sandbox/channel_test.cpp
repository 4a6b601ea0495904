// The channel between the trusted side and a host: created, sealed and attached, each step
// succeeding or failing with a reason.
#include "frob/sandbox/channel.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

namespace frob::sandbox {
namespace {

TEST(Channel, TheHostSeesTheAreasTheTrustedSideMade) {
  Channel trusted;
  ASSERT_TRUE(trusted.create(1000, 3, 200, 300).ok());
  trusted.replyArea(2)[299] = std::byte{42};

  Channel host;
  const Status attached = host.attach(::dup(trusted.fd()));
  ASSERT_TRUE(attached.ok()) << attached.error();
  EXPECT_EQ(host.header().robots, 3u);
  EXPECT_EQ(host.setup().size(), 1000u);
  EXPECT_EQ(host.frameArea(1).size(), 200u);
  ASSERT_EQ(host.replyArea(2).size(), 300u);
  EXPECT_EQ(host.replyArea(2)[299], std::byte{42});
}

TEST(Channel, TheHostCanNeitherShrinkNorGrowIt) {
  Channel trusted;
  ASSERT_TRUE(trusted.create(1000, 1, 200, 300).ok());
  const int host = ::dup(trusted.fd());
  EXPECT_EQ(::ftruncate(host, 0), -1);
  EXPECT_EQ(errno, EPERM);
  EXPECT_EQ(::ftruncate(host, 1 << 30), -1);
  EXPECT_EQ(errno, EPERM);
  EXPECT_EQ(::fcntl(host, F_ADD_SEALS, F_SEAL_WRITE), -1);  // and cannot seal the trusted side's writes
  EXPECT_FALSE(trusted.cut());
  ::close(host);
}

TEST(Channel, AReadThatFaultsReadsZerosAndMarksTheChannelCut) {
  // A channel whose memory is cut from under it anyway, as if the seals had not held: its mapping
  // is replaced by one of an unsealed file, which then shrinks to nothing.
  Channel trusted;
  ASSERT_TRUE(trusted.create(1000, 1, 200, 300).ok());
  trusted.replyArea(0)[0] = std::byte{7};
  ASSERT_EQ(trusted.replyArea(0)[0], std::byte{7});
  const int unsealed = ::memfd_create("unsealed", MFD_CLOEXEC);
  ASSERT_GE(unsealed, 0);
  const std::size_t bytes = Channel::kHeaderBytes + 1000 + 500;
  ASSERT_EQ(::ftruncate(unsealed, static_cast<off_t>(bytes)), 0);
  void* over = ::mmap(&trusted.header(), bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_FIXED, unsealed, 0);
  ASSERT_EQ(over, static_cast<void*>(&trusted.header()));
  ASSERT_EQ(::ftruncate(unsealed, 0), 0);

  EXPECT_EQ(trusted.replyArea(0)[0], std::byte{0});  // would die of SIGBUS unguarded
  EXPECT_TRUE(trusted.cut());
  EXPECT_EQ(trusted.header().reply.sequence.load(), 0u);
  ::close(unsealed);
}

TEST(Channel, AttachingToSomethingElseFailsWithAReason) {
  const int other = ::memfd_create("not-a-channel", MFD_CLOEXEC);
  ASSERT_GE(other, 0);
  ASSERT_EQ(::ftruncate(other, Channel::kHeaderBytes), 0);
  Channel host;
  const Status s = host.attach(other);
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "the controller channel has another version");
}

TEST(Channel, AnUnmappableDescriptorFailsWithAReason) {
  Channel host;
  const Status s = host.attach(-1);
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.error().rfind("mapping the controller channel: ", 0), 0u) << s.error();
}

}  // namespace
}  // namespace frob::sandbox
