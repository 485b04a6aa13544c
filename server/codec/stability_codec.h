#pragma once
// The stability contract (`softtune stability`, later GET|POST /api/v1/stability): no request = the
// default sweep; a request narrows or widens the grid. Field list: docs/accuracy-and-stability.md.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "plot/plot_model.h"
#include "softtune/sequential_impulse.h"
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
};

/// An empty object (or null) is the default sweep. Throws Problem (422) naming the field and the rule.
StabilityRequest decode_stability_request(const nlohmann::json& doc);

/// Runs the sweep and the chain; the JSON has summary, cases (unless summary only), chain, stages.
nlohmann::json run_stability(const StabilityRequest& request);
nlohmann::json run_stability(const nlohmann::json& doc);

/// Spectral radius against omega h per integrator at one damping ratio (log-log, reference line at 1).
plot::Plot stability_map_plot(double damping_ratio);

/// Stability maps at zeta = 0, 0.1, 1 and 10, and the chain's highest stable frequency per mass ratio.
std::string stability_svg(const nlohmann::json& encoded);

}  // namespace softtune::codec
