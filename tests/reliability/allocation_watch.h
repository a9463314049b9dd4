#pragma once

#include <cstddef>

namespace dream::testing {

/// Records the largest single heap allocation made while one is alive (this
/// test binary replaces the global operator new to feed it), so a test can
/// say "decoding this forged message allocated no more than N bytes".
class AllocationWatch {
 public:
  AllocationWatch();
  ~AllocationWatch();
  AllocationWatch(const AllocationWatch&) = delete;
  AllocationWatch& operator=(const AllocationWatch&) = delete;

  /// The largest allocation, in bytes, since this watch started.
  size_t largest() const;

  /// Called by the replaced operator new.
  static void Saw(size_t bytes);
};

}  // namespace dream::testing
