#include "app/job_runner.h"

#include <algorithm>
#include <cstdio>
#include <random>

#include "app/budgets.h"
#include "codec/problem.h"
#include "softtune/support/run_limit.h"
#include "softtune/support/sanitizer_build.h"

namespace softtune::app {

using nlohmann::json;

const char* job_state_name(JobState state) {
  switch (state) {
    case JobState::queued: return "queued";
    case JobState::running: return "running";
    case JobState::done: return "done";
    case JobState::failed: return "failed";
    case JobState::cancelled: return "cancelled";
  }
  return "failed";
}

bool is_job_id(const std::string& id) {
  if (id.size() != kJobIdLength || id[0] != 'j') return false;
  for (std::size_t i = 1; i < id.size(); ++i) {
    const char c = id[i];
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

JobRunner::JobRunner(JobLimits limits, std::function<void()> after_job)
    : limits_(limits), after_job_(std::move(after_job)), id_state_(std::random_device{}() ^ (std::uint64_t{std::random_device{}()} << 32)) {
  worker_ = std::thread([this] { run(); });
}

JobRunner::~JobRunner() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    for (auto& entry : jobs_) entry.second->progress.cancel();
  }
  wake_.notify_all();
  worker_.join();
}

std::string JobRunner::new_id() {
  // splitmix64 (Steele, Lea, Flood 2014) over a random seed: distinct ids, not guessable from each other's order.
  for (;;) {
    std::uint64_t z = (id_state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    char text[kJobIdLength + 1];
    std::snprintf(text, sizeof text, "j%016llx", static_cast<unsigned long long>(z));
    if (!jobs_.contains(text)) return text;
  }
}

void JobRunner::forget_old() {
  const auto now = std::chrono::steady_clock::now();
  while (!finished_.empty()) {
    auto it = jobs_.find(finished_.front());
    const bool expired = it == jobs_.end() || now - it->second->ended > limits_.keep_for;
    const bool over = finished_.size() > limits_.max_kept || (finished_.size() > 1 && kept_bytes_ > limits_.max_kept_bytes);
    if (!expired && !over) break;
    if (it != jobs_.end()) {
      if (it->second->result) kept_bytes_ -= it->second->result->size();
      jobs_.erase(it);
    }
    finished_.pop_front();
  }
}

std::optional<std::string> JobRunner::submit(Work work) {
  const std::lock_guard lock(mutex_);
  forget_old();
  if (active_ >= limits_.max_queued) return std::nullopt;
  auto job = std::make_shared<Job>();
  job->id = new_id();
  job->work = std::move(work);
  jobs_[job->id] = job;
  queue_.push_back(job);
  ++active_;
  wake_.notify_one();
  return job->id;
}

std::optional<std::string> JobRunner::status(const std::string& id) {
  const std::lock_guard lock(mutex_);  // state, result and times change under it
  forget_old();
  auto it = jobs_.find(id);
  if (it == jobs_.end()) return std::nullopt;
  const Job* job = it->second.get();
  const std::size_t done = job->progress.done(), total = job->progress.total();
  const auto now = std::chrono::steady_clock::now();
  const auto end = job->state == JobState::queued ? job->submitted
                   : job->state == JobState::running ? now
                                                     : job->ended;
  const auto begin = job->state == JobState::queued ? job->submitted : job->started;
  json out = {{"id", job->id},
              {"state", job_state_name(job->state)},
              {"progress", {{"done", done}, {"total", total},
                            {"fraction", total == 0 ? (job->state == JobState::done ? 1.0 : 0.0)
                                                    : std::min(1.0, static_cast<double>(done) / static_cast<double>(total))}}},
              {"elapsed_s", std::chrono::duration<double>(end - begin).count()}};
  if (job->problem) out["problem"] = *job->problem;
  std::string text = out.dump();
  if (job->result) {
    text.pop_back();  // the closing brace: "result" goes last
    text.reserve(text.size() + job->result->size() + 12);
    text.append(",\"result\":").append(*job->result).append("}");
  }
  return text;
}

bool JobRunner::cancel(const std::string& id) {
  const std::lock_guard lock(mutex_);
  auto it = jobs_.find(id);
  if (it == jobs_.end()) return false;
  Job& job = *it->second;
  job.progress.cancel();
  if (job.state == JobState::queued) {
    // Taken off the queue now: a cancelled job waiting behind a long one must not hold a queue place.
    for (auto q = queue_.begin(); q != queue_.end(); ++q) {
      if (q->get() == &job) {
        queue_.erase(q);
        break;
      }
    }
    job.state = JobState::cancelled;
    job.started = job.ended = std::chrono::steady_clock::now();
    job.work = nullptr;
    --active_;
    finished_.push_back(job.id);
  }
  return true;
}

std::pair<std::size_t, std::size_t> JobRunner::kept() const {
  const std::lock_guard lock(mutex_);
  return {finished_.size(), kept_bytes_};
}

void JobRunner::run() {
  for (;;) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      job = queue_.front();
      queue_.pop_front();
      job->state = JobState::running;
      job->started = std::chrono::steady_clock::now();
    }
    JobState state = JobState::done;
    std::optional<std::string> result;
    std::optional<json> problem;
    try {
      // Kept as text: a sweep's tree of a few million nodes is several times its text.
      // Held at run time too: twice the job budget of CPU time, and its cancel flag between frames and cases.
      const support::ScopedRunLimit limit({2.0 * budgets::kJobCpuSeconds * support::kInstrumentationSlowdown,
                                           &job->progress.cancel_flag(), nullptr});
      result = job->work(job->progress).dump();
      if (job->progress.cancelled()) state = JobState::cancelled, result.reset();
    } catch (const JobCancelled&) {
      state = JobState::cancelled;
    } catch (const support::RunStopped& stopped) {
      state = stopped.why == support::RunStopped::Why::cancelled ? JobState::cancelled : JobState::failed;
      if (state == JobState::failed) {
        problem = codec::problem_json(codec::Problem(422, "Request over budget", "",
                                                     "the job was stopped after " + std::to_string(stopped.cpu_seconds) +
                                                         " s of CPU time, past twice its budget"));
      }
    } catch (const codec::Problem& p) {
      state = JobState::failed;
      problem = codec::problem_json(p);
    } catch (const std::exception& e) {
      state = JobState::failed;
      problem = codec::problem_json(codec::Problem(500, "Internal error", "", e.what()));
    }
    {
      const std::lock_guard lock(mutex_);
      job->state = state;
      job->result = std::move(result);
      if (job->result) kept_bytes_ += job->result->size();
      job->problem = std::move(problem);
      job->ended = std::chrono::steady_clock::now();
      job->work = nullptr;  // the closure's request copy is freed before the trim
      --active_;
      finished_.push_back(job->id);
      forget_old();
    }
    job.reset();
    if (after_job_) after_job_();
  }
}

}  // namespace softtune::app
