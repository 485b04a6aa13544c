#include "http/limits_registry.h"

#include <cmath>
#include <cstdio>

#include "app/check_app.h"
#include "app/check_cost.h"
#include "app/check_request.h"
#include "app/budgets.h"
#include "app/job_runner.h"
#include "app/preset_store.h"
#include "app/preview_service.h"
#include "codec/identify_codec.h"
#include "codec/json_reader.h"
#include "codec/scene_codec.h"
#include "codec/stability_codec.h"
#include "codec/verify_codec.h"
#include "http/limits.h"
#include "softtune/accuracy.h"
#include "softtune/chain_design.h"
#include "softtune/engines/verify.h"
#include "softtune/identify.h"
#include "softtune/render/frame_pipeline.h"
#include "softtune/render/renderer.h"
#include "softtune/scene/limits.h"
#include "softtune/validation.h"

namespace softtune::http {
namespace {

namespace hl = http::limits;
namespace sl = scene::limits;
namespace vl = softtune::limits;  // core: validation.h and accuracy.h

// A figure as the table writes it: plain below 1e5, else mantissa and exponent ("2e5", "1e-9").
std::string figure(double v) {
  char buf[32];
  const double a = std::fabs(v);
  if (a != 0.0 && (a >= 1e5 || a < 1e-3)) {
    const int exponent = static_cast<int>(std::floor(std::log10(a)));
    std::snprintf(buf, sizeof buf, "%ge%d", v / std::pow(10.0, exponent), exponent);
  } else {
    std::snprintf(buf, sizeof buf, "%g", v);
  }
  return buf;
}
std::string figure(std::size_t v) { return figure(static_cast<double>(v)); }
std::string figure(int v) { return figure(static_cast<double>(v)); }

std::string bytes(std::size_t n) {
  if (n % (std::size_t{1} << 20) == 0) return std::to_string(n >> 20) + " MiB";
  if (n % 1024 == 0) return std::to_string(n / 1024) + " KiB";
  return std::to_string(n) + " bytes";
}

std::string millis(long long ms) { return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms"; }

}  // namespace

std::vector<NumericLimit> numeric_limits() {
  using D = double;
  return {
      {"max_body_bytes", D(hl::kMaxBodyBytes)},
      {"max_header_bytes", D(hl::kMaxHeaderBytes)},
      {"max_json_depth", D(hl::kMaxJsonDepth)},
      {"default_threads", D(hl::kDefaultThreads)},
      {"max_threads", D(hl::kMaxThreads)},
      {"max_queued_connections", D(hl::kMaxQueuedConnections)},
      {"max_open_connections", D(hl::kMaxOpenConnections)},
      {"max_connections_per_client", D(hl::kMaxConnectionsPerClient)},
      {"request_read_timeout_ms", D(hl::kRequestReadTimeout.count())},
      {"min_body_bytes_per_s", D(hl::kMinBodyBytesPerSecond)},
      {"body_grace_ms", D(hl::kBodyGrace.count())},
      {"max_gate_buffered_bytes", D(hl::kMaxGateBufferedBytes)},
      {"write_timeout_ms", D(hl::kWriteTimeout.count())},
      {"keep_alive_timeout_ms", D(hl::kKeepAliveTimeout.count())},
      {"keep_alive_max_requests", D(hl::kKeepAliveMaxRequests)},
      {"response_cache_entries", D(hl::kResponseCacheEntries)},
      {"response_cache_bytes", D(hl::kResponseCacheBytes)},
      {"max_header_line_bytes", D(hl::kMaxHeaderLineBytes)},
      {"request_budget_cpu_s", app::budgets::kCpuSeconds},
      {"request_budget_peak_bytes", app::budgets::kPeakBytes},
      {"job_budget_cpu_s", app::budgets::kJobCpuSeconds},
      {"check_job_max_work", app::kMaxCheckJobWork},
      {"max_queued_jobs", D(app::kMaxQueuedJobs)},
      {"max_kept_jobs", D(app::kMaxKeptJobs)},
      {"job_kept_s", D(app::kKeepJobsFor.count())},
      {"max_kept_job_bytes", D(app::kMaxKeptJobBytes)},
      {"scene_max_duration_s", sl::kMaxDurationS},
      {"scene_max_steps", sl::kMaxSceneSteps},
      {"scene_max_body_steps", sl::kMaxBodySteps},
      {"scene_max_bodies", D(sl::kMaxBodies)},
      {"scene_max_joints", D(sl::kMaxJoints)},
      {"scene_max_typed_stiffness", sl::kMaxTypedStiffness},
      {"modes_max_dynamic_bodies", D(sl::kMaxModeBodies)},
      {"modal_max_targets", D(sl::kMaxModeTargets)},
      {"modal_max_groups", D(sl::kMaxJointGroups)},
      {"simulate_max_frame_stride", D(codec::kMaxFrameStride)},
      {"accuracy_max_step_rates", D(vl::kMaxStepRates)},
      {"accuracy_max_soft_substeps", D(vl::kMaxSoftSubsteps)},
      {"accuracy_max_timing_repeats", D(vl::kMaxTimingRepeats)},
      {"accuracy_max_steps_per_row", vl::kMaxAccuracyStepsPerRow},
      {"stability_max_grid_entries", D(codec::kMaxGridEntries)},
      {"stability_max_cases", D(codec::kMaxCases)},
      {"stability_max_observe_steps", D(codec::kMaxObserveSteps)},
      {"max_preview_frames", D(render::caps::kMaxFrames)},
      {"max_preview_width", D(render::caps::kMaxWidth)},
      {"max_preview_height", D(render::caps::kMaxHeight)},
      {"identify_max_samples", D(kIdentifyMaxSamples)},
      {"identify_max_probes", D(kIdentifyMaxProbes)},
      {"identify_max_values", D(kIdentifyMaxCells)},
      {"identify_max_csv_bytes", D(codec::kCsvMaxBytes)},
      {"identify_max_previous", D(codec::kIdentifyMaxPrevious)},
      {"check_max_work", app::kMaxCheckWork},
      {"check_max_presets", D(app::kMaxCheckPresets)},
      {"check_max_scenes", D(app::kMaxCheckScenes)},
      {"check_max_rates", D(sl::kMaxRates)},
  };
}

namespace {

// Connections, heads, bodies and threads: the HTTP service's own limits.
std::vector<LimitRow> transport_rows() {
  return {
      {"request body", bytes(hl::kMaxBodyBytes) + ", by `Content-Length`", "`server/http/limits.h` `kMaxBodyBytes`",
       "413 before the body is read; the connection closes"},
      {"chunked or compressed bodies",
       "not accepted: `Content-Length` only, no `Transfer-Encoding`, no `Content-Encoding`",
       "`server/http/request_policy.cpp`",
       "411 / 415 before any byte of the body is read: a 100 MB chunked body or a gzip bomb is never buffered or "
       "inflated"},
      {"request line, one header line", bytes(hl::kMaxHeaderLineBytes) + " (cpp-httplib 0.11.4's compiled-in limit)",
       "`server/http/limits.h` `kMaxHeaderLineBytes`",
       "414 for a request line, 431 for a header line; the connection closes"},
      {"request line plus headers", bytes(hl::kMaxHeaderBytes) + " in total", "`server/http/limits.h` `kMaxHeaderBytes`",
       "431; the connection closes (10 000 headers end here)"},
      {"reading one request",
       millis(hl::kRequestReadTimeout.count()) + " for line, headers and body together, however slowly they trickle; "
           "once the head is in, the body within " + millis(hl::kBodyGrace.count()) + " plus its length at " +
           bytes(hl::kMinBodyBytesPerSecond) + "/s. Heads and bodies arrive in the connection gate, never in a worker: " +
           bytes(hl::kMaxGateBufferedBytes) + " of them held in all",
       "`server/http/limits.h` `kRequestReadTimeout`, `kBodyGrace`, `kMinBodyBytesPerSecond`, `kMaxGateBufferedBytes`",
       "408 and the connection closes (slowloris heads and slow bodies are cut off); past the bytes held, the "
       "connection that has waited longest is closed"},
      {"writing a response", millis(hl::kWriteTimeout.count()) + " without progress",
       "`server/http/limits.h` `kWriteTimeout`", "the connection closes"},
      {"idle keep-alive connection",
       millis(hl::kKeepAliveTimeout.count()) + " idle, at most " + figure(hl::kKeepAliveMaxRequests) +
           " requests per connection",
       "`server/http/limits.h` `kKeepAliveTimeout`, `kKeepAliveMaxRequests`",
       "the connection closes (`Connection: close` on the last answer)"},
      {"worker threads",
       figure(hl::kDefaultThreads) + " by default, 1 to " + figure(hl::kMaxThreads) + " (`--threads`); one per request being served",
       "`server/http/limits.h` `kDefaultThreads`, `kMaxThreads`", "complete requests wait in the queue"},
      {"requests waiting for a worker", figure(hl::kMaxQueuedConnections), "`server/http/limits.h` `kMaxQueuedConnections`",
       "503 at once with `Retry-After: 1`"},
      {"open connections",
       figure(hl::kMaxOpenConnections) +
           " (request heads arriving, idle keep-alive, draining after a refusal); none of them holds a worker. The "
           "server raises its soft file-descriptor limit to fit them, and holds fewer if the hard limit is lower",
       "`server/http/limits.h` `kMaxOpenConnections`",
       "one that is draining is closed, or else the one that has waited longest, to admit the new one"},
      {"connections per client address",
       figure(hl::kMaxConnectionsPerClient) +
           " open at once from one IP address (IPv4, or IPv6 in full; an IPv4-mapped address as its IPv4 one), "
           "wherever they are: arriving, idle, queued or being served",
       "`server/http/limits.h` `kMaxConnectionsPerClient`",
       "the next one from that address is answered 503 with `Retry-After: 1` before any byte of it is read, "
       "and closed; it takes no other connection's place"},
  };
}

// What a request may hold: JSON, names, and each contract's values.
std::vector<LimitRow> request_rows() {
  return {
      {"JSON nesting", figure(codec::kMaxJsonDepth) + " levels", "`server/codec/json_reader.h` `kMaxJsonDepth`",
       "400 (nlohmann's recursive dump and copy would crash on deep documents)"},
      {"JSON numbers", "finite doubles", "`server/codec/json_reader.cpp`",
       "422 naming the dotted field (`1e999`, `1e309`); `NaN`, `Infinity` as bare words are malformed JSON (400), as "
       "strings a wrong type (422)"},
      {"cost of one request",
       "about " + figure(app::budgets::kCpuSeconds) + " s of CPU on one core here and " +
           bytes(static_cast<std::size_t>(app::budgets::kPeakBytes)) +
           " held at its peak, estimated from the request's own fields before any work (stability cases x steps, "
           "accuracy rows x steps x repeats, scene frames x substeps x bodies, verify engines x steps)",
       "`server/app/budgets.h` `kCpuSeconds`, `kPeakBytes`; each contract's estimate in `server/app/*_cost.h`",
       "422 `request-over-budget` naming the fields that drive the cost (`field` the first, `fields` all) with "
       "`estimated_cpu_seconds`, `budget_cpu_seconds`, `estimated_peak_bytes`, `budget_peak_bytes`"},
      {"cost of one job",
       "about " + figure(app::budgets::kJobCpuSeconds) + " s of CPU on one core (check: " + figure(app::kMaxCheckJobWork) +
           " body-steps) and " + bytes(static_cast<std::size_t>(app::budgets::kPeakBytes)) +
           " at its peak, by the same estimates (`POST /api/v1/stability/jobs`, `POST /api/v1/check/jobs`)",
       "`server/app/budgets.h` `kJobCpuSeconds`, `server/app/check_cost.h` `kMaxCheckJobWork`",
       "422 naming the fields that drive the cost, before the job is queued"},
      {"jobs",
       figure(app::kMaxQueuedJobs) + " queued or running at once, run one at a time on one worker thread; " +
           figure(app::kMaxKeptJobs) + " finished jobs kept, " + bytes(app::kMaxKeptJobBytes) +
           " of their results as JSON text, each for at most " + figure(static_cast<int>(app::kKeepJobsFor.count())) + " s",
       "`server/app/job_runner.h` `kMaxQueuedJobs`, `kMaxKeptJobs`, `kMaxKeptJobBytes`, `kKeepJobsFor`",
       "503 with `Retry-After: 5` when the queue is full; a forgotten job's status is a 404"},
      {"query parameters", "only those a route reads (`format` on accuracy and stability), each once",
       "`server/http/routes.cpp` (each row's list), `server/http/service.cpp`", "422 naming the parameter"},
      {"preview ids and frame numbers", "64 lower-case hex digits; frame numbers without sign or leading zeros",
       "`server/http/preview_routes.cpp`",
       "404 that does not echo the id (`00.png` is a 404 naming `n`, pointing at `0.png`)"},
      {"duplicated keys", "none", "`server/codec/json_reader.cpp`", "400 naming the key"},
      {"unknown fields", "none", "`ObjectReader::finish`, `server/codec/json_reader.h`", "422 naming the dotted field"},
      {"paths", "no `..`, `%2e%2e`, `..%2f`, `%00`, backslashes or non-UTF-8 after decoding; static files only under `web/`",
       "`server/http/static_files.cpp`, `server/http/router.cpp`", "400 / 404"},
      {"preset names", "`[a-z0-9_-]`, 1 to " + figure(app::kMaxPresetNameLength) + " characters, not `schema`",
       "`server/app/preset_store.h` `kMaxPresetNameLength`",
       "422 naming `name` (GET) or `preset` (simulate, preview); 404 for a well-formed name with no preset"},
      {"preset files", bytes(app::kMaxPresetBytes), "`server/app/preset_store.h` `kMaxPresetBytes`",
       "413 naming the file"},
      {"tune request values",
       "fps " + figure(vl::kMinFps) + " to " + figure(vl::kMaxFps) + " Hz, substeps 1 to " + figure(vl::kMaxSubsteps) +
           ", fps x substeps <= " + figure(vl::kMaxStepRate) + ", response_frames " + figure(vl::kMinFrames) + " to " +
           figure(vl::kMaxFrames) + ", frequency 0 to " + figure(vl::kMaxFrequencyHz) + " Hz, damping ratio 0 to " +
           figure(vl::kMaxDampingRatio) + ", masses " + figure(vl::kMinMass) + " to " + figure(vl::kMaxMass) +
           " kg, inertias " + figure(vl::kMinInertia) + " to " + figure(vl::kMaxInertia) +
           " kg m^2, coordinates within " + figure(vl::kMaxCoordinate) + " m, axis longer than " +
           figure(vl::kMinAxisLength) + " m",
       "`core/include/softtune/validation.h`",
       "422 naming the field; a frequency above Nyquist in exact mode is clamped with a warning"},
      {"engine settings", "each engine model's settings: its own range, integer or choice",
       "the model's `SettingSpec`s, `core/src/engines/<engine>.cpp`",
       "422 naming `engine_settings.<engine>.<setting>`"},
      {"scene engine", "a scene backend of this build (GET /api/v1/scene-engines) and its own settings: range, integer or choice",
       "the backend's `SettingSpec`s, `engines/scene_backends.cpp`",
       "422 naming `engine` (listing the engines) or `engine_settings.<setting>`; a scene feature the engine cannot represent: 422 naming the feature"},
      {"scenes",
       "gravity <= " + figure(sl::kMaxGravity) + " m/s^2 per component, fps <= " + figure(sl::kMaxSceneFps) +
           " Hz, substeps <= " + figure(sl::kMaxSceneSubsteps) + ", iterations <= " + figure(sl::kMaxIterations) +
           ", duration <= " + figure(sl::kMaxDurationS) + " s, frames x substeps <= " + figure(sl::kMaxSceneSteps) +
           ", frames x substeps x (bodies + joints) <= " + figure(sl::kMaxBodySteps) + ", " + figure(sl::kMaxBodies) +
           " bodies, " + figure(sl::kMaxJoints) + " joints, " + figure(sl::kMaxOscillators) + " oscillators, " +
           figure(sl::kMaxProbes) + " probes, coordinates within " + figure(sl::kMaxWorldCoordinate) + " m, sizes " +
           figure(sl::kMinSize) + " to " + figure(sl::kMaxSize) + " m, joint lengths and polygon edges >= " +
           figure(sl::kMinJointLength * 1000.0) + " mm, body masses " + figure(sl::kMinBodyMass) + " to " +
           figure(sl::kMaxBodyMass) + " kg, densities " + figure(sl::kMinDensity) + " to " + figure(sl::kMaxDensity) +
           " kg/m^2, speeds <= " + figure(sl::kMaxSpeed) + " m/s, angular speeds <= " + figure(sl::kMaxAngularSpeed) +
           " rad/s, " + figure(sl::kMaxPolygonVertices) + " polygon vertices, ids <= " + figure(sl::kMaxIdLength) +
           " characters, a joint's typed stiffness in (0, " + figure(sl::kMaxTypedStiffness) + "] and |damping| <= " +
           figure(sl::kMaxTypedStiffness),
       "`scene/include/softtune/scene/limits.h`", "422 naming the field"},
      {"modes and modal tuning",
       "at most " + figure(sl::kMaxModeBodies) + " dynamic bodies, at_s within [0, duration_s], " +
           figure(sl::kMaxModeTargets) + " targets, " + figure(sl::kMaxJointGroups) + " joint groups",
       "`scene/include/softtune/scene/limits.h` `kMaxModeBodies`, `kMaxModeTargets`, `kMaxJointGroups`",
       "422 naming the field before any Box2D step"},
      {"check request",
       figure(app::kMaxCheckPresets) + " preset names, " + figure(app::kMaxCheckScenes) + " inline scenes, " +
           figure(sl::kMaxRates) + " entries each of fps, substeps (and of a preset's rates), shard I/N with N <= " +
           figure(app::kMaxShards) + "; estimated work, frames x substeps x (bodies + joints) summed over every case, <= " +
           figure(app::kMaxCheckWork) + " body-steps (about 2 s of one core); `softtune check -j` 1 to " +
           figure(app::kMaxCheckJobs),
       "`server/app/check_request.h`, `server/app/check_cost.h` `kMaxCheckWork`, `server/app/check_app.h`, "
       "`scene/include/softtune/scene/limits.h` `kMaxRates`",
       "422 naming the field; above the work budget 422 naming `presets, scenes, fps, substeps` before any step"},
      {"simulate options", "frame_stride 1 to " + figure(codec::kMaxFrameStride),
       "`server/codec/scene_codec.h` `kMaxFrameStride`", "422 naming the field"},
      {"accuracy request",
       figure(vl::kMaxStepRates) + " step rates, " + figure(vl::kMaxSoftSubsteps) + " soft_substeps entries of 1 to " +
           figure(vl::kMaxSoftSubstepCount) + ", error_budget " + figure(vl::kMinErrorBudget) + " to " +
           figure(vl::kMaxErrorBudget) + ", timing_repeats 1 to " + figure(vl::kMaxTimingRepeats) +
           ", fps x substeps x duration_s <= " + figure(vl::kMaxAccuracyStepsPerRow) + " steps per row",
       "`core/include/softtune/accuracy.h` (`softtune::limits`)", "422 naming the field"},
      {"stability request",
       figure(codec::kMaxGridEntries) + " entries per grid list, " + figure(codec::kMaxCases) +
           " cases (product of the lists), observe_steps " + figure(codec::kMinObserveSteps) + " to " +
           figure(codec::kMaxObserveSteps) + ", frequency ratio <= " + figure(codec::kMaxFrequencyRatio) + ", step " +
           figure(codec::kMinStep) + " to " + figure(codec::kMaxStep) + " s, stiffness <= " +
           figure(codec::kMaxStiffness) + " N/m, mass ratio <= " + figure(codec::kMaxMassRatio) +
           ", chain iterations <= " + figure(codec::kMaxChainIterations) + ", chain solvers 1 to " +
           figure(kAllChainSolvers.size()) + " names",
       "`server/codec/stability_codec.h`", "422 naming the field"},
      {"tune `chain`",
       "mass_ratio 1 to " + figure(codec::kMaxMassRatio) + " (required), margin 1 to " + figure(kMaxChainMargin) +
           ", solvers 1 to " + figure(kAllChainSolvers.size()) + " names; the fewest-count search stops at " +
           figure(kMaxDesignCount) + " (`null` beyond)",
       "`server/codec/stability_codec.h` `kMaxMassRatio`; `core/include/softtune/chain_design.h` `kMaxChainMargin`, "
       "`kMaxDesignCount`",
       "422 naming `chain.<field>`"},
      {"verify request",
       "at most " + figure(codec::kVerifyMaxEngines) + " engine names; duration_s in (0, " +
           figure(engines::kVerifyMaxDuration) + "] s and duration x fps x substeps <= " +
           figure(engines::kVerifyMaxSteps) + " steps per run; x0 in (0, 1] m",
       "`server/codec/verify_codec.h` `kVerifyMaxEngines`; `engines/include/softtune/engines/verify.h` "
       "`kVerifyMaxDuration`, `kVerifyMaxSteps`; x0 in `server/codec/verify_codec.cpp`",
       "422 naming the field; each trajectory in the answer is strided to at most " +
           figure(codec::kVerifyMaxPlotSamples) + " samples (`kVerifyMaxPlotSamples`)"},
      {"identify request",
       "2 to " + figure(kIdentifyMaxSamples) + " rows, 1 to " + figure(kIdentifyMaxProbes) + " probe columns, at most " +
           figure(kIdentifyMaxCells) + " values; CSV at most " + bytes(codec::kCsvMaxBytes) + ", column names of 1 to " +
           figure(codec::kCsvMaxNameBytes) + " bytes; at most " + figure(codec::kIdentifyMaxPrevious) +
           " `previous` rounds; `engine` 1 to " + figure(codec::kIdentifyMaxEngineName) +
           " of `A-Za-z0-9_.-`; a typed damping ratio from " + figure(codec::kIdentifyLowestTypedRatio) +
           " (a correction types one down to -omega h / 4)",
       "`core/include/softtune/identify.h` `kIdentifyMaxSamples`, `kIdentifyMaxProbes`, `kIdentifyMaxCells`; "
       "`server/codec/csv_recording.h` `kCsvMaxBytes`, `kCsvMaxNameBytes`; `server/codec/identify_codec.h` "
       "`kIdentifyMaxPrevious`, `kIdentifyMaxEngineName`, `kIdentifyLowestTypedRatio`; "
       "`core/include/softtune/identify_correction.h` `lowest_typed_damping_ratio`",
       "422 naming the row and column (`csv.rows.N.x`, `probes.x.N`); the fit runs at most " +
           figure(kIdentifyMaxIterations) + " Levenberg-Marquardt steps per window; `plot` strided to at most " +
           figure(codec::kIdentifyMaxPlotSamples) + " samples per probe"},
  };
}

// Preview frames: sizes, waiters, raster processes and the caches.
std::vector<LimitRow> preview_rows() {
  const render::PipelineOptions pipeline;
  return {
      {"preview",
       figure(render::caps::kMinSide) + " to " + figure(render::caps::kMaxWidth) + " x " +
           figure(render::caps::kMaxHeight) + " px, 1 to " + figure(render::caps::kMaxFrames) + " frames",
       "`render/include/softtune/render/frame_pipeline.h` (`render::caps`)",
       "422 naming `size` / `frames`; more frames than a scene runs are clamped with a `frames_clamped` warning"},
      {"requests waiting for preview frames", figure(app::kMaxPreviewWaiters) + " at a time (`\"wait\": true`)",
       "`server/app/preview_service.h` `kMaxPreviewWaiters`",
       "answered at once as with `\"wait\": false` (status `rendering`, `progress_url`) with a `wait_declined` "
       "warning; the render goes on. Without the cap, 16 waiting previews held all " + figure(hl::kDefaultThreads) +
           " worker threads and health went unanswered for 4 s"},
      {"one preview frame", millis(render::kFrameTimeoutMs) + " in its raster process",
       "`render/include/softtune/render/renderer.h` `kFrameTimeoutMs`",
       "the raster process is killed and the preview fails with a 500 problem saying so; the next frame starts a new "
       "process"},
      {"raster processes",
       "one per render worker (" + figure(pipeline.workers) + "), started on the first frame, ended after " +
           millis(pipeline.release_renderer_after_ms) + " without one",
       "`render/include/softtune/render/frame_pipeline.h` `PipelineOptions`",
       "a raster process that dies fails its frame (500 naming the signal), not the server"},
      {"caches",
       "tune responses " + figure(hl::kResponseCacheEntries) + " entries / " + bytes(hl::kResponseCacheBytes) +
           " (a canonical request and each spelling of it seen are an entry each, sharing the body); preview PNGs " +
           bytes(pipeline.cache_bytes) + " (counted by the strings' capacity: each PNG is shrunk to its bytes)",
       "`server/http/limits.h` `kResponseCacheEntries`, `kResponseCacheBytes`; `frame_pipeline.h` "
       "`PipelineOptions::cache_bytes`",
       "least recently used evicted"},
  };
}

}  // namespace

std::vector<LimitRow> limit_rows() {
  std::vector<LimitRow> rows = transport_rows();
  for (auto part : {request_rows(), preview_rows()}) rows.insert(rows.end(), part.begin(), part.end());
  return rows;
}

nlohmann::json limits_json() {
  nlohmann::json out = nlohmann::json::object();
  for (const NumericLimit& l : numeric_limits()) {
    const auto whole = static_cast<long long>(l.value);
    if (static_cast<double>(whole) == l.value) {
      out[std::string(l.key)] = whole;
    } else {
      out[std::string(l.key)] = l.value;
    }
  }
  return out;
}

std::string limits_table_markdown() {
  std::string out = "| Cap | Value | Defined in | Above it |\n| --- | --- | --- | --- |\n";
  for (const LimitRow& r : limit_rows()) out += "| " + r.cap + " | " + r.value + " | " + r.defined_in + " | " + r.above + " |\n";
  return out;
}

}  // namespace softtune::http
