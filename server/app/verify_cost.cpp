#include "app/verify_cost.h"

#include "app/cost_drivers.h"

namespace softtune::app {
namespace {

// Rates measured on the reference machine (verify_cost.h).
constexpr double kEngineStepSeconds = 4e-6;
constexpr double kRunBytes = 64 * 1024;  // a strided trajectory and its report, per engine

}  // namespace

RequestCost verify_cost(const codec::VerifyRequest& q) {
  const double steps = q.options.duration_s * q.tune.fps * q.tune.substeps;
  const double engines = static_cast<double>(q.engines.size());
  RequestCost cost;
  cost.cpu_seconds = engines * steps * kEngineStepSeconds;
  cost.peak_bytes = engines * kRunBytes;
  cost.work = std::to_string(q.engines.size()) + " engines x " + std::to_string(static_cast<long long>(steps)) + " steps";
  const engines::VerifyOptions defaults;
  const TuneRequest tune_defaults;
  CostDrivers drivers;
  drivers.add("duration_s", q.options.duration_s / defaults.duration_s);
  drivers.add("fps", q.tune.fps / tune_defaults.fps);
  drivers.add("substeps", static_cast<double>(q.tune.substeps) / tune_defaults.substeps);
  drivers.add("engines", engines);
  cost.fields = drivers.fields();
  return cost;
}

}  // namespace softtune::app
