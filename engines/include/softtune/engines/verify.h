#pragma once
// `softtune verify` (issue 15): a tuning run in the real engines linked in process. Per engine, the
// oscillator is built from the engine's report alone (its `parameters`, then its `exact`), stepped, and
// its trajectory fitted, so the answer holds measured against predicted and requested side by side.

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "softtune/engines/engine_run.h"
#include "softtune/tune.h"

namespace softtune::engines {

/// What a run did, fitted from its trajectory (fit_response, core/response_fit.h).
struct Measured {
  std::optional<double> frequency_hz;   ///< Hz, natural frequency; empty when the fit fails
  std::optional<double> damping_ratio;
  std::optional<double> residual;       ///< RMS fit residual / RMS motion (0 = a clean linear response)
  bool finite = true;                   ///< false when the engine returned NaN or infinity
};
Measured measure(const RunTrajectory& trajectory, double dt);

struct VerifyOptions {
  double duration_s = 10.0;  ///< s simulated per run
  RunBody body = RunBody::point;
  double x0 = 0.01;          ///< m, initial stretch
};

/// Bounds of a verify request (checked by the codec, listed in the OpenAPI document).
inline constexpr double kVerifyMaxDuration = 60.0;  ///< s
inline constexpr double kVerifyMaxSteps = 2e5;      ///< duration x fps x substeps per run

struct EngineVerification {
  const RealEngine* engine = nullptr;
  RunTrajectory trajectory;                ///< with the report's `parameters`
  Measured measured;
  std::optional<RunTrajectory> exact_trajectory;  ///< with `exact`, when the report has it
  std::optional<Measured> exact_measured;
};

/// Runs one engine for a tune result (whose request is `request`): the report of the engine's model,
/// typed into the real engine.
EngineVerification verify_engine(const RealEngine& engine, const TuneResult& result, const TuneRequest& request,
                                 const VerifyOptions& options);

/// Every real engine linked in process, and one by name (null when not linked).
std::span<const RealEngine* const> real_engines();
const RealEngine* find_real_engine(std::string_view name);

/// The index of a model in engine_models(), or engine_models().size().
std::size_t model_index(std::string_view name);

}  // namespace softtune::engines
