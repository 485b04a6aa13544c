// Scene validation (scene.cpp): a refused scene names the field and the rule.
#include "softtune/scene/scene.h"

#include <gtest/gtest.h>

#include "scene_builders.h"
#include "softtune/scene/runner.h"

namespace softtune::scene {
namespace {

using namespace test;

TEST(SceneValidation, NamesTheFieldAndTheRule) {
  Scene s = buddhas({0.5});
  s.joints[0].body_b = "nobody";
  auto e = validate_scene(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "joints.0.body_b");

  s = buddhas({0.5});
  s.joints[0].kind = JointKind::wheel;
  s.joints[0].tuning.reset();
  EXPECT_EQ(validate_scene(s)->field, "joints.0.frequency_hz");

  s = buddhas({0.5});
  s.bodies[1].shape.kind = ShapeKind::polygon;
  s.bodies[1].shape.vertices = {{0, 0}, {1, 0}, {1, 1}, {0.9, 0.1}};  // not convex
  EXPECT_EQ(validate_scene(s)->field, "bodies.1.shape.vertices");

  s = buddhas({0.5});
  s.bodies[1].shape.kind = ShapeKind::polygon;
  s.bodies[1].shape.vertices = {{0, 0}, {1, 0}, {1, 1}, {0.001, 1.001}, {0, 1}};  // an edge Box2D would weld
  EXPECT_EQ(validate_scene(s)->field, "bodies.1.shape.vertices");

  s = buddhas({0.5});
  s.world.duration_s = 1e9;
  EXPECT_EQ(validate_scene(s)->field, "world.duration_s");
  s = buddhas(std::vector<double>(60, 0.0));  // 121 bodies and joints for 600 s at 60 fps x 5 substeps
  s.world.duration_s = 600;
  s.world.substeps = 5;
  EXPECT_EQ(validate_scene(s)->field, "world.duration_s");

  // A designer field out of range is refused by the core's validation with the joint's path.
  s = buddhas({0.5});
  s.joints[0].tuning->response_frames = 0.0;
  const SceneResult r = run_scene(s);
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->field, "joints.0.response_frames");
}

}  // namespace
}  // namespace softtune::scene
