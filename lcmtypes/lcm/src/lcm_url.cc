#include "dream/lcm/lcm_url.h"

#include <cstdlib>
#include <random>
#include <stdexcept>

namespace dream::lcm {

std::string ResolveLcmUrl(const std::string& cli_url) {
  std::string url = cli_url;
  if (url.empty()) {
    const char* env = std::getenv("LCM_DEFAULT_URL");
    url = (env != nullptr && *env != '\0') ? env : kLcmFallbackUrl;
  }
  if (url.find("://") == std::string::npos) {
    throw std::invalid_argument("LCM URL '" + url +
                                "' has no provider; use memq://, udpm://GROUP:PORT?ttl=0 or file://");
  }
  if (url.rfind("udpm://", 0) == 0 && url.find("recv_buf_size") == std::string::npos) {
    url += (url.find('?') == std::string::npos ? "?" : "&");
    url += "recv_buf_size=" + std::to_string(kUdpmReceiveBufferBytes);
  }
  return url;
}

std::string PrivateUdpmUrl() {
  std::random_device entropy;
  std::uniform_int_distribution<int> octet(1, 254);
  std::uniform_int_distribution<int> port(20000, 59999);
  const int a = octet(entropy);
  const int b = octet(entropy);
  return ResolveLcmUrl("udpm://239.255." + std::to_string(a) + "." + std::to_string(b) + ":" +
                       std::to_string(port(entropy)) + "?ttl=0");
}

}  // namespace dream::lcm
