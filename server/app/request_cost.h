#pragma once
// What a request will cost, estimated from its own fields before any work starts, and the check against
// the budget (budgets.h). Every contract has one function beside its use case returning a RequestCost
// (stability_cost.h, accuracy_cost.h, scene_cost.h, verify_cost.h, ...): it counts the work the request
// asks for (cases x steps, rows x steps, frames x bodies, ...) and prices it with per-unit rates measured
// on the reference machine, written beside the function; bench/request_cost_bench.cpp keeps them honest.
// A new contract adds its own X_cost.{h,cpp} and calls require_within_budget() before its work.

#include <string>
#include <vector>

namespace softtune::app {

struct RequestCost {
  double cpu_seconds = 0.0;  ///< estimated CPU time on one core of the reference machine, s
  double peak_bytes = 0.0;   ///< estimated bytes held at the peak (answer tree and text, arrays), B
  /// Dotted paths of the request fields that drive the cost, the largest driver first ("observe_steps").
  std::vector<std::string> fields;
  /// The counted work in words, for the refusal's detail ("17500 cases x 91835 steps").
  std::string work;
};

/// What an estimate is held to: a request's budget (budgets::kCpuSeconds) or a job's (kJobCpuSeconds).
struct Budget {
  double cpu_seconds = 0.0;  ///< s
  double peak_bytes = 0.0;   ///< B
  std::string per;           ///< "request" or "job", for the detail
  /// Where a larger request can go instead ("run it as a job: POST /api/v1/stability/jobs ..."); may be empty.
  std::string instead;
};
/// budgets::kCpuSeconds and kPeakBytes per request, with the way out `instead`.
Budget request_budget(std::string instead = "");
/// "over HTTP, run it as a job: POST `route` takes the same body, within 60 s of CPU, and reports progress".
std::string job_route_hint(const std::string& route);
/// budgets::kJobCpuSeconds and kPeakBytes per job.
Budget job_budget();

/// Throws codec::Problem 422 when the estimate is over the budget's CPU time or peak bytes: its
/// `field` is the first driver, its detail names every driver, the estimate and the budget, and its
/// extension members carry them as data ("fields", "estimated_cpu_seconds", "budget_cpu_seconds",
/// "estimated_peak_bytes", "budget_peak_bytes").
void require_within_budget(const RequestCost& cost, const Budget& budget = request_budget());

}  // namespace softtune::app
