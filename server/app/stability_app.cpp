#include "app/stability_app.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/preset_stability_app.h"
#include "app/preset_store.h"
#include "app/stability_cost.h"
#include "codec/problem.h"
#include "plot/svg_writer.h"
#include "softtune/support/run_limit.h"

namespace softtune::app {

using nlohmann::json;

namespace {

// The sweep and the chain; with `progress`, one unit per case of either, stopping when it is cancelled.
json sweep_and_encode(const codec::StabilityRequest& q, JobProgress* progress) {
  StageList stages;
  stages.add(Stage::validate);
  stages.add(Stage::stability_sweep);
  if (progress) progress->set_total(sweep_case_count(q.sweep) + (q.run_chain ? chain_sweep_case_count(q.chain) : 0));
  // Between cases, the request's or job's run-time limit (softtune/support/run_limit.h) is checked too.
  const std::function<bool()> hook = [progress] {
    support::check_run_limit();
    return !progress || progress->advance();
  };
  const SweepResult sweep = run_sweep(q.sweep, hook);
  if (progress && progress->cancelled()) throw JobCancelled{};
  std::optional<ChainSweepResult> chain;
  if (q.run_chain) {
    stages.add(Stage::sequential_impulse_chain);
    chain = run_chain_sweep(q.chain, hook);
    if (progress && progress->cancelled()) throw JobCancelled{};
  }
  return codec::encode_stability_result(q, sweep, chain, stages);
}

}  // namespace

json run_stability(const codec::StabilityRequest& q, const std::string& presets_dir) {
  if (q.preset) return run_preset_stability(*q.preset, presets_dir.empty() ? resolve_presets_dir() : presets_dir, q.preset_engine);
  require_within_budget(stability_cost(q), request_budget(job_route_hint(kStabilityJobsRoute)));
  return sweep_and_encode(q, nullptr);
}

void require_stability_job_budget(const codec::StabilityRequest& q) {
  // A preset search reports no progress of its own and fits the request budget: it runs on the synchronous route.
  if (q.preset) throw codec::invalid_field("preset", "a preset search runs on POST /api/v1/stability; a job runs a sweep");
  require_within_budget(stability_cost(q), job_budget());
}

json run_stability_job(const codec::StabilityRequest& q, JobProgress& progress) { return sweep_and_encode(q, &progress); }

json run_stability(const json& doc) { return run_stability(codec::decode_stability_request(doc)); }

Answer stability_answer(codec::StabilityRequest request, Format format, const std::string& presets_dir) {
  Answer a;
  a.format = format;
  if (format == Format::svg) {
    if (request.preset) throw codec::invalid_field("format", "must be json for a preset search (svg draws the sweep and the chain)");
    request.include_cases = false;
    a.text = stability_svg(run_stability(request));
  } else {
    a.json = run_stability(request, presets_dir);
  }
  return a;
}

plot::Plot stability_map_plot(double damping_ratio) {
  using plot::Scale;
  char title[160];
  std::snprintf(title, sizeof title, "Stability map at zeta = %g: spectral radius against omega h (dashed: 1)", damping_ratio);
  plot::Plot p{title, plot::make_axis("omega h", "rad", Scale::log), plot::make_axis("spectral radius", "", Scale::log, 1e-3, 1e3), {}, {1.0}};
  const double mass = 1.0, h = 1.0;
  const int samples = 240;
  for (Method m : kAllMethods) {
    plot::Series series{std::string(method_name(m)), "", {}, {}, plot::Style::line, false};
    for (int i = 0; i <= samples; ++i) {
      const double omega_h = std::pow(10.0, -2.0 + 4.0 * i / samples);
      const StepModel model = make_step_model(mass, omega_h / h, damping_ratio, h);
      series.x.push_back(omega_h);
      series.y.push_back(analyze(m, model, omega_h / h, damping_ratio).spectral_radius);
    }
    p.series.push_back(std::move(series));
  }
  return p;
}

std::string stability_svg(const json& encoded) {
  std::vector<plot::Plot> plots;
  for (double zeta : {0.0, 0.1, 1.0, 10.0}) plots.push_back(stability_map_plot(zeta));
  if (encoded.contains("chain")) {
    // One plot per solver: the bisected highest stable f h against the mass ratio, a series per count and
    // warm start ("none in range" plots at the scan's top).
    using plot::Scale;
    std::vector<std::string> solvers;
    for (const json& l : encoded.at("chain").at("limits")) {
      const std::string solver = l.at("solver").get<std::string>();
      if (std::find(solvers.begin(), solvers.end(), solver) == solvers.end()) solvers.push_back(solver);
    }
    for (const std::string& solver : solvers) {
      const bool substeps = solver == "box2d_v3" || solver == "rapier";
      plot::Plot p{"Chain in " + solver + ": highest stable f h (bisected; no limit: at the scan top)",
                   plot::make_axis("mass ratio m2 / m1", "", Scale::log), plot::make_axis("highest stable f h", "", Scale::log), {}, {}};
      for (const json& l : encoded.at("chain").at("limits")) {
        if (l.at("solver") != solver) continue;
        const std::string name = std::to_string(l.at("count").get<int>()) + (substeps ? " substeps" : " iterations") +
                                 (l.at("warm_start").get<bool>() ? ", warm start" : "");
        auto it = std::find_if(p.series.begin(), p.series.end(), [&](const plot::Series& s) { return s.name == name; });
        if (it == p.series.end()) {
          p.series.push_back({name, "", {}, {}, plot::Style::line_and_markers, l.at("warm_start").get<bool>()});
          it = p.series.end() - 1;
        }
        const json& f = l.at("highest_stable_frequency_ratio");
        it->x.push_back(l.at("mass_ratio").get<double>());
        it->y.push_back(f.is_null() ? std::nan("") : f.get<double>());
      }
      plots.push_back(std::move(p));
    }
  }
  return plot::render_svg(plots);
}

}  // namespace softtune::app
