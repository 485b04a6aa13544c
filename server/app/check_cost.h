#pragma once
// What a check costs, estimated before any step is taken, so POST /api/v1/check can refuse a request that
// would hold a worker for long: Box2D body-steps (frames x substeps x (bodies + joints)) summed over every
// case and every mass-model run. One small function the route calls (a general cost model for every route
// may absorb it later).

#include <vector>

#include "app/check_app.h"

namespace softtune::app {

/// Largest estimated work of one check request, in body-steps: about 2 s of one core (seven presets at 6 rates x 3
/// substep counts, 7.9e6 body-steps, took 3.1 s of CPU: 2.5e6 a second; docs/preset-ci.md).
inline constexpr double kMaxCheckWork = 5.0e6;
/// Body-steps one core checks in a second (the measurement above).
inline constexpr double kCheckWorkPerSecond = 2.5e6;
/// Largest estimated work of one check job (POST /api/v1/check/jobs): budgets::kJobCpuSeconds of one core.
inline constexpr double kMaxCheckJobWork = 1.5e8;

/// Body-steps of one case: frames x substeps x max(1, bodies + joints + oscillators), times the runs its
/// expectations need (one per mass model). Oscillators cost a core-integrator step each, far less than a
/// Box2D body; counting them as one keeps the estimate an upper bound.
double case_work(const scene::Scene& scene, const CheckRate& rate);

/// The work of checking `inputs` (this shard only) under `options`; undecodable inputs cost nothing.
double check_work(const std::vector<CheckInput>& inputs, const CheckOptions& options);

/// Refuses (Problem 422, field `fields`) a work estimate above `budget`, naming the estimate, the budget
/// and `instead` (where a larger check can go; may be empty).
void require_check_budget(double work, double budget, const std::string& fields, const std::string& instead = "");

}  // namespace softtune::app
