#pragma once
// One step of a trust-region Gauss-Newton (Levenberg-Marquardt) method on a 2-D linear model, the step the
// black-box correction (identify_correction.h) takes: minimise |r + J d| over steps d with |d| <= radius
// and x + d >= lower on the second coordinate (a damping ratio is never negative). Nocedal & Wright,
// "Numerical Optimization" (2nd ed.), 4.3: d(mu) = -(J^T J + mu I)^-1 J^T r with the smallest mu >= 0 that
// keeps |d(mu)| <= radius; |d(mu)| falls as mu grows, so mu is found by bisection. A rank-deficient J (an
// engine whose response does not move in some direction) is handled by the same mu > 0: the step goes
// only where the model says the response moves.

#include <Eigen/Core>

namespace softtune {

struct TrustStep {
  Eigen::Vector2d step = Eigen::Vector2d::Zero();      ///< d
  Eigen::Vector2d predicted = Eigen::Vector2d::Zero();  ///< r + J d, the model's residual after the step
  bool on_bound = false;  ///< the lower bound on the second coordinate holds the step
};

/// The step for residual r and model J at x; radius > 0 (use +infinity for no trust region), x(1) >= lower.
TrustStep trust_step(const Eigen::Matrix2d& J, const Eigen::Vector2d& r, const Eigen::Vector2d& x, double radius,
                     double lower);

}  // namespace softtune
