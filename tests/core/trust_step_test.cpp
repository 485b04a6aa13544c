// The trust-region step against closed forms: the Newton step when it fits, a step of exactly the radius
// along the Levenberg-Marquardt curve when it does not, only the moving direction of a rank-deficient model,
// and the lower bound held on the second coordinate.
#include "softtune/trust_step.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace softtune {
namespace {

constexpr double kNoRadius = std::numeric_limits<double>::infinity();

TEST(TrustStep, NewtonStepWhenItFits) {
  Eigen::Matrix2d J;
  J << 2.0, 0.5, -0.3, 1.5;
  const Eigen::Vector2d r(3.0, -1.0);
  const TrustStep s = trust_step(J, r, {0.0, 10.0}, kNoRadius, 0.0);
  const Eigen::Vector2d newton = -J.inverse() * r;
  EXPECT_NEAR((s.step - newton).norm(), 0.0, 1e-12);
  EXPECT_NEAR(s.predicted.norm(), 0.0, 1e-12);
  EXPECT_FALSE(s.on_bound);
}

// With J = I the Levenberg-Marquardt curve is the ray -r / (1 + mu): the step is -r scaled to the radius.
TEST(TrustStep, RadiusCutsTheStepAlongItsCurve) {
  const Eigen::Vector2d r(30.0, 40.0);
  const TrustStep s = trust_step(Eigen::Matrix2d::Identity(), r, {0.0, 100.0}, 10.0, 0.0);
  EXPECT_NEAR(s.step.norm(), 10.0, 1e-9);
  EXPECT_NEAR(s.step(0), -6.0, 1e-9);
  EXPECT_NEAR(s.step(1), -8.0, 1e-9);
}

// A response that does not move with the first coordinate (J's first column zero, a clamped stiffness):
// the step leaves that coordinate alone and the model's least residual stays in the unmoved direction.
TEST(TrustStep, RankDeficientModelMovesOnlyWhereTheResponseMoves) {
  Eigen::Matrix2d J;
  J << 0.0, 0.0, 0.0, 2.0;
  const Eigen::Vector2d r(5.0, 4.0);
  const TrustStep s = trust_step(J, r, {0.0, 10.0}, kNoRadius, 0.0);
  EXPECT_NEAR(s.step(0), 0.0, 1e-9);
  EXPECT_NEAR(s.step(1), -2.0, 1e-9);
  EXPECT_NEAR(s.predicted(0), 5.0, 1e-9);
  EXPECT_NEAR(s.predicted(1), 0.0, 1e-9);
}

// The Newton step would need the second coordinate at -3 (a negative damping ratio): it stops at the bound
// and the first coordinate is the best for it there, -(J_u . (r + J_v dv)) / |J_u|^2.
TEST(TrustStep, LowerBoundHoldsTheSecondCoordinate) {
  Eigen::Matrix2d J;
  J << 1.0, 0.5, 0.0, 1.0;
  const Eigen::Vector2d r(2.0, 5.0), x(0.0, 2.0);
  const TrustStep s = trust_step(J, r, x, kNoRadius, 0.0);
  EXPECT_TRUE(s.on_bound);
  EXPECT_NEAR(x(1) + s.step(1), 0.0, 1e-12);
  EXPECT_NEAR(s.step(0), -(2.0 + 0.5 * -2.0), 1e-12);
  EXPECT_NEAR(s.predicted(0), 0.0, 1e-12);
  EXPECT_NEAR(s.predicted(1), 3.0, 1e-12);
}

}  // namespace
}  // namespace softtune
