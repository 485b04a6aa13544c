#pragma once
// The design answer for a mass-ratio chain (sequential_impulse.h, chain_solvers.h): for a light link and a
// weight `mass_ratio` times heavier, each joint tuned to the asked frequency and damping ratio, per solver
//   - with the user's settings (count, warm start): the highest stable frequency, bisected and confirmed
//     by simulation (find_chain_limit), and whether the asked frequency is stable with margin;
//   - the fewest counts (iterations or substeps, chain_count_name) that keep the chain stable up to
//     margin x the asked frequency, searched from 1 up to kMaxDesignCount.
// "Stable with margin": the chain's limit (its first crossing into instability, going up in frequency) is
// at least margin x the asked frequency (default kDefaultChainMargin = 1.25, i.e. 25 % headroom).

#include <optional>
#include <vector>

#include "softtune/sequential_impulse.h"

namespace softtune {

inline constexpr double kDefaultChainMargin = 1.25;
inline constexpr double kMaxChainMargin = 10.0;
inline constexpr int kMaxDesignCount = 64;  ///< the fewest-count search stops here

/// One solver's settings as the user runs it.
struct ChainSolverSettings {
  ChainSolver solver = ChainSolver::box2d_v2_4;
  int count = 1;            ///< chain_count_name(solver)
  bool warm_start = true;
  double h = 1.0 / 60.0;    ///< s, one engine step
  std::optional<double> linear_damping;  ///< 1/s, Jolt's mLinearDamping when the user set it
  int collision_steps = 1;  ///< Jolt's collision steps per engine step (each a full warm-started step)
};

/// What a tune request asks about its chain (the `chain` object of the tune contract).
struct ChainAsk {
  double mass_ratio = 1.0;                 ///< m2 / m1, [1, 1e9]
  double margin = kDefaultChainMargin;     ///< [1, kMaxChainMargin]
  std::vector<ChainSolver> solvers{kAllChainSolvers.begin(), kAllChainSolvers.end()};
};

struct ChainDesignRequest {
  double mass_ratio = 1.0;     ///< m2 / m1, [1, 1e9]
  double frequency_hz = 0.0;   ///< Hz, each joint's asked natural frequency
  double damping_ratio = 0.0;
  double margin = kDefaultChainMargin;  ///< [1, kMaxChainMargin]
  std::vector<ChainSolverSettings> solvers;
};

struct ChainDesign {
  ChainSolverSettings settings;
  ChainLimit limit;             ///< with the user's settings (frequency ratios at settings.h)
  bool stable_at_target = false;  ///< the asked frequency lies below the limit
  bool meets_margin = false;      ///< the limit reaches margin x the asked frequency
  std::optional<int> fewest_count;  ///< empty: no count up to kMaxDesignCount reaches the margin
  std::optional<double> fewest_count_limit_hz;  ///< that count's highest stable frequency (or the scan top)
};

/// The answer per solver of the request, in its order.
std::vector<ChainDesign> design_chain(const ChainDesignRequest& request);

/// The chain as `settings` run it (chain_model, with the user's linear damping for Jolt).
ChainModel chain_model_for(const ChainSolverSettings& settings, int count, double mass_ratio, double omega,
                           double zeta);

}  // namespace softtune
