// The draw model's bounds (draw_model.cpp): an empty box until a point is added, every shape's extent (a
// circle's radius included), springs and anchors, the ground's height but not labels.
#include "softtune/render/draw_model.h"

#include <gtest/gtest.h>

namespace softtune::render {
namespace {

TEST(DrawModel, BoundsStartEmptyAndGrowToEachPoint) {
  Bounds b;
  EXPECT_TRUE(b.empty());
  b.add(Vec2{1.0, -2.0});
  EXPECT_FALSE(b.empty());
  EXPECT_DOUBLE_EQ(b.lo.x, 1.0);
  EXPECT_DOUBLE_EQ(b.hi.y, -2.0);
  b.add(Vec2{-3.0, 4.0});
  EXPECT_DOUBLE_EQ(b.lo.x, -3.0);
  EXPECT_DOUBLE_EQ(b.lo.y, -2.0);
  EXPECT_DOUBLE_EQ(b.hi.x, 1.0);
  EXPECT_DOUBLE_EQ(b.hi.y, 4.0);
  Bounds other;
  b.add(other);  // an empty box adds nothing
  EXPECT_DOUBLE_EQ(b.hi.x, 1.0);
  other.add(Vec2{10.0, 0.0});
  b.add(other);
  EXPECT_DOUBLE_EQ(b.hi.x, 10.0);
}

TEST(DrawModel, FrameBoundsCoverEveryShape) {
  DrawFrame f;
  EXPECT_TRUE(bounds_of(f).empty());
  f.ground_y_m = -5.0;
  EXPECT_TRUE(bounds_of(f).empty());  // a ground alone has no extent
  f.polygons.push_back({{{0, 0}, {1, 0}, {1, 1}}, Role::static_body});
  f.circles.push_back({{3.0, 0.5}, 0.5});                 // reaches x = 3.5 and y = 0
  f.springs.push_back({{0.5, 1.0}, {0.5, 2.0}, 1.0, std::nullopt});  // up to y = 2
  f.anchors.push_back({{-1.0, 0.5}});                     // down to x = -1
  f.labels.push_back({"far away", {100.0, 100.0}});       // labels are left out
  const Bounds b = bounds_of(f);
  EXPECT_DOUBLE_EQ(b.lo.x, -1.0);
  EXPECT_DOUBLE_EQ(b.hi.x, 3.5);
  EXPECT_DOUBLE_EQ(b.lo.y, -5.0);  // the ground's height belongs in the picture
  EXPECT_DOUBLE_EQ(b.hi.y, 2.0);
}

}  // namespace
}  // namespace softtune::render
