#pragma once
// The stability use case, shared by `softtune stability` and GET|POST /api/v1/stability: the extreme-case
// sweep (predicted against observed per integrator) and the sequential-impulse mass-ratio chain, as JSON or
// as SVG maps.

#include <nlohmann/json.hpp>
#include <string>

#include "app/answer.h"
#include "app/job_progress.h"
#include "codec/stability_codec.h"
#include "plot/plot_model.h"

namespace softtune::app {

/// Runs the sweep and the chain, refused (422) first when over the budget (stability_cost.h); the JSON has summary, cases (unless summary only), chain, stages.
/// A request naming a preset runs the preset search alone (preset_stability_app.h), from `presets_dir`
/// (empty: resolve_presets_dir()).
nlohmann::json run_stability(const codec::StabilityRequest& request, const std::string& presets_dir = {});
nlohmann::json run_stability(const nlohmann::json& doc);

/// The job route of the stability contract, which the synchronous route's budget refusal points to.
inline constexpr const char* kStabilityJobsRoute = "/api/v1/stability/jobs";

/// The job form (POST /api/v1/stability/jobs): refused (422 naming the fields) over the job budget (budgets.h),
/// and for a preset search (422 naming `preset`: it runs on the synchronous route)...
void require_stability_job_budget(const codec::StabilityRequest& request);
/// ...then, on the job worker, exactly the JSON run_stability answers, one progress unit per sweep and chain
/// case; throws JobCancelled when cancelled. Checks no budget (the job route checked it before queueing).
nlohmann::json run_stability_job(const codec::StabilityRequest& request, JobProgress& progress);

/// The answer in `format` (json or svg); the SVG needs no per-case list, so it leaves the cases out. A
/// preset search answers JSON only (422 on `format` for svg).
Answer stability_answer(codec::StabilityRequest request, Format format, const std::string& presets_dir = {});

/// Spectral radius against omega h per integrator at one damping ratio (log-log, reference line at 1).
plot::Plot stability_map_plot(double damping_ratio);

/// Stability maps at zeta = 0, 0.1, 1 and 10, and the chain's highest stable frequency per mass ratio.
std::string stability_svg(const nlohmann::json& encoded);

}  // namespace softtune::app
