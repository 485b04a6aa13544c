#pragma once
// Gives the memory of a large request back to the system. glibc keeps what a request frees in the
// arena of the thread that freed it: a stability sweep builds a JSON tree of a few million small nodes,
// and after eight of them on eight workers the server held 250-360 MB for good (measured: 11 MB at
// start), with or without a cap on the arenas (MALLOC_ARENA_MAX=2 held 263 MB), since the freed nodes
// lie between live ones and only the top of a heap is ever returned. Two settings fix it:
//  - malloc_trim(0) after a request that was large (it ran long or answered a large body): it walks every
//    arena and returns their free pages with madvise, wherever they lie. A trim while other requests are
//    in flight gives back less (eight concurrent sweeps, each trimming after itself, still left 49-61 MB;
//    one trim with nothing in flight then brought it to 14 MB), so the last request to leave trims again
//    when a large one finished since the last trim;
//  - a fixed mmap threshold: glibc raises its threshold to the largest block freed (up to 32 MiB), so
//    once a 6 MB answer had been freed the next ones came from the arenas; fixed at 256 KiB, every large
//    answer body is its own mapping and goes back to the system when it is freed.

#include <atomic>
#include <chrono>
#include <cstddef>

namespace softtune::http {

/// A request past either bound counts as large and is followed by a trim.
inline constexpr std::chrono::milliseconds kTrimAfterRequestTime{20};
inline constexpr std::size_t kTrimAfterBodyBytes = 256 * 1024;
/// Blocks at least this large are mapped on their own (M_MMAP_THRESHOLD), never kept in an arena.
inline constexpr std::size_t kMmapThresholdBytes = 256 * 1024;

/// Sets the allocator's mmap threshold (once per process; later calls do nothing).
void configure_allocator();

/// Counts the requests in flight and trims after large ones (see above). Thread-safe.
class MemoryRelease {
 public:
  /// A request starts.
  void enter();
  /// A request ends after `handler_time` with a body of `body_bytes`; trims when it was large, and when
  /// it is the last in flight and a large one ended since the last trim. True when it trimmed.
  bool leave(std::chrono::steady_clock::duration handler_time, std::size_t body_bytes);
  /// Trims done so far.
  std::size_t trims() const { return trims_.load(); }

 private:
  std::atomic<int> in_flight_{0};
  std::atomic<bool> pending_{false};
  std::atomic<std::size_t> trims_{0};
};

/// Returns every arena's free pages to the system now (malloc_trim(0)); the job worker calls it after
/// each job (app/job_runner.h), whose sweep freed its tree on that thread.
void trim_allocator();

/// The process's resident set size in bytes (VmRSS of /proc/self/status), 0 when unknown.
std::size_t resident_bytes();

}  // namespace softtune::http
