#include "http/memory_release.h"

#include <malloc.h>

#include <fstream>
#include <mutex>
#include <string>

namespace softtune::http {

void configure_allocator() {
  static std::once_flag once;
  std::call_once(once, [] { mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThresholdBytes)); });
}

void MemoryRelease::enter() { in_flight_.fetch_add(1); }

bool MemoryRelease::leave(std::chrono::steady_clock::duration handler_time, std::size_t body_bytes) {
  const bool large = handler_time >= kTrimAfterRequestTime || body_bytes >= kTrimAfterBodyBytes;
  if (large) pending_.store(true);
  const bool last = in_flight_.fetch_sub(1) == 1;
  if (!large && !(last && pending_.load())) return false;
  if (last) pending_.store(false);
  malloc_trim(0);
  trims_.fetch_add(1);
  return true;
}

void trim_allocator() { malloc_trim(0); }

std::size_t resident_bytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      std::size_t kib = 0;
      status >> kib;
      return kib * 1024;
    }
    status.ignore(1 << 12, '\n');
  }
  return 0;
}

}  // namespace softtune::http
