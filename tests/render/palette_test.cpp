#include "softtune/render/palette.h"

#include <gtest/gtest.h>

namespace softtune::render {
namespace {

TEST(SpringColour, NeutralAtRestFullAtTheStretchLimits) {
  EXPECT_EQ(spring_colour(2.0, 2.0), palette::kSpringNeutral);
  EXPECT_EQ(spring_colour(2.0 * (1.0 + palette::kFullStretch), 2.0), palette::kSpringStretched);
  EXPECT_EQ(spring_colour(5.0, 2.0), palette::kSpringStretched);
  EXPECT_EQ(spring_colour(2.0 * (1.0 - palette::kFullStretch), 2.0), palette::kSpringCompressed);
  EXPECT_EQ(spring_colour(0.0, 2.0), palette::kSpringCompressed);
}

TEST(SpringColour, HalfwayIsTheMidpointBlend) {
  const Rgba c = spring_colour(1.0 + 0.5 * palette::kFullStretch, 1.0);
  EXPECT_NEAR(c.r, 0.5 * (palette::kSpringNeutral.r + palette::kSpringStretched.r), 1.0);
  EXPECT_NEAR(c.b, 0.5 * (palette::kSpringNeutral.b + palette::kSpringStretched.b), 1.0);
}

TEST(SpringColour, ZeroRestLengthOrNonFiniteIsNeutral) {
  EXPECT_EQ(spring_colour(1.0, 0.0), palette::kSpringNeutral);
  EXPECT_EQ(spring_colour(std::numeric_limits<double>::quiet_NaN(), 1.0), palette::kSpringNeutral);
}

TEST(RoleColours, RolesAreDistinguishableAndGhostIsTranslucent) {
  EXPECT_NE(role_colours(Role::static_body).fill, role_colours(Role::dynamic_body).fill);
  EXPECT_NE(role_colours(Role::dynamic_body).fill, role_colours(Role::probed).fill);
  EXPECT_EQ(role_colours(Role::dynamic_body).fill.a, 255);
  EXPECT_LT(role_colours(Role::ghost).fill.a, 128);
}

}  // namespace
}  // namespace softtune::render
