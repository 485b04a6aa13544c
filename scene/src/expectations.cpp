#include "softtune/scene/expectations.h"

#include <algorithm>
#include <cmath>

namespace softtune::scene {

std::optional<double> metric_value(const Expectation& e, const SceneResult& run) {
  switch (e.metric) {
    case Metric::max_constraint_error: return run.max_constraint_error;
    case Metric::finite: return run.finite ? 1.0 : 0.0;
    case Metric::in_world: return run.left_world.empty() ? 1.0 : 0.0;
    default: break;
  }
  const auto it = std::find_if(run.probes.begin(), run.probes.end(), [&](const ProbeResult& p) { return p.id == e.probe; });
  if (it == run.probes.end()) return std::nullopt;
  const ProbeResult& p = *it;
  auto absolute = [](const std::optional<double>& v) { return v ? std::optional<double>(std::abs(*v)) : std::nullopt; };
  switch (e.metric) {
    case Metric::frequency_error: return absolute(p.frequency_error);
    case Metric::damping_ratio_error: return absolute(p.damping_ratio_error);
    case Metric::measured_frequency_hz: return p.measured.frequency_hz;
    case Metric::measured_damping_ratio: return p.measured.damping_ratio;
    case Metric::overshoot: return p.measured.overshoot;
    case Metric::settle_frames:
      return p.settle_frames ? std::optional<double>(*p.settle_frames) : std::nullopt;
    case Metric::settle_s: return p.settle_s;
    case Metric::max_abs_value:
      // A diverged integrator's series is cut at kDivergence: report that bound, it is what "blew up" means.
      return p.diverged ? std::max(p.max_abs_value, kDivergence) : p.max_abs_value;
    default: return std::nullopt;
  }
}

CheckResult check_scene(const Scene& scene, const RunOptions& engine) {
  CheckResult out;
  std::vector<MassModel> models = {scene.mass_model};
  for (const Expectation& e : scene.expectations) {
    if (!applies_at(e, scene.world)) continue;
    if (e.mass_model && std::find(models.begin(), models.end(), *e.mass_model) == models.end()) models.push_back(*e.mass_model);
  }
  for (MassModel m : models) {
    RunOptions options;
    options.mass_model = m;
    options.backend = engine.backend;
    options.engine_settings = engine.engine_settings;
    out.runs.push_back(run_scene(scene, options));
  }
  for (const SceneResult& run : out.runs) out.passed = out.passed && !run.error;
  for (const Expectation& e : scene.expectations) {
    if (!applies_at(e, scene.world)) continue;  // a bound stated for other rates
    const MassModel m = e.mass_model.value_or(scene.mass_model);
    const auto run = std::find_if(out.runs.begin(), out.runs.end(), [m](const SceneResult& r) { return r.mass_model == m; });
    ExpectationResult r{e, m, metric_value(e, *run), false};
    if (e.metric == Metric::finite || e.metric == Metric::in_world) {
      r.passed = r.value == 1.0;
    } else {
      r.passed = r.value && (!e.min || *r.value >= *e.min) && (!e.max || *r.value <= *e.max);
    }
    out.passed = out.passed && r.passed;
    out.results.push_back(r);
  }
  out.runs.front().stages.add(Stage::expectations);
  return out;
}

}  // namespace softtune::scene
