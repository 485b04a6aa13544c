#include "app/request_cost.h"

#include <cstdio>

#include "app/budgets.h"
#include "codec/problem.h"

namespace softtune::app {
namespace {

std::string format(const char* fmt, double a, double b) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, fmt, a, b);
  return buffer;
}

}  // namespace

void require_within_budget(const RequestCost& cost) {
  const bool cpu = cost.cpu_seconds > budgets::kCpuSeconds;
  const bool bytes = cost.peak_bytes > budgets::kPeakBytes;
  if (!cpu && !bytes) return;
  std::string names;
  for (const std::string& f : cost.fields) names += (names.empty() ? "" : ", ") + f;
  std::string detail = "the request asks for " + cost.work + ": about ";
  detail += cpu ? format("%.3g s of CPU time; the budget is %g s per request", cost.cpu_seconds, budgets::kCpuSeconds)
                : format("%.3g MiB at its peak; the budget is %g MiB per request", cost.peak_bytes / (1 << 20),
                         budgets::kPeakBytes / (1 << 20));
  detail += names.empty() ? "" : "; the fields driving it: " + names;
  codec::Problem p(422, "Request over budget", cost.fields.empty() ? "" : cost.fields.front(), detail);
  p.extensions = {{"fields", cost.fields},
                  {"estimated_cpu_seconds", cost.cpu_seconds},
                  {"budget_cpu_seconds", budgets::kCpuSeconds},
                  {"estimated_peak_bytes", cost.peak_bytes},
                  {"budget_peak_bytes", budgets::kPeakBytes}};
  throw p;
}

}  // namespace softtune::app
