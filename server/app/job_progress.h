#pragma once
// What a long use case reports while it runs as a job (job_runner.h): units done of a total, and whether
// it should stop. The use cases take a JobProgress* (null: the synchronous path, nothing reported).

#include <atomic>
#include <cstddef>

namespace softtune::app {

/// A job's count of work units done of its total, and its cancel flag. Thread-safe: the worker advances
/// it, request threads read it and cancel.
class JobProgress {
 public:
  void set_total(std::size_t total) { total_.store(total); }
  /// One more unit done; false once the job is cancelled (the work stops at this point).
  bool advance() {
    done_.fetch_add(1);
    return !cancelled_.load();
  }
  void cancel() { cancelled_.store(true); }
  bool cancelled() const { return cancelled_.load(); }
  std::size_t done() const { return done_.load(); }
  std::size_t total() const { return total_.load(); }
  /// The flag cancel() sets, for a run-time limit (softtune/support/run_limit.h) that stops the work within
  /// one unit (a scene frame, a sweep case) rather than at the next advance().
  const std::atomic<bool>& cancel_flag() const { return cancelled_; }

 private:
  std::atomic<std::size_t> done_{0}, total_{0};
  std::atomic<bool> cancelled_{false};
};

/// Thrown by a job's work when it stopped because it was cancelled.
struct JobCancelled {};

}  // namespace softtune::app
