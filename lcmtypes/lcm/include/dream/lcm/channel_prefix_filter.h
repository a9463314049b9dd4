#pragma once

#include <linux/filter.h>

#include <string>
#include <vector>

namespace dream::lcm {

/// A classic BPF socket filter for an LCM udpm receive socket that lets
/// through only datagrams whose channel starts with one of some prefixes.
///
/// Every process on a udpm URL receives every datagram of the group, and
/// LCM's receive thread wakes up for each one only to drop what nobody in
/// the process subscribed to: an agent of a 10-robot lockstep run woke for
/// the nine other robots' commands every step, most of its CPU time
/// (docs/performance.md). The kernel drops them before they are queued.
///
/// It never drops what a subscriber could want: datagrams it cannot read a
/// channel from (LCM's fragments, which name the channel in their first
/// fragment only, and anything not in LCM's short format) all pass, and a
/// prefix only rules out channels no subscriber's regex can match.
class ChannelPrefixFilter {
 public:
  /// Prefixes are cut to this length (a shorter prefix only lets more through).
  static constexpr size_t kMaxPrefixBytes = 64;
  /// More distinct prefixes than this: no filter (the program's size is bounded).
  static constexpr size_t kMaxPrefixes = 64;

  /// The literal text every channel a whole-name ECMAScript `regex` (as LCM
  /// and LcmBus match) can match begins with: "DREAM_RADIO_" for
  /// "DREAM_RADIO_.*", the whole name for "DREAM_POSES", "" when it cannot
  /// be told (".*", alternatives, escapes, a leading group).
  static std::string LiteralPrefix(const std::string& regex);

  /// A filter passing channels that start with any of `prefixes`. It filters
  /// nothing (passes_everything()) when a prefix is empty or there are more
  /// than kMaxPrefixes different ones.
  explicit ChannelPrefixFilter(const std::vector<std::string>& prefixes);

  bool passes_everything() const { return program_.empty(); }
  /// The BPF program (empty when it passes everything).
  const std::vector<sock_filter>& program() const { return program_; }

  /// Puts the filter on the socket `fd` (or takes any filter off when it
  /// passes everything). False, with errno set, when the kernel refused.
  bool ApplyTo(int fd) const;
  /// Takes any filter off the socket `fd`.
  static void RemoveFrom(int fd);

 private:
  std::vector<sock_filter> program_;
};

}  // namespace dream::lcm
