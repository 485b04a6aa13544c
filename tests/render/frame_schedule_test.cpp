// Which game frames a preview shows (render/src/frame_schedule.cpp): the whole run, ends included.
#include "softtune/render/frame_schedule.h"

#include <gtest/gtest.h>

#include <cmath>

namespace softtune::render {
namespace {

TEST(FrameSchedule, FirstFrameAtTheStartLastAtTheRunsEnd) {
  // The cases the old rounded-down stride cut short: chain 480 steps in 300 frames (ended at step 299),
  // bridge 300 in 120 (238), the oscillator 180 in 60 (59), a 6 s vehicle in 53 (312 of 360).
  for (const auto [run, n] : {std::pair{480, 300}, {300, 120}, {180, 60}, {360, 53}, {480, 481}, {7, 2}}) {
    const std::vector<int> at = spread_frames(run, n);
    ASSERT_EQ(static_cast<int>(at.size()), n);
    EXPECT_EQ(at.front(), 0);
    EXPECT_EQ(at.back(), run) << run << " steps in " << n << " frames";
    for (int k = 1; k < n; ++k) {
      EXPECT_GT(at[k], at[k - 1]) << "frame " << k << " repeats a game frame";
      // Each is the nearest game frame to the evenly spaced ideal k run / (n - 1).
      EXPECT_LE(std::abs(at[k] - static_cast<double>(k) * run / (n - 1)), 0.5) << "frame " << k;
    }
  }
}

TEST(FrameSchedule, OneFrameIsTheStartAndNoFramesIsEmpty) {
  EXPECT_EQ(spread_frames(480, 1), std::vector<int>{0});
  EXPECT_TRUE(spread_frames(480, 0).empty());
  EXPECT_EQ(spread_frames(0, 3), (std::vector<int>{0, 0, 0}));
}

TEST(FrameSchedule, FirstFrameShowingAGameFrame) {
  const std::vector<int> at = spread_frames(120, 5);  // 0, 30, 60, 90, 120
  EXPECT_EQ(first_frame_showing(at, 0), 0);
  EXPECT_EQ(first_frame_showing(at, 2), 1);
  EXPECT_EQ(first_frame_showing(at, 60), 2);
  EXPECT_EQ(first_frame_showing(at, 120), 4);
  EXPECT_EQ(first_frame_showing(at, 121), -1);
}

}  // namespace
}  // namespace softtune::render
