#pragma once
// The stability contract (`softtune stability`, later GET|POST /api/v1/stability): no request = the
// default sweep; a request narrows or widens the grid. Field list: docs/accuracy-and-stability.md.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "softtune/sequential_impulse.h"
#include "softtune/tune.h"
#include "softtune/stability_sweep.h"

namespace softtune::codec {

/// Request caps (also in openapi.json's x-softtune-limits and docs/limits-and-security.md "Limits").
inline constexpr std::size_t kMaxGridEntries = 32;  ///< entries of each list
inline constexpr std::size_t kMaxCases = 200000;    ///< product of the sweep lists
inline constexpr int kMinObserveSteps = 1000, kMaxObserveSteps = 100000;
inline constexpr double kMaxFrequencyRatio = 1000.0;
inline constexpr double kMinStep = 1e-9, kMaxStep = 1.0;  ///< s
inline constexpr double kMaxStiffness = 1e15;             ///< N/m
inline constexpr double kMaxMassRatio = 1e9;
inline constexpr int kMaxChainIterations = 256;

struct StabilityRequest {
  SweepSettings sweep = default_sweep_settings();
  ChainSweepSettings chain = default_chain_sweep_settings();
  bool run_chain = true;
  bool include_cases = true;  ///< false: counts and chain limits only (`--summary`)
  /// A preset's name: its tuned joints' highest stable frequencies (scene/preset_stability.h) instead of
  /// the sweep and the chain; it runs alone (other sweep fields beside it are refused).
  std::optional<std::string> preset;
  /// With a preset: its "engine" and "engine_settings" as given (an object; empty: the default engine), read
  /// by the app layer against the scene backends (app/simulate_app.h read_request_engine).
  nlohmann::json preset_engine = nlohmann::json::object();
};

/// Longest `preset` name (app::kMaxPresetNameLength; the preset store checks the characters).
inline constexpr std::size_t kMaxPresetName = 64;

/// A list of chain solver names (`field` names it in a Problem); empty when `value` is null.
std::optional<std::vector<ChainSolver>> read_chain_solvers(const nlohmann::json* value, const std::string& field);

/// "found", "none_in_range" (no limit inside the searched range), "unstable_at_lowest".
const char* limit_kind_name(LimitKind kind);

/// Cases of the sweep grid at most (run_sweep skips frequency cases above max_stiffness): methods x steps
/// x masses x damping_ratios x (frequency_ratios + stiffnesses). Capped at kMaxCases, and priced by
/// app::stability_cost.
std::size_t grid_case_bound(const SweepSettings& s);

/// An empty object (or null) is the default sweep. Throws Problem (422) naming the field and the rule.
StabilityRequest decode_stability_request(const nlohmann::json& doc);

/// The JSON answer: summary, cases (unless summary only), chain (when it ran), stages.
nlohmann::json encode_stability_result(const StabilityRequest& request, const SweepResult& sweep,
                                       const std::optional<ChainSweepResult>& chain, const StageList& stages);

}  // namespace softtune::codec
