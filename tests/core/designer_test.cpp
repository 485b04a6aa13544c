#include "softtune/designer.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace softtune;

TEST(Designer, FramesOnABasisGiveTheFrequency) {
  // One period lasts N frames on a B fps clock: f = B / N (docs/math.md).
  EXPECT_DOUBLE_EQ(frequency_from_frames(12, 60), 5.0);
  EXPECT_DOUBLE_EQ(frequency_from_frames(60, 60), 1.0);
  EXPECT_DOUBLE_EQ(frequency_from_frames(12, 120), 10.0);
}

TEST(Designer, OscillationLevelsAreTheTalksThree) {
  EXPECT_EQ(damping_ratio_of(Oscillation::free), 0.0);
  EXPECT_EQ(damping_ratio_of(Oscillation::some), 0.5);
  EXPECT_EQ(damping_ratio_of(Oscillation::none), 1.0);
}

TEST(Designer, StepSizeCountsSubsteps) {
  EXPECT_DOUBLE_EQ(step_size(60, 1), 1.0 / 60.0);
  EXPECT_DOUBLE_EQ(step_size(60, 4), 1.0 / 240.0);
}

TEST(Designer, AngularFrequencyRoundTrips) {
  EXPECT_DOUBLE_EQ(angular_frequency(1.0), 2.0 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(frequency_from_angular(angular_frequency(7.25)), 7.25);
}
