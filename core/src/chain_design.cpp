#include "softtune/chain_design.h"

#include <algorithm>
#include <numbers>

#include "softtune/chain_solvers.h"
#include "softtune/stability_limit.h"

namespace softtune {
namespace {

constexpr double kLowestFrequencyRatio = 1e-3;  // as the sweep's scan
constexpr double kScanTopFrequencyRatio = 2.0;
constexpr int kScanPoints = 16;
constexpr int kObserveSteps = 1000;

}  // namespace

ChainModel chain_model_for(const ChainSolverSettings& s, int count, double ratio, double omega, double zeta) {
  ChainModel m = chain_model(s.solver, count, s.warm_start, ratio, omega, zeta, s.h);
  if (s.solver == ChainSolver::jolt) {
    if (s.linear_damping) m.linear_damping = *s.linear_damping;
    m.substeps = std::max(1, s.collision_steps);
  }
  return m;
}

std::vector<ChainDesign> design_chain(const ChainDesignRequest& q) {
  std::vector<ChainDesign> out;
  for (const ChainSolverSettings& s : q.solvers) {
    ChainDesign d;
    d.settings = s;
    const double target = q.frequency_hz * s.h;  // f h
    const double needed = q.margin * target;
    // The scan reaches past the margin when the asked frequency is above the sweep's top.
    const double top = std::max(kScanTopFrequencyRatio, 1.01 * needed);
    const std::vector<double> scan = log_scan(kLowestFrequencyRatio, top, kScanPoints);
    const auto model_at = [&](int count) {
      return [&s, &q, count](double fr) {
        return chain_model_for(s, count, q.mass_ratio, 2.0 * std::numbers::pi * fr / s.h, q.damping_ratio);
      };
    };
    d.limit = find_chain_limit(model_at(s.count), scan, kObserveSteps);
    d.limit.solver = s.solver;
    d.limit.count = s.count;
    const auto reaches = [&](const ChainLimit& l, double fr) {
      return l.kind == LimitKind::none_in_range || (l.highest_stable_frequency_ratio && *l.highest_stable_frequency_ratio >= fr);
    };
    d.stable_at_target = reaches(d.limit, target);
    d.meets_margin = reaches(d.limit, needed);
    // Fewest count: predicted not unstable at every f h of a scan up to margin x target (the first
    // crossing lies above it), then that count's own limit, bisected and confirmed.
    const double lowest = needed > 0.0 ? std::min(kLowestFrequencyRatio, 0.5 * needed) : kLowestFrequencyRatio;
    const std::vector<double> up_to_needed = log_scan(lowest, std::max(needed, 2.0 * lowest), 12);
    for (int n = 1; n <= kMaxDesignCount; ++n) {
      const ChainModelAt at = model_at(n);
      const SpectralRadiusOf rho = [&](double fr) { return chain_spectral_radius(chain_step_matrix(at(fr))); };
      if (find_stability_limit(rho, up_to_needed).kind != LimitKind::none_in_range) continue;
      d.fewest_count = n;
      const ChainLimit full = find_chain_limit(at, scan, kObserveSteps);
      if (full.highest_stable_frequency_hz) d.fewest_count_limit_hz = *full.highest_stable_frequency_hz;
      break;
    }
    out.push_back(d);
  }
  return out;
}

}  // namespace softtune
