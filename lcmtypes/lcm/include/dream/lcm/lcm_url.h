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

/// A udpm URL (ttl=0) on a group and port drawn at random from
/// 239.255.1-254.1-254 and 20000-59999: a bus of its own for processes of
/// one run beside others (dream sweep's runs of a script), 2^31 choices.
std::string PrivateUdpmUrl();

}  // namespace dream::lcm
