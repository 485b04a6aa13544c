#include "softtune/render/view.h"

#include <gtest/gtest.h>

namespace softtune::render {
namespace {

TEST(View, MapsWorldToPixelsWithYDown) {
  Camera c;
  c.auto_fit = false;
  c.centre_m = {1.0, 2.0};
  c.width_m = 10.0;
  const View v = make_view(c, {640, 360});
  EXPECT_DOUBLE_EQ(v.pixels_per_m, 64.0);
  EXPECT_DOUBLE_EQ(v.px(1.0), 320.0);
  EXPECT_DOUBLE_EQ(v.py(2.0), 180.0);
  EXPECT_DOUBLE_EQ(v.px(2.0), 384.0);
  EXPECT_DOUBLE_EQ(v.py(3.0), 116.0);  // up in the world is up in the image
  EXPECT_DOUBLE_EQ(v.world_x(v.px(-3.25)), -3.25);
  EXPECT_DOUBLE_EQ(v.world_y(v.py(7.5)), 7.5);
}

TEST(View, FittedCameraShowsEveryPointBelowTheCaptionBand) {
  Bounds b;
  b.add(Vec2{-0.25, 0.0});
  b.add(Vec2{3.0, 1.6});
  for (ImageSize size : {ImageSize{640, 360}, ImageSize{360, 640}, ImageSize{100, 100}}) {
    const Camera c = fit_camera(b, static_cast<double>(size.width) / size.height);
    const View v = make_view(c, size);
    for (Vec2 p : {b.lo, b.hi, Vec2{b.lo.x, b.hi.y}, Vec2{b.hi.x, b.lo.y}}) {
      EXPECT_GE(v.px(p.x), 0.0);
      EXPECT_LE(v.px(p.x), size.width);
      EXPECT_GE(v.py(p.y), kCaptionBand * size.height - 1e-9);
      EXPECT_LE(v.py(p.y), size.height);
    }
  }
}

TEST(View, FittingAPointKeepsAMinimumWidth) {
  Bounds b;
  b.add(Vec2{5.0, 5.0});
  const Camera c = fit_camera(b, 16.0 / 9.0);
  EXPECT_GE(c.width_m, 0.5);
  EXPECT_DOUBLE_EQ(c.centre_m.x, 5.0);
}

TEST(View, AutoCameraFitsTheFrame) {
  DrawFrame f;
  f.circles.push_back({{10.0, 0.0}, 1.0, 0.0, Role::dynamic_body});
  const Camera c = resolve_camera(Camera{}, f, {640, 360});
  EXPECT_FALSE(c.auto_fit);
  EXPECT_DOUBLE_EQ(c.centre_m.x, 10.0);
  Camera fixed;
  fixed.auto_fit = false;
  fixed.width_m = 3.0;
  EXPECT_DOUBLE_EQ(resolve_camera(fixed, f, {640, 360}).width_m, 3.0);
}

}  // namespace
}  // namespace softtune::render
