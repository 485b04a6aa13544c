// The camera of a run (render/src/camera_path.cpp): fixed, fitted to the action (static shapes clipped
// near it), or following a box, always leaving the title band free.
#include "softtune/render/camera_path.h"

#include <gtest/gtest.h>

#include <cmath>

namespace softtune::render {
namespace {

PolygonShape box(double x0, double y0, double x1, double y1, Role role) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, role};
}

bool inside(const Bounds& view, const Bounds& b) {
  return b.lo.x >= view.lo.x - 1e-9 && b.hi.x <= view.hi.x + 1e-9 && b.lo.y >= view.lo.y - 1e-9 &&
         b.hi.y <= view.hi.y + 1e-9;
}

// A 1 m box driving from x = 0 to x = 30 over a 200 m static ground.
std::vector<DrawFrame> drive(int frames) {
  std::vector<DrawFrame> out;
  for (int i = 0; i < frames; ++i) {
    DrawFrame f;
    f.polygons.push_back(box(-100, -1, 100, 0, Role::static_body));
    const double x = 30.0 * i / (frames - 1);
    f.polygons.push_back(box(x, 0, x + 1, 1, Role::dynamic_body));
    out.push_back(f);
  }
  return out;
}

TEST(CameraPath, StaticShapesCountOnlyNearTheAction) {
  const Bounds b = action_bounds(drive(11));
  // The moving box spans x 0..31, y 0..1; of the 200 m ground only the strip within a quarter of 31 m
  // (7.75 m) of it counts.
  EXPECT_NEAR(b.lo.x, -7.75, 1e-12);
  EXPECT_NEAR(b.hi.x, 38.75, 1e-12);
  EXPECT_NEAR(b.lo.y, -1.0, 1e-12);
  EXPECT_NEAR(b.hi.y, 1.0, 1e-12);
}

TEST(CameraPath, FitCoversTheWholeRunBelowTheBand) {
  const auto frames = drive(11);
  const ImageSize size{640, 360};
  const auto cameras = run_cameras(Camera{}, {}, frames, size);
  ASSERT_EQ(cameras.size(), frames.size());
  const Bounds view = visible_below_band(cameras[0], size);
  for (const DrawFrame& f : frames) EXPECT_TRUE(inside(view, bounds_of(DrawFrame{{f.polygons[1]}})));
  for (const Camera& c : cameras) EXPECT_DOUBLE_EQ(c.width_m, cameras[0].width_m);  // one camera: no jumps
}

TEST(CameraPath, FollowKeepsTheBoxWholeAtTheGivenWidth) {
  const auto frames = drive(31);
  Follow follow;
  follow.width_m = 8.0;
  for (const DrawFrame& f : frames) follow.bounds_m.push_back(bounds_of(DrawFrame{{f.polygons[1]}}));
  for (ImageSize size : {ImageSize{640, 360}, ImageSize{200, 400}}) {
    const auto cameras = run_cameras(Camera{}, follow, frames, size);
    for (std::size_t i = 0; i < frames.size(); ++i) {
      EXPECT_DOUBLE_EQ(cameras[i].width_m, 8.0);
      EXPECT_TRUE(inside(visible_below_band(cameras[i], size), follow.bounds_m[i])) << i;
    }
    // It moves with the box: 30 m over the run.
    EXPECT_GT(cameras.back().centre_m.x - cameras.front().centre_m.x, 20.0);
  }
  // A box wider than the asked width widens the view.
  Follow wide = follow;
  wide.width_m = 0.5;
  EXPECT_GT(run_cameras(Camera{}, wide, frames, {640, 360})[0].width_m, 1.0);
}

TEST(CameraPath, FixedCameraIsUsedAsIs) {
  Camera fixed;
  fixed.auto_fit = false;
  fixed.centre_m = {3, 4};
  fixed.width_m = 7;
  const auto cameras = run_cameras(fixed, {}, drive(3), {640, 360});
  ASSERT_EQ(cameras.size(), 3u);
  EXPECT_DOUBLE_EQ(cameras[2].centre_m.x, 3.0);
  EXPECT_DOUBLE_EQ(cameras[2].width_m, 7.0);
}

}  // namespace
}  // namespace softtune::render
