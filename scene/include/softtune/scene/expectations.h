#pragma once
// The automated preset test: run a scene (once per mass model its expectations name) and check each
// expectation against the measured figures.

#include <optional>
#include <vector>

#include "softtune/scene/runner.h"

namespace softtune::scene {

struct ExpectationResult {
  Expectation expectation;
  MassModel mass_model = MassModel::effective;  ///< the run it was checked on
  std::optional<double> value;                  ///< the measured figure; empty when undefined (fails)
  bool passed = false;
};

struct CheckResult {
  bool passed = true;
  std::vector<SceneResult> runs;                ///< runs[0] uses the scene's own mass model
  std::vector<ExpectationResult> results;
};

/// The figure an expectation bounds, from one run; empty when it is undefined (no fit, no request, ...).
std::optional<double> metric_value(const Expectation& e, const SceneResult& run);

/// Runs and checks, in the engine of `engine` (its backend and engine_settings; the rest is ignored: the mass
/// models are the expectations'). `stages` of runs[0] gain `expectations`.
CheckResult check_scene(const Scene& scene, const RunOptions& engine = {});

}  // namespace softtune::scene
