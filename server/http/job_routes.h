#pragma once
// The job routes: POST /api/v1/stability/jobs and /api/v1/check/jobs (the synchronous routes' bodies, held
// to the job budget, queued on one worker; 202 with the status URL), GET /api/v1/jobs/{id} (state,
// progress, and the synchronous route's JSON when done) and DELETE /api/v1/jobs/{id} (cancel).
// docs/api.md "Jobs".

#include <vector>

#include "http/service.h"

namespace softtune::http {

inline constexpr const char* kJobsPrefix = "/api/v1/jobs";

/// The rows for the route table. They share one app::JobRunner, made (with its worker thread) on the first
/// job request.
std::vector<Route> job_routes();

}  // namespace softtune::http
