#include "dream/workflows/lcm_tool_commands.h"

#include "dream/lcm/lcm_url.h"

namespace dream::workflows {

std::string LcmToolCommands::Url(const std::string& lcm_url) { return lcm::ResolveLcmUrl(lcm_url); }

std::vector<std::vector<std::string>> LcmToolCommands::Spy(const std::string& classpath, const std::string& log,
                                                           const std::string& lcm_url) {
  const std::string url = Url(lcm_url.empty() && !log.empty() ? std::string(kPrivateLogUrl) : lcm_url);
  std::vector<std::string> player;
  if (!log.empty()) player = {"lcm-logplayer", "--lcm-url=" + url, log};
  return {{"java", "-cp", classpath, "lcm.spy.Spy", "--lcm-url=" + url}, player};
}

std::vector<std::string> LcmToolCommands::Player(const std::string& lcm_jar, const std::string& log,
                                                 const std::string& url, bool paused) {
  // Debian's lcm-logplayer-gui passes -Xincgc, which Java 17 refuses: its class is started directly,
  // with the script's heap sizes. The URL goes as its own word: LogPlayer cuts `--lcm-url=URL` at every '=', which kept
  // only "udpm://...?ttl" and dropped the URL's options.
  std::vector<std::string> player = {"java",      "-Xmx64m", "-Xms32m", "-cp", lcm_jar, "lcm.logging.LogPlayer",
                                     "--lcm-url", url};
  if (paused) player.push_back("--paused");
  player.push_back(log);
  return player;
}

}  // namespace dream::workflows
