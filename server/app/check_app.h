#pragma once
// The check use case, shared by `softtune check` and POST /api/v1/check: presets (files, directories, names or
// inline scenes) checked at every frame rate and substep count the game ships at, each measured figure
// compared with a baseline, the work split into CI shards and run on a thread pool. Reports as text (the CLI),
// JSON and JUnit XML (check_junit.h). docs/preset-ci.md.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/check_baseline.h"
#include "app/job_progress.h"
#include "codec/scene_engine_codec.h"
#include "softtune/scene/expectations.h"
#include "softtune/scene/scene.h"

namespace softtune::app {

/// One rate a preset is checked at.
struct CheckRate {
  double fps = 60.0;  ///< Hz
  int substeps = 1;
};

/// One preset to check: its name and scene document, or the problem that refused it (a preset that cannot be
/// loaded fails its case; it does not stop the others).
struct CheckInput {
  std::string name;
  nlohmann::json document;
  std::optional<nlohmann::json> problem;  ///< problem+json
};

/// `--shard I/N`: this runner checks every N-th preset of the sorted list, starting with the I-th (1-based).
struct Shard {
  int index = 1;
  int count = 1;
};

inline constexpr int kMaxCheckJobs = 64;       ///< -j
inline constexpr int kMaxShards = 10000;       ///< N of --shard I/N

struct CheckOptions {
  std::vector<double> fps;  ///< Hz; empty: each preset's declared rates.fps, else its world.fps
  std::vector<int> substeps;  ///< empty: each preset's rates.substeps, else its world.substeps
  int jobs = 1;             ///< threads checking cases at once (1..kMaxCheckJobs)
  Shard shard;
  const Baseline* baseline = nullptr;  ///< compare every figure with it (nullptr: no comparison)
  /// A job's progress: one unit per case; when it is cancelled, cases not yet started are left out
  /// (nullptr: the synchronous path).
  JobProgress* progress = nullptr;
  /// The engine every case runs in (its backend and settings); a null backend: Box2D 2.4 with its defaults.
  codec::SceneEngineChoice engine;
};

/// One preset at one rate.
struct CaseResult {
  std::string preset;
  CheckRate rate;
  bool passed = false;
  nlohmann::json expectations = nlohmann::json::array();  ///< as check_preset's
  std::optional<nlohmann::json> problem;                  ///< a preset or rate that could not run
  std::vector<Figure> figures;                            ///< every measured figure (check_baseline.h)
  std::vector<Drift> drift;                               ///< figures beyond their baseline tolerance
  bool in_baseline = false;                               ///< the baseline has an entry for this case
  double seconds = 0.0;                                   ///< s, wall time of this case
};

struct CheckReport {
  bool passed = true;
  std::vector<CaseResult> cases;  ///< presets in input order, each preset's rates fps-major
  std::size_t presets_total = 0;  ///< before sharding
  Shard shard;
  nlohmann::json engine;          ///< {name, version, settings} of the options' engine; null: the default
};

/// "mouse@60x1": the case's key in baselines, text lines and JUnit.
std::string case_key(const std::string& preset, const CheckRate& rate);

/// The rates `scene` is checked at under `options`: fps x substeps, each list from the options, else the
/// preset's declared rates, else its world's own value.
std::vector<CheckRate> check_rates(const scene::Scene& scene, const CheckOptions& options);

/// The scene at another rate: world.fps and world.substeps replaced. Tuning stays in seconds (response_frames
/// count basis_fps frames, 60 by default, not the world's), so the request is the same physical motion.
scene::Scene at_rate(scene::Scene scene, const CheckRate& rate);

/// The inputs of shard I/N: every N-th of `inputs` (sorted by name first), from the I-th.
std::vector<CheckInput> shard_inputs(std::vector<CheckInput> inputs, const Shard& shard);

/// Presets from the CLI's positional arguments: a directory gives every preset in it (validated against its
/// schema.json), a file one preset (validated against the schema.json beside it, else `fallback_schema_dir`'s).
/// A path that does not exist or a name given twice is a Problem (bad input).
std::vector<CheckInput> presets_from_paths(const std::vector<std::string>& paths, const std::string& fallback_schema_dir);

/// Checks every input of the shard at every rate; cases run on `options.jobs` threads, results in a fixed order.
CheckReport run_checks(const std::vector<CheckInput>& inputs, const CheckOptions& options);

/// The expectations of a check: [{probe, metric, mass_model, value, min, max, passed, note}].
nlohmann::json expectations_json(const scene::CheckResult& check);

/// The report as JSON: {passed, presets_total, shard, engine (when one was named), cases: [{preset, fps, substeps, key, passed,
/// expectations, problem?, drift: [{figure, baseline, value, message}], in_baseline, figures}]}.
nlohmann::json check_report_json(const CheckReport& report);

/// The baseline `report` measured, merged into `previous` (cases of other shards and their tolerances kept).
Baseline updated_baseline(const CheckReport& report, Baseline previous);

/// The messages of a failed case, one per failed expectation or drift ("drag.frequency_error = 0.33, above
/// max 0.03"); the problem's detail when it could not run.
std::vector<std::string> failure_messages(const CaseResult& c);

}  // namespace softtune::app
