#include "app/stability_cost.h"

#include <algorithm>

#include "app/cost_drivers.h"

namespace softtune::app {
namespace {

// Rates measured on the reference machine (stability_cost.h).
constexpr double kSweepCaseSeconds = 0.4e-6;
constexpr double kSweepStepSeconds = 30e-9;
constexpr double kSweepEncodeSeconds = 10e-6, kSweepEncodeBytes = 3 * 1024, kSweepCaseBytes = 128;
constexpr double kChainCaseSeconds = 10e-6;
constexpr double kChainIterationSeconds = 15e-9, kChainStepSeconds = 15e-9;
constexpr double kChainEncodeSeconds = 5e-6, kChainEncodeBytes = 2 * 1024;

double ratio(std::size_t given, std::size_t fallback) {
  return fallback == 0 ? static_cast<double>(given) : static_cast<double>(given) / static_cast<double>(fallback);
}

}  // namespace

std::size_t chain_case_count(const codec::StabilityRequest& q) {
  if (!q.run_chain) return 0;
  const ChainSweepSettings& c = q.chain;
  return c.warm_start.size() * c.mass_ratios.size() * c.iterations.size() * c.frequency_ratios.size();
}

RequestCost stability_cost(const codec::StabilityRequest& q) {
  const SweepSettings& s = q.sweep;
  const SweepSettings d = default_sweep_settings();
  const ChainSweepSettings dc = default_chain_sweep_settings();
  const double cases = static_cast<double>(codec::grid_case_bound(s));
  const double steps = std::max(1000, s.observe_steps);
  RequestCost cost;
  cost.cpu_seconds = cases * (kSweepCaseSeconds + steps * kSweepStepSeconds);
  cost.peak_bytes = cases * kSweepCaseBytes;
  if (q.include_cases) {
    cost.cpu_seconds += cases * kSweepEncodeSeconds;
    cost.peak_bytes += cases * kSweepEncodeBytes;
  }
  const double chain_cases = static_cast<double>(chain_case_count(q));
  if (chain_cases > 0) {
    const ChainSweepSettings& c = q.chain;
    double iterations = 0.0;  // mean Gauss-Seidel iterations per step over the chain's cases
    for (int n : c.iterations) iterations += n;
    iterations /= static_cast<double>(c.iterations.size());
    const double chain_steps = std::max(1000, c.observe_steps);
    cost.cpu_seconds += chain_cases * (kChainCaseSeconds + chain_steps * (iterations * kChainIterationSeconds + kChainStepSeconds));
    if (q.include_cases) {
      cost.cpu_seconds += chain_cases * kChainEncodeSeconds;
      cost.peak_bytes += chain_cases * kChainEncodeBytes;
    }
  }
  cost.work = std::to_string(static_cast<long long>(cases)) + " sweep cases x " +
              std::to_string(static_cast<long long>(steps)) + " steps";
  if (chain_cases > 0) cost.work += " and " + std::to_string(static_cast<long long>(chain_cases)) + " chain cases";
  if (q.include_cases) cost.work += ", each listed in the answer";

  CostDrivers drivers;
  drivers.add("observe_steps", steps / std::max(1000, d.observe_steps));
  drivers.add("methods", ratio(s.methods.size(), d.methods.size()));
  drivers.add("steps", ratio(s.steps.size(), d.steps.size()));
  drivers.add("masses", ratio(s.masses.size(), d.masses.size()));
  drivers.add("damping_ratios", ratio(s.damping_ratios.size(), d.damping_ratios.size()));
  drivers.add("frequency_ratios", ratio(s.frequency_ratios.size(), d.frequency_ratios.size()));
  drivers.add("stiffnesses", ratio(s.stiffnesses.size(), d.stiffnesses.size()));
  if (chain_cases > 0) {
    double iterations = 0.0, default_iterations = 0.0;
    for (int n : q.chain.iterations) iterations += n;
    for (int n : dc.iterations) default_iterations += n;
    drivers.add("chain.iterations", iterations / default_iterations);
    drivers.add("chain.mass_ratios", ratio(q.chain.mass_ratios.size(), dc.mass_ratios.size()));
    drivers.add("chain.frequency_ratios", ratio(q.chain.frequency_ratios.size(), dc.frequency_ratios.size()));
  }
  if (q.include_cases && cost.peak_bytes > 0) drivers.add("include_cases", 1.0 + 1e-9);
  cost.fields = drivers.fields();
  return cost;
}

}  // namespace softtune::app
