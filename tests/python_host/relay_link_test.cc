// RelayLink: the frames between dream and the process hosting its Python
// controllers, which a controller gone wrong may write anything into.
#include "dream/python_host/relay_link.h"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace dream::python_host {
namespace {

struct LinkPair {
  LinkPair() {
    int fds[2];
    EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds), 0);
    ours = std::make_unique<RelayLink>(fds[0]);
    theirs = fds[1];
  }
  ~LinkPair() {
    if (theirs >= 0) ::close(theirs);
  }
  void Write(const std::string& bytes) const {
    ASSERT_EQ(::write(theirs, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
  }
  std::unique_ptr<RelayLink> ours;
  int theirs = -1;
};

std::string FrameBytes(char kind, const std::string& channel, const std::string& data) {
  std::string bytes;
  RelayLink::Encode(kind, channel, data.data(), data.size(), &bytes);
  return bytes;
}

TEST(RelayLinkTest, FramesComeThroughWholeAndInOrderHoweverTheBytesArrive) {
  LinkPair pair;
  const size_t first = FrameBytes('M', "DREAM_CMD_0", std::string("\0\1\2", 3)).size();
  const std::string two = FrameBytes('M', "DREAM_CMD_0", std::string("\0\1\2", 3)) + FrameBytes('R', "", "");
  std::vector<RelayLink::Frame> frames;
  std::string problem;
  // Byte by byte: nothing until a frame is whole.
  for (size_t i = 0; i < two.size(); ++i) {
    pair.Write(two.substr(i, 1));
    EXPECT_EQ(pair.ours->ReadAvailable(&frames, &problem), RelayLink::Read::kOpen);
    if (i + 1 < first) {
      EXPECT_TRUE(frames.empty()) << i;
    }
  }
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].kind, 'M');
  EXPECT_EQ(frames[0].channel, "DREAM_CMD_0");
  EXPECT_EQ(frames[0].data, std::string("\0\1\2", 3));
  EXPECT_EQ(frames[1].kind, 'R');
  ::close(pair.theirs);
  pair.theirs = -1;
  EXPECT_EQ(pair.ours->ReadAvailable(&frames, &problem), RelayLink::Read::kClosed);
}

TEST(RelayLinkTest, AHeaderClaimingMoreThanTheBoundsIsMalformedNotAnAllocation) {
  LinkPair pair;
  // Kind, then channel and data lengths of 4 GiB - 1 each.
  pair.Write(std::string("M\xff\xff\xff\xff\xff\xff\xff\xff", 9));
  std::vector<RelayLink::Frame> frames;
  std::string problem;
  EXPECT_EQ(pair.ours->ReadAvailable(&frames, &problem), RelayLink::Read::kMalformed);
  EXPECT_NE(problem.find("beyond the bounds"), std::string::npos) << problem;
  EXPECT_TRUE(frames.empty());

  LinkPair blocking;
  blocking.Write(std::string("M\x00\x00\x04\x01\x00\x00\x00\x00", 9));  // a channel of 1025 bytes
  RelayLink::Frame frame;
  EXPECT_THROW(blocking.ours->Receive(&frame), std::runtime_error);
}

TEST(RelayLinkTest, SendIsReceivedAndFailsOnceTheOtherSideIsGone) {
  int fds[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds), 0);
  RelayLink a(fds[0]);
  {
    RelayLink b(fds[1]);
    ASSERT_TRUE(a.Send('D', "", std::string("{\"x\":1}")));
    RelayLink::Frame frame;
    ASSERT_TRUE(b.Receive(&frame));
    EXPECT_EQ(frame.kind, 'D');
    EXPECT_EQ(frame.data, "{\"x\":1}");
  }                                                                     // b closed
  EXPECT_FALSE(a.Send('M', "DREAM_POSES", std::string(1 << 20, 'x')));  // no SIGPIPE: false
  EXPECT_FALSE(a.Send('M', std::string(RelayLink::kMaxChannelBytes + 1, 'c'), std::string()));
}

}  // namespace
}  // namespace dream::python_host
