#include "dream/lcm/lcm_url.h"

#include <cstdlib>
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

}  // namespace dream::lcm
