// UdpmReceiveSocket: the port of a udpm URL, and the one socket opened since
// it was made that is bound there (sockets on this process's loopback; no
// traffic is sent).
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <string>

#include "dream/lcm/udpm_receive_socket.h"

namespace dream::lcm {
namespace {

TEST(UdpmReceiveSocketTest, PortOfAUdpmUrl) {
  EXPECT_EQ(UdpmReceiveSocket::PortOf("udpm://239.255.76.67:7667?ttl=0"), 7667);
  EXPECT_EQ(UdpmReceiveSocket::PortOf("udpm://239.255.76.67:7700"), 7700);
  EXPECT_EQ(UdpmReceiveSocket::PortOf("udpm://239.255.76.67?ttl=0"), 7667);  // LCM's default
  EXPECT_EQ(UdpmReceiveSocket::PortOf("udpm://239.255.76.67:0"), -1);
  EXPECT_EQ(UdpmReceiveSocket::PortOf("udpm://239.255.76.67:99999"), -1);
  EXPECT_EQ(UdpmReceiveSocket::PortOf("udpm://239.255.76.67:76a"), -1);
  EXPECT_EQ(UdpmReceiveSocket::PortOf("udpm://239.255.76.67:?ttl=0"), -1);
  EXPECT_EQ(UdpmReceiveSocket::PortOf("memq://"), -1);
  EXPECT_EQ(UdpmReceiveSocket("memq://").Find(), -1);
}

// A UDP socket on the loopback, bound to `port` (0: any free one).
int BoundSocket(int port) {
  const int fd = socket(AF_INET, SOCK_DGRAM, 0);
  const int yes = 1;
  setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));  // as LCM's, so two can share the port
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

int PortOfSocket(int fd) {
  sockaddr_in address{};
  socklen_t length = sizeof(address);
  getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  return ntohs(address.sin_port);
}

TEST(UdpmReceiveSocketTest, FindsTheOneSocketBoundToThePortSinceAndOnlyThen) {
  const int before = BoundSocket(0);
  ASSERT_GE(before, 0);
  const int port = PortOfSocket(before);
  const std::string url = "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";

  // Opened before: not LCM's.
  const UdpmReceiveSocket already_open(url);
  EXPECT_EQ(already_open.Find(), -1);

  const UdpmReceiveSocket watcher(url);
  const int other_port = BoundSocket(0);  // new, but bound elsewhere
  const int receiver = BoundSocket(port);
  ASSERT_GE(receiver, 0);
  EXPECT_EQ(watcher.Find(), receiver);

  const int second = BoundSocket(port);  // two candidates: it cannot tell
  ASSERT_GE(second, 0);
  EXPECT_EQ(watcher.Find(), -1);

  close(second);
  close(receiver);
  close(other_port);
  close(before);
}

}  // namespace
}  // namespace dream::lcm
