#pragma once
// A limit on one piece of work while it runs, beside the estimate made before it starts (server/app
// request_cost.h): the CPU time of the thread doing it, a cancel flag (a job's DELETE) and whether the
// client that asked has gone. The caller that owns the work sets it for its thread (ScopedRunLimit); long
// loops call check_run_limit() once per unit of work (a scene frame), which throws RunStopped once the
// limit is passed, so the work ends within one unit of its limit. Without a limit set, a check costs a
// thread-local read. The clocks are read at most every kRunLimitPoll, so a check costs about 20 ns.

#include <atomic>
#include <chrono>
#include <ctime>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

namespace softtune::support {

struct RunLimit {
  double cpu_seconds = 0.0;                       ///< CPU time of the thread from the start, s (0: no limit)
  const std::atomic<bool>* cancelled = nullptr;   ///< stop once it is true
  std::function<bool()> abandoned;                ///< stop once it returns true (the client closed)
};

/// How often a check reads the clocks and asks whether the client has gone.
inline constexpr std::chrono::milliseconds kRunLimitPoll{10};

/// Thrown by check_run_limit(): why the work stopped and the CPU time it had taken, s.
struct RunStopped : std::runtime_error {
  enum class Why { budget, cancelled, abandoned };
  RunStopped(Why why, double cpu_seconds, double limit_seconds)
      : std::runtime_error(why == Why::budget      ? "the work ran past its CPU-time limit"
                           : why == Why::cancelled ? "the work was cancelled"
                                                   : "the client has gone"),
        why(why), cpu_seconds(cpu_seconds), limit_seconds(limit_seconds) {}
  Why why;
  double cpu_seconds;
  double limit_seconds;
};

/// CPU time of the calling thread, s.
inline double thread_cpu_seconds() {
  timespec t{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

namespace run_limit_detail {
struct Active {
  RunLimit limit;
  double start_cpu = 0.0;
  std::chrono::steady_clock::time_point next_poll;
  bool on = false;
};
inline thread_local Active t_active;
}  // namespace run_limit_detail

/// Sets the calling thread's limit for its lifetime (the one it replaces comes back after).
class ScopedRunLimit {
 public:
  explicit ScopedRunLimit(RunLimit limit) : saved_(std::move(run_limit_detail::t_active)) {
    run_limit_detail::Active& a = run_limit_detail::t_active;
    a.limit = std::move(limit);
    a.start_cpu = thread_cpu_seconds();
    a.next_poll = std::chrono::steady_clock::now();
    a.on = true;
  }
  ~ScopedRunLimit() { run_limit_detail::t_active = std::move(saved_); }
  ScopedRunLimit(const ScopedRunLimit&) = delete;
  ScopedRunLimit& operator=(const ScopedRunLimit&) = delete;

 private:
  run_limit_detail::Active saved_;
};

/// Throws RunStopped when the calling thread's limit is passed; does nothing without one.
inline void check_run_limit() {
  run_limit_detail::Active& a = run_limit_detail::t_active;
  if (!a.on) return;
  const auto now = std::chrono::steady_clock::now();
  if (now < a.next_poll) return;
  a.next_poll = now + kRunLimitPoll;
  const double spent = thread_cpu_seconds() - a.start_cpu;
  if (a.limit.cpu_seconds > 0.0 && spent > a.limit.cpu_seconds) {
    throw RunStopped(RunStopped::Why::budget, spent, a.limit.cpu_seconds);
  }
  if (a.limit.cancelled && a.limit.cancelled->load(std::memory_order_relaxed)) {
    throw RunStopped(RunStopped::Why::cancelled, spent, a.limit.cpu_seconds);
  }
  if (a.limit.abandoned && a.limit.abandoned()) throw RunStopped(RunStopped::Why::abandoned, spent, a.limit.cpu_seconds);
}

}  // namespace softtune::support
