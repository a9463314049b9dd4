#pragma once

#include <string>

namespace dream::lcm {

/// LCM's own default when neither --lcm-url nor LCM_DEFAULT_URL is set.
inline constexpr const char* kLcmFallbackUrl = "udpm://239.255.76.67:7667?ttl=0";

/// Kernel receive buffer requested for udpm when the URL sets none: the
/// default 208 KB overflows when 50 agents answer a step at once.
inline constexpr int kUdpmReceiveBufferBytes = 4 * 1024 * 1024;

/// Picks the URL: `cli_url` if not empty, else $LCM_DEFAULT_URL, else
/// kLcmFallbackUrl. For udpm URLs without `recv_buf_size`, appends
/// kUdpmReceiveBufferBytes.
/// @throws std::invalid_argument if the URL has no "provider://" prefix.
std::string ResolveLcmUrl(const std::string& cli_url);

}  // namespace dream::lcm
