#pragma once
// Long requests as jobs: POST .../jobs queues the work and answers at once; one worker thread runs the jobs
// one after another (so jobs never take both cores beside the request threads), each reporting progress at
// its natural unit (a sweep case, a check case) through JobProgress, which also carries the cancel flag;
// finished jobs are kept for a bounded time and count. The preview pipeline (render/frame_pipeline.h) has
// its own pool, tied to its renderers and frame cache; this is the small generic runner for the JSON
// contracts (stability, check), docs/api.md "Jobs".

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/job_progress.h"

namespace softtune::app {

enum class JobState { queued, running, done, failed, cancelled };
const char* job_state_name(JobState state);

/// Bounds of one runner (docs/api.md "Jobs"; the limits table lists them).
struct JobLimits {
  std::size_t max_queued = 8;   ///< jobs waiting or running at once; one more is refused (503)
  std::size_t max_kept = 32;    ///< finished jobs kept; the oldest is forgotten first
  std::chrono::seconds keep_for{600};  ///< a finished job is forgotten this long after it ended
  /// Bytes of finished results (their JSON text) kept; past it the oldest are forgotten. Eight default
  /// sweeps kept as JSON trees held 290 MB; as text, about 8 MB each.
  std::size_t max_kept_bytes = std::size_t{64} << 20;
};

/// The runner's default bounds.
inline constexpr std::size_t kMaxQueuedJobs = 8, kMaxKeptJobs = 32;
inline constexpr std::chrono::seconds kKeepJobsFor{600};
inline constexpr std::size_t kMaxKeptJobBytes = std::size_t{64} << 20;

/// A job's id: "j" and 16 lower-case hex digits (random, so ids do not tell how many jobs ran).
inline constexpr std::size_t kJobIdLength = 17;
bool is_job_id(const std::string& id);

class JobRunner {
 public:
  /// The work: fills `progress` (set_total first) and returns the result; throws codec::Problem (the job
  /// fails with that problem), JobCancelled, or anything else (a 500 problem).
  using Work = std::function<nlohmann::json(JobProgress& progress)>;
  /// `after_job` runs on the worker after each job, its result stored and its work's memory freed (the HTTP
  /// layer gives memory back to the system there, http/memory_release.h).
  explicit JobRunner(JobLimits limits = {}, std::function<void()> after_job = {});
  ~JobRunner();  ///< cancels what runs, drops what waits, joins the worker
  JobRunner(const JobRunner&) = delete;
  JobRunner& operator=(const JobRunner&) = delete;

  /// Queues `work`; its id, or nullopt when max_queued jobs are already waiting or running.
  std::optional<std::string> submit(Work work);
  /// {"id", "state", "progress": {"done", "total", "fraction"}, "elapsed_s", "result"?, "problem"?} as JSON
  /// text (the result is kept as text and spliced in, never parsed again); nullopt for an unknown (or
  /// forgotten) id.
  std::optional<std::string> status(const std::string& id);
  /// Cancels a queued or running job (a running one stops at its next progress point); false when unknown.
  bool cancel(const std::string& id);
  /// Finished jobs kept and the bytes of their results (GET /metrics).
  std::pair<std::size_t, std::size_t> kept() const;

 private:
  struct Job {
    std::string id;
    Work work;
    JobProgress progress;
    JobState state = JobState::queued;
    std::chrono::steady_clock::time_point submitted = std::chrono::steady_clock::now(), started, ended;
    std::optional<std::string> result;  ///< the result's JSON text
    std::optional<nlohmann::json> problem;
  };
  void run();
  void forget_old();  ///< with mutex_ held
  std::string new_id();  ///< with mutex_ held

  const JobLimits limits_;
  const std::function<void()> after_job_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::map<std::string, std::shared_ptr<Job>> jobs_;
  std::deque<std::shared_ptr<Job>> queue_;
  std::deque<std::string> finished_;  ///< ids, oldest first
  std::size_t active_ = 0;            ///< queued or running
  std::size_t kept_bytes_ = 0;        ///< of the finished jobs' results
  bool stopping_ = false;
  std::uint64_t id_state_;
  std::thread worker_;
};

}  // namespace softtune::app
