#include "allocation_watch.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace dream::testing {
namespace {

std::atomic<bool> watching{false};
std::atomic<size_t> largest_seen{0};

}  // namespace

AllocationWatch::AllocationWatch() {
  largest_seen = 0;
  watching = true;
}

AllocationWatch::~AllocationWatch() { watching = false; }

size_t AllocationWatch::largest() const { return largest_seen; }

void AllocationWatch::Saw(size_t bytes) {
  if (!watching) return;
  size_t seen = largest_seen.load();
  while (bytes > seen && !largest_seen.compare_exchange_weak(seen, bytes)) {
  }
}

}  // namespace dream::testing

// Replaced for the whole test binary; the sized and aligned forms of delete
// fall back to these.
void* operator new(size_t bytes) {
  dream::testing::AllocationWatch::Saw(bytes);
  if (void* memory = std::malloc(bytes == 0 ? 1 : bytes)) return memory;
  throw std::bad_alloc();
}

void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, size_t) noexcept { std::free(memory); }

// The rest of the family, so every new/delete pair in the binary is this
// file's malloc/free (AddressSanitizer reports a nothrow new from its runtime
// freed by the delete above as alloc-dealloc-mismatch; std::stable_sort's
// temporary buffer does exactly that).
void* operator new(size_t bytes, const std::nothrow_t&) noexcept {
  dream::testing::AllocationWatch::Saw(bytes);
  return std::malloc(bytes == 0 ? 1 : bytes);
}
void* operator new[](size_t bytes) { return operator new(bytes); }
void* operator new[](size_t bytes, const std::nothrow_t& tag) noexcept { return operator new(bytes, tag); }
void operator delete(void* memory, const std::nothrow_t&) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete[](void* memory, size_t) noexcept { std::free(memory); }
void operator delete[](void* memory, const std::nothrow_t&) noexcept { std::free(memory); }
