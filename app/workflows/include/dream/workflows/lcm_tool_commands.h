#pragma once

#include <string>
#include <vector>

namespace dream::workflows {

/// The command lines of LCM's own windows that `dream spy` and `dream replay`
/// open (lcm-spy and LCM's log player, Java programs from lcm.jar), on the URL
/// every command resolves the same way (lcm::ResolveLcmUrl). The command line
/// finds and checks their files, then prints or starts these.
class LcmToolCommands {
 public:
  /// Where `dream spy --log` plays a log when no URL is given: a port of its
  /// own, loopback only (ttl=0), so it does not mix with a live run.
  static constexpr const char* kPrivateLogUrl = "udpm://239.255.76.67:7668?ttl=0";

  /// `lcm_url` when given, else $LCM_DEFAULT_URL, else LCM's default; a udpm
  /// URL without `recv_buf_size` gets DREAM's receive buffer.
  /// @throws std::invalid_argument naming a URL without "provider://".
  static std::string Url(const std::string& lcm_url);

  /// `dream spy`: {lcm-spy, player}. lcm-spy is its class started directly
  /// with `classpath` (Debian's lcm-spy script passes -Xincgc, which Java 17
  /// refuses); with a `log`, lcm-logplayer plays it (on kPrivateLogUrl unless
  /// `lcm_url` names a URL), else the player is empty.
  static std::vector<std::vector<std::string>> Spy(const std::string& classpath, const std::string& log,
                                                   const std::string& lcm_url);

  /// `dream replay`: LCM's log player window (lcm.logging.LogPlayer from
  /// `lcm_jar`, with its script's heap sizes) playing `log` on `url` (Url's),
  /// paused at its start when `paused`.
  static std::vector<std::string> Player(const std::string& lcm_jar, const std::string& log, const std::string& url,
                                         bool paused);
};

}  // namespace dream::workflows
