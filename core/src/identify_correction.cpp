#include "softtune/identify_correction.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "softtune/trust_step.h"

namespace softtune {
namespace {

// The coordinates of identify_correction.h: (ln f / 0.01, zeta / 0.02), one unit of the bar on each axis.
Eigen::Vector2d point(const ResponseValues& v) {
  return {std::log(v.frequency_hz) / kCorrectionFrequencyBar, v.damping_ratio / kCorrectionDampingBar};
}
ResponseValues values(const Eigen::Vector2d& p) {
  return {std::exp(p(0) * kCorrectionFrequencyBar), p(1) * kCorrectionDampingBar};
}

// What the rounds say so far: the model J, the best round and the trust region, replayed from the first
// round so the answer depends on the rounds alone (the service keeps no state between requests).
struct Replay {
  Eigen::Matrix2d J = Eigen::Matrix2d::Identity();
  std::size_t best = 0;
  double radius = kCorrectionFirstRadius;
  int failures_in_a_row = 0;  // rounds that did not improve on the best before them
};

Replay replay(std::span<const Eigen::Vector2d> x, std::span<const Eigen::Vector2d> r) {
  Replay s;
  for (std::size_t i = 1; i < x.size(); ++i) {
    const Eigen::Vector2d step = x[i] - x[s.best];
    const double before = r[s.best].norm(), after = r[i].norm();
    const bool improved = after < before;
    if (step.norm() > 1e-9) {
      const double predicted = before - (r[s.best] + s.J * step).norm();
      const double ratio = predicted > 0.0 ? (before - after) / predicted : (improved ? 1.0 : -1.0);
      // Broyden's update: the least change of J (Frobenius) with J step = the change measured.
      s.J += (r[i] - r[s.best] - s.J * step) * step.transpose() / step.squaredNorm();
      // Nocedal & Wright, Algorithm 4.1: shrink after a poor prediction, grow after a good full step.
      if (ratio < 0.25) {
        s.radius = 0.5 * std::min(s.radius, step.norm());
      } else if (ratio > 0.75 && step.norm() >= 0.9 * s.radius) {
        s.radius = std::min(2.0 * s.radius, kCorrectionMaxRadius);
      }
    }
    s.failures_in_a_row = improved ? 0 : s.failures_in_a_row + 1;
    if (improved) s.best = i;
  }
  return s;
}

// The residual as a response: r = (ln(f / f_asked) / 0.01, (zeta - zeta_asked) / 0.02) read back.
ResponseValues response_of(const ResponseValues& asked, const Eigen::Vector2d& r) {
  return {asked.frequency_hz * std::exp(r(0) * kCorrectionFrequencyBar),
          std::max(0.0, asked.damping_ratio + r(1) * kCorrectionDampingBar)};
}

// A negative damping ratio is typed only once the engine has shown it damps by itself: a round typed with
// at most half the asked ratio (or the bar, asked none) still measured more than asked plus the bar. An
// explicit step (Bullet's spring) adds no damping of its own, and a negative ratio typed into it grows
// instead of settling; the first round, typed as asked, cannot tell the two apart.
double damping_floor(const ResponseValues& asked, std::span<const CorrectionRound> rounds, double lowest) {
  const double little = std::max(0.5 * asked.damping_ratio, kCorrectionDampingBar);
  for (const CorrectionRound& r : rounds) {
    if (r.typed.damping_ratio <= little &&
        r.measured.damping_ratio > asked.damping_ratio + kCorrectionDampingBar) {
      return std::min(0.0, lowest);
    }
  }
  return 0.0;
}

bool inside_bar(const Eigen::Vector2d& r) { return r.lpNorm<Eigen::Infinity>() <= 1.0; }

}  // namespace

bool meets_bar(const ResponseValues& asked, const ResponseValues& measured) {
  return std::abs(measured.frequency_hz / asked.frequency_hz - 1.0) <= kCorrectionFrequencyBar &&
         std::abs(measured.damping_ratio - asked.damping_ratio) <= kCorrectionDampingBar;
}

double lowest_typed_damping_ratio(double frequency_hz, double step_s) {
  return -0.25 * 2.0 * std::numbers::pi * frequency_hz * step_s;
}

Correction correct_response(const ResponseValues& asked, std::span<const CorrectionRound> rounds,
                            double lowest_damping_ratio) {
  const double lower = damping_floor(asked, rounds, lowest_damping_ratio) / kCorrectionDampingBar;
  std::vector<Eigen::Vector2d> x, r;
  const Eigen::Vector2d target = point(asked);
  for (const CorrectionRound& round : rounds) {
    x.push_back(point(round.typed));
    r.push_back(point(round.measured) - target);
  }
  const Replay s = replay(x, r);
  const CorrectionRound& best = rounds[s.best];
  Correction out;
  out.method = rounds.size() < 2 ? CorrectionMethod::scaled : CorrectionMethod::secant;
  out.best_round = s.best;
  out.trust_radius = s.radius;
  // Any round within the bar ends the rounds, even where another is nearer in the Euclidean sense the
  // steps use (1.1 % / 0 is nearer than 0.9 % / 0.019, and only the second meets the bar).
  std::optional<std::size_t> met;
  for (std::size_t i = 0; i < rounds.size(); ++i) {
    if (meets_bar(asked, rounds[i].measured) && (!met || r[i].norm() < r[*met].norm())) met = i;
  }
  if (met) {
    out.verdict = CorrectionVerdict::met;
    out.best_round = *met;
    out.next = rounds[*met].typed;
    out.expected = rounds[*met].measured;
    return out;
  }
  // Where the model itself cannot reach the bar with any step (J has lost a direction, or the request
  // needs a damping ratio below the floor), more rounds will not help: said from a second recording on.
  const double unlimited = std::numeric_limits<double>::infinity();
  const bool beyond =
      rounds.size() >= 2 && !inside_bar(trust_step(s.J, r[s.best], x[s.best], unlimited, lower).predicted);
  // Two rounds in a row worse than the best, each where the model said it would improve, or a region
  // shrunk below what a recording resolves: the response does not follow any smooth model at this scale.
  if (s.failures_in_a_row >= 2 || s.radius < kCorrectionMinRadius) {
    out.verdict = beyond ? CorrectionVerdict::beyond_reach : CorrectionVerdict::stalled;
    out.next = best.typed;
    out.expected = best.measured;
    return out;
  }
  const TrustStep step = trust_step(s.J, r[s.best], x[s.best], s.radius, lower);
  out.next = values(x[s.best] + step.step);
  out.expected = response_of(asked, step.predicted);
  out.verdict = beyond ? CorrectionVerdict::beyond_reach : CorrectionVerdict::converging;
  return out;
}

}  // namespace softtune
