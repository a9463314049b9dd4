#pragma once

#include <sys/types.h>

#include <set>
#include <string>

namespace dream::lcm {

/// Finds the socket LCM's udpm provider receives on, which LCM does not
/// hand out, so that a ChannelPrefixFilter can be put on it.
///
/// Made just before LCM opens the URL, it notes the sockets open then; once
/// LCM has subscribed (which opens its receive socket), Find() names the one
/// UDP socket opened since that is bound to the URL's port. Anything
/// uncertain (not udpm, none or several such sockets: another thread opened
/// one meanwhile) finds nothing, and the bus simply goes unfiltered.
class UdpmReceiveSocket {
 public:
  explicit UdpmReceiveSocket(const std::string& url);

  /// The receive socket's descriptor, or -1 when it cannot be told.
  int Find() const;

  /// The port of a udpm URL ("udpm://239.255.76.67:7667?ttl=0": 7667; LCM's
  /// 7667 when none is given), or -1 when `url` is not udpm or the port is bad.
  static int PortOf(const std::string& url);

 private:
  int port_ = -1;
  std::set<ino_t> sockets_before_;
};

}  // namespace dream::lcm
