#include "softtune/render/tessellate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "softtune/render/font.h"
#include "softtune/render/text.h"
#include "softtune/render/view.h"

namespace softtune::render {
namespace {

View test_view() {
  Camera c;
  c.auto_fit = false;
  c.width_m = 10.0;
  return make_view(c, {640, 360});
}

TEST(GridStep, SmallestOneTwoFiveStepWideEnough) {
  EXPECT_DOUBLE_EQ(grid_step_m(64.0, 36.0), 1.0);    // 0.5625 m wanted -> 1
  EXPECT_DOUBLE_EQ(grid_step_m(100.0, 36.0), 0.5);   // 0.36 -> 0.5
  EXPECT_DOUBLE_EQ(grid_step_m(36.0, 36.0), 1.0);    // exactly 1
  EXPECT_DOUBLE_EQ(grid_step_m(10.0, 36.0), 5.0);    // 3.6 -> 5
  EXPECT_DOUBLE_EQ(grid_step_m(1.0, 36.0), 50.0);
  EXPECT_NEAR(grid_step_m(1000.0, 36.0), 0.05, 1e-15);
}

TEST(Tessellate, EveryVertexFiniteAndWholeTriangles) {
  DrawFrame f;
  f.ground_y_m = -1.0;
  f.polygons.push_back({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, Role::dynamic_body});
  f.circles.push_back({{2, 0}, 0.5, 0.3, Role::static_body});
  f.springs.push_back({{-3, 0}, {0, 0}, 2.0, std::nullopt, false});
  f.anchors.push_back({{-3, 0}, false});
  f.labels.push_back({"A1", {0, 2}});
  f.caption = "T 0.5 S\nLINE 2";
  for (bool aa : {true, false}) {
    Mesh m;
    tessellate(f, test_view(), aa, m);
    ASSERT_FALSE(m.vertices.empty());
    EXPECT_EQ(m.vertices.size() % 3, 0u);
    for (const Vertex& v : m.vertices) {
      ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y));
    }
  }
}

TEST(Tessellate, DegenerateShapesAreSkippedNotCrashed) {
  DrawFrame f;
  f.polygons.push_back({{{0, 0}, {0, 0}, {0, 0}}, Role::dynamic_body});
  f.polygons.push_back({{{std::nan(""), 0}, {1, 0}}, Role::dynamic_body});
  f.springs.push_back({{0, 0}, {0, 0}, 0.0, std::nullopt, false});
  Mesh m;
  tessellate(f, test_view(), true, m);
  for (const Vertex& v : m.vertices) ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y));
}

TEST(Tessellate, TextIsNotInTheMesh) {
  DrawFrame f;
  Mesh without, with;
  tessellate(f, test_view(), true, without);
  f.caption = "LONG CAPTION 0123456789";
  f.labels.push_back({"LABEL", {0, 0}});
  tessellate(f, test_view(), true, with);
  EXPECT_EQ(with.vertices.size(), without.vertices.size());
}

}  // namespace
}  // namespace softtune::render
