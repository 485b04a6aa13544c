#include "app/request_cost.h"

#include <fmt/format.h>
#include <utility>

#include "app/budgets.h"
#include "codec/problem.h"

namespace softtune::app {
Budget request_budget(std::string instead) {
  return {budgets::kCpuSeconds, budgets::kPeakBytes, "request", std::move(instead)};
}

std::string job_route_hint(const std::string& route) {
  char text[64];
  std::snprintf(text, sizeof text, "%g s of CPU", budgets::kJobCpuSeconds);
  return "over HTTP, run it as a job: POST " + route + " takes the same body, within " + text + ", and reports progress";
}

Budget job_budget() { return {budgets::kJobCpuSeconds, budgets::kPeakBytes, "job", ""}; }

void require_within_budget(const RequestCost& cost, const Budget& budget) {
  const bool cpu = cost.cpu_seconds > budget.cpu_seconds;
  const bool bytes = cost.peak_bytes > budget.peak_bytes;
  if (!cpu && !bytes) return;
  std::string names;
  for (const std::string& f : cost.fields) names += (names.empty() ? "" : ", ") + f;
  std::string detail = "the request asks for " + cost.work + ": about ";
  detail += cpu ? fmt::format("{:.3g} s of CPU time; the budget is {:g} s per ", cost.cpu_seconds, budget.cpu_seconds)
                : fmt::format("{:.3g} MiB at its peak; the budget is {:g} MiB per ", cost.peak_bytes / (1 << 20), budget.peak_bytes / (1 << 20));
  detail += budget.per;
  detail += names.empty() ? "" : "; the fields driving it: " + names;
  // Only CPU time is larger for a job: a request over the byte budget is over a job's too.
  if (cpu && !bytes && !budget.instead.empty()) detail += "; " + budget.instead;
  codec::Problem p(422, "Request over budget", cost.fields.empty() ? "" : cost.fields.front(), detail);
  p.extensions = {{"fields", cost.fields},
                  {"estimated_cpu_seconds", cost.cpu_seconds},
                  {"budget_cpu_seconds", budget.cpu_seconds},
                  {"estimated_peak_bytes", cost.peak_bytes},
                  {"budget_peak_bytes", budget.peak_bytes}};
  throw p;
}

}  // namespace softtune::app
