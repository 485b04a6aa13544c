#include "softtune/trust_step.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace softtune {
namespace {

// d(mu) = -(J^T J + mu I)^-1 J^T r; mu > 0 makes the matrix invertible even for a rank-deficient J.
Eigen::Vector2d levenberg_marquardt(const Eigen::Matrix2d& J, const Eigen::Vector2d& r, double mu) {
  const Eigen::Matrix2d a = J.transpose() * J + mu * Eigen::Matrix2d::Identity();
  return -(a.inverse() * (J.transpose() * r));
}

// The Levenberg-Marquardt step no longer than radius: mu = 0 when that fits (and J^T J is well
// conditioned), else the mu of |d(mu)| = radius, by bisection on ln mu. The smallest mu (1e-12 of J's
// scale) stands for mu -> 0+, the minimum-norm solution of a rank-deficient J.
Eigen::Vector2d bounded_step(const Eigen::Matrix2d& J, const Eigen::Vector2d& r, double radius) {
  const double scale = std::max((J.transpose() * J).trace(), 1e-300);
  double lo = 1e-12 * scale;
  Eigen::Vector2d d = levenberg_marquardt(J, r, lo);
  if (d.norm() <= radius) {
    const Eigen::Matrix2d jtj = J.transpose() * J;
    if (std::abs(jtj.determinant()) > 1e-12 * scale * scale) {
      const Eigen::Vector2d newton = levenberg_marquardt(J, r, 0.0);
      if (newton.allFinite() && newton.norm() <= radius) return newton;
    }
    return d;
  }
  double hi = scale;
  while (levenberg_marquardt(J, r, hi).norm() > radius) hi *= 4.0;
  for (int i = 0; i < 100 && hi / lo > 1.0 + 1e-12; ++i) {
    const double mid = std::sqrt(lo * hi);
    if (levenberg_marquardt(J, r, mid).norm() > radius) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return levenberg_marquardt(J, r, hi);
}

}  // namespace

TrustStep trust_step(const Eigen::Matrix2d& J, const Eigen::Vector2d& r, const Eigen::Vector2d& x, double radius,
                     double lower) {
  TrustStep out;
  out.step = bounded_step(J, r, radius);
  if (x(1) + out.step(1) < lower) {
    // The ball's minimiser leaves the half-plane, so (the model being convex) the constrained one lies on
    // its edge: fix the second coordinate there and minimise over the first within what is left of the ball.
    out.on_bound = true;
    const double dv = lower - x(1);
    const Eigen::Vector2d rest = r + J.col(1) * dv;
    const double ju = J.col(0).squaredNorm();
    const double reach = std::sqrt(std::max(0.0, radius * radius - dv * dv));
    const double du = ju > 0.0 ? std::clamp(-J.col(0).dot(rest) / ju, -reach, reach) : 0.0;
    out.step = {du, dv};
  }
  out.predicted = r + J * out.step;
  return out;
}

}  // namespace softtune
