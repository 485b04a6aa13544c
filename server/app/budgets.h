#pragma once
// The budget every request is held to before it runs (docs/limits-and-security.md "Cost budget"). Each
// contract estimates its own cost from its request's fields (app/*_cost.h: one function per contract,
// returning RequestCost); request_cost.h refuses an estimate over these with a 422 naming the fields that
// drive it. The estimates are in CPU seconds of one core of the reference machine (the project's 2-core
// build machine, 2026-12); bench/request_cost_bench.cpp measures each against its estimate.

#include <cstddef>

namespace softtune::app::budgets {

/// CPU time one request may take on one core: a request above it is refused, never a half-minute run
/// on a worker thread. The default stability sweep (about 1 s) is the heaviest request inside.
inline constexpr double kCpuSeconds = 2.0;
/// Bytes one request may hold at its peak: its answer as a JSON tree and text, and the arrays it is built
/// from. Eight workers at this peak stay within about 0.5 GB.
inline constexpr double kPeakBytes = 64.0 * 1024 * 1024;

/// CPU time one job may take (POST /api/v1/stability/jobs, /api/v1/check/jobs; app/job_runner.h): the same
/// estimate as a request's, held to a budget 30 times larger, since a job runs on the one job worker and
/// never holds a request thread. Peak bytes stay kPeakBytes: a job's answer is kept until it is fetched.
inline constexpr double kJobCpuSeconds = 60.0;

}  // namespace softtune::app::budgets
