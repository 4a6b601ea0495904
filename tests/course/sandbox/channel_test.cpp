// The channel between the trusted side and a host: created, grown and attached, each step
// succeeding or failing with a reason.
#include "frob/sandbox/channel.hpp"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

namespace frob::sandbox {
namespace {

TEST(Channel, TheHostSeesTheAreasTheTrustedSideMade) {
  Channel trusted;
  ASSERT_TRUE(trusted.create(1000).ok());
  ASSERT_TRUE(trusted.resize(3, 200, 300).ok());
  trusted.replyArea(2)[299] = std::byte{42};

  Channel host;
  const Status attached = host.attach(::dup(trusted.fd()));
  ASSERT_TRUE(attached.ok()) << attached.error();
  EXPECT_EQ(host.header().robots, 3u);
  EXPECT_EQ(host.setup().size(), 1000u);
  EXPECT_EQ(host.frameArea(1).size(), 200u);
  ASSERT_EQ(host.replyArea(2).size(), 300u);
  EXPECT_EQ(host.replyArea(2)[299], std::byte{42});
  // Attached again on its own descriptor (as the host does at each build), it keeps it.
  ASSERT_TRUE(host.attach(host.fd()).ok());
  EXPECT_EQ(host.replyArea(2)[299], std::byte{42});
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
