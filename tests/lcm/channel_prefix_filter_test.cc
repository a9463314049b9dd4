// ChannelPrefixFilter: the literal prefixes it takes from regexes, and its BPF
// program run by the kernel on a UDP socket of this process's loopback (no
// multicast, nothing leaves the machine).
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <string>
#include <vector>

#include "dream/lcm/channel_prefix_filter.h"

namespace dream::lcm {
namespace {

TEST(ChannelPrefixFilterTest, LiteralPrefixIsWhatEveryMatchingChannelStartsWith) {
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("DREAM_POSES"), "DREAM_POSES");
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("DREAM_RADIO_.*"), "DREAM_RADIO_");
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("DREAM_CMD_[0-9]+"), "DREAM_CMD_");
  // A quantifier may remove the character before it.
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("DREAM_CMDS?"), "DREAM_CMD");
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("AB*"), "A");
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("AB{0,2}"), "A");
  // Nothing can be told: any channel may match.
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix(".*"), "");
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("DREAM_POSES|OTHER"), "");
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("(?:DREAM_POSES)"), "");
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("\\w+"), "");
  EXPECT_EQ(ChannelPrefixFilter::LiteralPrefix("^DREAM"), "");
}

TEST(ChannelPrefixFilterTest, AnEmptyPrefixOrTooManyFilterNothing) {
  EXPECT_TRUE(ChannelPrefixFilter({"DREAM_POSES", ""}).passes_everything());
  EXPECT_TRUE(ChannelPrefixFilter({}).passes_everything());
  std::vector<std::string> many;
  for (size_t i = 0; i <= ChannelPrefixFilter::kMaxPrefixes; ++i) many.push_back("CHANNEL_" + std::to_string(i));
  EXPECT_TRUE(ChannelPrefixFilter(many).passes_everything());
  many.pop_back();
  EXPECT_FALSE(ChannelPrefixFilter(many).passes_everything());
}

// LCM's short datagram: "LC02", a sequence number, the channel, NUL, the payload.
std::string ShortDatagram(const std::string& channel, const std::string& payload = "payload") {
  return std::string("LC02") + std::string("\0\0\0\1", 4) + channel + std::string(1, '\0') + payload;
}

class LoopbackSocket {
 public:
  LoopbackSocket() {
    receiver_ = socket(AF_INET, SOCK_DGRAM, 0);
    sender_ = socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof(address);
    if (bind(receiver_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 ||
        getsockname(receiver_, reinterpret_cast<sockaddr*>(&address_), &length) != 0) {
      ADD_FAILURE() << "cannot bind a UDP socket on the loopback";
    }
  }
  ~LoopbackSocket() {
    close(receiver_);
    close(sender_);
  }
  int receiver() const { return receiver_; }
  void Send(const std::string& datagram) const {
    ASSERT_EQ(sendto(sender_, datagram.data(), datagram.size(), 0, reinterpret_cast<const sockaddr*>(&address_),
                     sizeof(address_)),
              static_cast<ssize_t>(datagram.size()));
  }
  // Every datagram received up to and including `marker` (sent last: datagrams on one socket keep their order).
  std::vector<std::string> ReceiveUntil(const std::string& marker) const {
    std::vector<std::string> received;
    while (received.empty() || received.back() != marker) {
      pollfd ready{receiver_, POLLIN, 0};
      // Only bounds a failure: the marker was sent, and it passes every filter here.
      if (poll(&ready, 1, 30000) != 1) {
        ADD_FAILURE() << "the marker never arrived";
        break;
      }
      char buffer[2048];
      const ssize_t size = recv(receiver_, buffer, sizeof(buffer), 0);
      if (size < 0) break;
      received.emplace_back(buffer, static_cast<size_t>(size));
    }
    return received;
  }

 private:
  int receiver_ = -1;
  int sender_ = -1;
  sockaddr_in address_{};
};

TEST(ChannelPrefixFilterTest, TheKernelDropsOnlyChannelsNoPrefixStarts) {
  LoopbackSocket socket;
  // "AB" sorts before the long prefix: its datagrams are shorter than the
  // long prefix needs, and must still be let through by their own.
  const ChannelPrefixFilter filter({"DREAM_POSES", "DREAM_RADIO_", "AB"});
  ASSERT_TRUE(filter.ApplyTo(socket.receiver())) << "the kernel refused the program";

  const std::string fragment = std::string("LC03") + std::string(16, '\0') + "DREAM_CMD_1";
  const std::vector<std::string> kept = {
      ShortDatagram("DREAM_POSES"),
      ShortDatagram("DREAM_RADIO_3"),
      ShortDatagram("DREAM_RADIO_12", ""),
      ShortDatagram("AB", ""),
      ShortDatagram("DREAM_POSES_AND_MORE"),
      fragment,  // fragments are LCM's to judge
      std::string("not LCM at all"),
  };
  const std::vector<std::string> dropped = {
      ShortDatagram("DREAM_CMD_3"),  ShortDatagram("DREAM_POSE"),  ShortDatagram("A", ""),
      ShortDatagram("DREAM_STATUS"), ShortDatagram("dream_poses"),
  };
  for (size_t i = 0; i < kept.size() || i < dropped.size(); ++i) {
    if (i < dropped.size()) socket.Send(dropped[i]);
    if (i < kept.size()) socket.Send(kept[i]);
  }
  const std::string marker = ShortDatagram("DREAM_POSES", "marker");
  socket.Send(marker);
  std::vector<std::string> expected = kept;
  expected.push_back(marker);
  EXPECT_EQ(socket.ReceiveUntil(marker), expected);

  // Taken off, everything passes again.
  ChannelPrefixFilter::RemoveFrom(socket.receiver());
  socket.Send(ShortDatagram("DREAM_CMD_3"));
  socket.Send(marker);
  EXPECT_EQ(socket.ReceiveUntil(marker), (std::vector<std::string>{ShortDatagram("DREAM_CMD_3"), marker}));
}

}  // namespace
}  // namespace dream::lcm
