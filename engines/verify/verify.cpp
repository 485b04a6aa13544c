#include "softtune/engines/verify.h"

#include <cmath>

#include "softtune/response_fit.h"

namespace softtune::engines {

Measured measure(const RunTrajectory& trajectory, double dt) {
  Measured out;
  for (double x : trajectory) {
    if (!std::isfinite(x)) {
      out.finite = false;
      return out;
    }
  }
  const ResponseFit fit = fit_response(trajectory, dt);
  out.frequency_hz = fit.frequency_hz;
  out.damping_ratio = fit.damping_ratio;
  out.residual = fit.residual;
  return out;
}

std::size_t model_index(std::string_view name) {
  const auto models = engine_models();
  std::size_t i = 0;
  while (i < models.size() && models[i]->name != name) ++i;
  return i;
}

EngineVerification verify_engine(const RealEngine& engine, const TuneResult& result, const TuneRequest& request,
                                 const VerifyOptions& options) {
  EngineVerification out;
  out.engine = &engine;
  const std::size_t index = model_index(engine.name);
  if (index >= result.engine_reports.size()) return out;
  const EngineReport& report = result.engine_reports[index];
  EngineRun run;
  run.effective_mass = result.effective_mass;
  run.settings = engine_settings_for(request, index);
  run.dt = result.h;
  run.steps = static_cast<int>(std::ceil(options.duration_s / result.h));
  run.x0 = options.x0;
  run.body = options.body;
  run.parameters = report.parameters;
  out.trajectory = engine.run(run);
  out.measured = measure(out.trajectory, run.dt);
  if (report.exact) {
    run.parameters = *report.exact;
    out.exact_trajectory = engine.run(run);
    out.exact_measured = measure(*out.exact_trajectory, run.dt);
  }
  return out;
}

const RealEngine* find_real_engine(std::string_view name) {
  for (const RealEngine* e : real_engines()) {
    if (e->name == name) return e;
  }
  return nullptr;
}

}  // namespace softtune::engines
