#include "http/job_routes.h"

#include <atomic>
#include <memory>
#include <mutex>

#include "app/check_request.h"
#include "app/job_runner.h"
#include "app/stability_app.h"
#include "codec/json_reader.h"
#include "codec/problem.h"
#include "codec/stability_codec.h"
#include "http/memory_release.h"

namespace softtune::http {
namespace {

// One JobRunner per route table, made when first needed, as preview_routes.cpp's LazyPreviews.
class LazyJobs {
 public:
  /// The runner, made on the first call (its kept results then show in `metrics`).
  app::JobRunner& get(Metrics* metrics = nullptr) {
    std::call_once(once_, [this, metrics] {
      runner_ = std::make_unique<app::JobRunner>(
          app::JobLimits{app::kMaxQueuedJobs, app::kMaxKeptJobs, app::kKeepJobsFor, app::kMaxKeptJobBytes}, trim_allocator);
      if (metrics) {
        metrics->add_cache_gauge("job_results", [this] {
          const auto [entries, bytes] = runner_->kept();
          return Metrics::CacheSize{entries, bytes};
        });
      }
      started_.store(true, std::memory_order_release);
    });
    return *runner_;
  }
  bool started() const { return started_.load(std::memory_order_acquire); }

 private:
  std::once_flag once_;
  std::atomic<bool> started_{false};
  std::unique_ptr<app::JobRunner> runner_;
};

// An id not of the job form names no job and is not echoed (as preview ids, preview_routes.cpp checked_preview_id).
const std::string& checked_job_id(const HttpRequest& request) {
  const std::string& id = request.params.at("id");
  if (!app::is_job_id(id)) {
    throw codec::Problem(404, "Not found", "id", "no such job: a job id is \"j\" and 16 lower-case hex digits, as POST .../jobs gives it");
  }
  return id;
}

codec::Problem unknown_job(const std::string& id) {
  return codec::Problem(404, "Not found", "id", "no job " + id + " (finished jobs are kept for a bounded time and count)");
}

// 202 with the status URL, or 503 with Retry-After when the queue is full.
HttpResponse queued(LazyJobs& jobs, Service& service, app::JobRunner::Work work) {
  const std::optional<std::string> id = jobs.get(&service.metrics()).submit(std::move(work));
  if (!id) {
    HttpResponse r = problem_response(codec::Problem(
        503, "Service unavailable", "",
        "the job queue is full: " + std::to_string(app::kMaxQueuedJobs) + " jobs are queued or running; retry when one ends"));
    r.headers.emplace_back("Retry-After", "5");
    return r;
  }
  const std::string url = std::string(kJobsPrefix) + "/" + *id;
  HttpResponse r = json_response({{"id", *id}, {"status_url", url}, {"state", "queued"}}, 202);
  r.headers.emplace_back("Location", url);
  return r;
}

}  // namespace

std::vector<Route> job_routes() {
  auto jobs = std::make_shared<LazyJobs>();
  return {
      {"POST", app::kStabilityJobsRoute,
       [jobs](const HttpRequest& request, Service& service) {
         // Read and priced on the request thread, so a bad or too large request is a 4xx now, not a failed job.
         auto q = std::make_shared<const codec::StabilityRequest>(codec::decode_stability_request(codec::parse_json(request.body)));
         app::require_stability_job_budget(*q);
         return queued(*jobs, service, [q](app::JobProgress& progress) { return app::run_stability_job(*q, progress); });
       }},
      {"POST", app::kCheckJobsRoute,
       [jobs](const HttpRequest& request, Service& service) {
         auto plan = std::make_shared<const app::CheckPlan>(app::plan_check_job(codec::parse_json(request.body), service.config().presets_dir));
         return queued(*jobs, service, [plan](app::JobProgress& progress) { return app::run_check_plan(*plan, &progress).json; });
       }},
      {"GET", std::string(kJobsPrefix) + "/{id}",
       [jobs](const HttpRequest& request, Service&) {
         const std::string& id = checked_job_id(request);
         auto status = jobs->started() ? jobs->get().status(id) : std::nullopt;
         if (!status) throw unknown_job(id);
         HttpResponse r;
         r.body = std::move(*status);
         return r;
       }},
      {"DELETE", std::string(kJobsPrefix) + "/{id}",
       [jobs](const HttpRequest& request, Service&) {
         const std::string& id = checked_job_id(request);
         if (!jobs->started() || !jobs->get().cancel(id)) throw unknown_job(id);
         auto status = jobs->get().status(id);
         if (!status) throw unknown_job(id);
         HttpResponse r;
         r.body = std::move(*status);
         return r;
       }},
  };
}

}  // namespace softtune::http
