#pragma once
// Where stability ends, as a number: the one routine every reported stability limit goes through (the
// chain's highest stable frequency per solver, the largest stable omega h per integrator, the design
// answers of `tune`).
//
// A limit is the first crossing, going up a parameter p (a frequency ratio, omega h), from "not unstable"
// to "unstable", judged on the spectral radius rho(p) of the step matrix with classify_spectral_radius():
// rho within 1 +- kMarginalBand is marginal, which counts as not unstable (as the sweep counts it), so a
// marginal plateau (semi-implicit Euler undamped below omega h = 2) lies on the stable side.
// 1. Bracket: walk an ascending scan of p until the first unstable point; the point before it is the
//    stable side. No unstable point: no limit inside the searched range. The first point unstable: the
//    limit lies below the range.
// 2. Bisect the bracket at its geometric midpoint (the scans are log-spaced) until
//    unstable_side / stable_side - 1 <= the relative tolerance (default 0.1 %).
// The stable side is the reported limit (a value known not to blow up); both sides are reported. An
// unstable island narrower than the scan's spacing below the first unstable scan point is not seen.

#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "softtune/discrete_analysis.h"

namespace softtune {

/// Relative width the bisection stops at: unstable_side / stable_side - 1 <= this.
inline constexpr double kLimitRelativeTolerance = 1e-3;

enum class LimitKind {
  found,               ///< the bracket holds the crossing
  none_in_range,       ///< not unstable at any scanned point: no limit inside the searched range
  unstable_at_lowest,  ///< unstable already at the lowest scanned point: the limit lies below the range
};

struct StabilityLimit {
  LimitKind kind = LimitKind::none_in_range;
  std::optional<double> stable_side;    ///< highest p found not unstable (the reported limit)
  std::optional<double> unstable_side;  ///< lowest p found unstable
  double stable_side_radius = 0.0;      ///< rho at stable_side (0 when empty)
  double unstable_side_radius = 0.0;    ///< rho at unstable_side (0 when empty)
  int evaluations = 0;                  ///< spectral radii computed
};

using SpectralRadiusOf = std::function<double(double p)>;

/// Bisects a bracket: `stable` not unstable, `unstable` unstable, 0 < stable < unstable (or either order
/// when the caller's parameter runs the other way: the sides are kept as given). Geometric midpoints.
StabilityLimit bisect_stability_limit(const SpectralRadiusOf& rho, double stable, double unstable,
                                      double relative_tolerance = kLimitRelativeTolerance);

/// Brackets on an ascending scan (all > 0), then bisects (see the header comment).
StabilityLimit find_stability_limit(const SpectralRadiusOf& rho, std::span<const double> scan,
                                    double relative_tolerance = kLimitRelativeTolerance);

/// `n` log-spaced points from lo to hi inclusive (n >= 2, 0 < lo < hi).
std::vector<double> log_scan(double lo, double hi, int n);

}  // namespace softtune
