#pragma once
// The check contract's options as a JSON request, read the same way for `softtune check` (which builds the
// request from its flags) and POST /api/v1/check: fps, substeps, shard, and for the route the presets, inline
// scenes, baseline and format. Every field bounded before work starts (docs/preset-ci.md).

#include <nlohmann/json.hpp>
#include <string>

#include "app/check_app.h"
#include "codec/json_reader.h"

namespace softtune::app {

/// Largest lists of a check request: preset names, inline scenes.
inline constexpr std::size_t kMaxCheckPresets = 256, kMaxCheckScenes = 16;

/// "I/N" with 1 <= I <= N <= kMaxShards; Problem (422) naming `field` otherwise.
Shard parse_shard(const std::string& text, const std::string& field);

/// Reads "fps" (up to 16 frame rates, Hz), "substeps" (up to 16 counts), "shard" ("I/N") and the scene engine
/// ("engine", "engine_settings": read_request_engine) into options.
void read_check_options(codec::ObjectReader& r, CheckOptions& options);

/// What POST /api/v1/check answers: the JSON report, or JUnit XML when the request asks "format": "junit".
struct CheckAnswer {
  bool junit = false;
  nlohmann::json json;
  std::string xml;
};

/// POST /api/v1/check: {"presets": [NAME...]?, "scenes": [{scene}...]?, "fps"?, "substeps"?, "shard"?, "engine"?,
/// "engine_settings"?,
/// "baseline": {baseline document}?, "format": "json" | "junit"?}; neither presets nor scenes: every preset of
/// `presets_dir`. Refused (422 naming presets, scenes, fps and substeps) when its work estimate exceeds
/// kMaxCheckWork.
CheckAnswer run_check_request(const nlohmann::json& request, const std::string& presets_dir);

/// A check request read and its work estimated, not yet run (the job route queues it).
struct CheckPlan {
  std::vector<CheckInput> inputs;
  CheckOptions options;  ///< its baseline pointer unset: run_check_plan points it at `baseline`
  std::optional<Baseline> baseline;
  bool junit = false;
  double work = 0.0;  ///< body-steps (check_cost.h)
};

/// The fields a check's budget refusal names, and the job route it points to.
inline constexpr const char* kCheckCostFields = "presets, scenes, fps, substeps";
inline constexpr const char* kCheckJobsRoute = "/api/v1/check/jobs";

/// Reads and validates a request as run_check_request does (the same 4xx problems), checking no budget.
CheckPlan plan_check_request(const nlohmann::json& request, const std::string& presets_dir);
/// Runs a plan; with `progress`, one unit per case, JobCancelled when cancelled.
CheckAnswer run_check_plan(const CheckPlan& plan, JobProgress* progress);
/// POST /api/v1/check/jobs: plan_check_request, then refused over kMaxCheckJobWork (422 naming the same
/// fields) and for "format": "junit" (422 naming `format`: a job's result is the JSON report).
CheckPlan plan_check_job(const nlohmann::json& request, const std::string& presets_dir);

}  // namespace softtune::app
