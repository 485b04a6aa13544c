// Box2D 2.4.1 as a scene backend (box2d_backend.cpp): the spring it is given reaches the Box2D joint, and what it
// says to type reads back as the same spring.
#include "softtune/scene/box2d_backend.h"

#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include "scene_builders.h"
#include "softtune/scene/box2d_scene.h"

namespace softtune::scene {
namespace {

using namespace test;

Scene box2d_backend_hanging() {
  Scene s;
  s.bodies.push_back(box("ceiling", 4, 0.2, {0, 3}, std::nullopt, true));
  s.bodies.push_back(box("weight", 0.5, 0.5, {0, 1}, 2.0));
  JointSettings j = joint("spring", JointKind::distance, "ceiling", "weight", designer(12, Oscillation::some));
  j.anchor_a = {0, 2.9};
  j.anchor_b = {0, 1.25};
  s.joints.push_back(j);
  return s;
}

TEST(Box2DBackend, TheGivenSpringReachesTheJoint) {
  const Scene s = box2d_backend_hanging();
  std::optional<FieldError> error;
  SceneBuild build{&s, {JointSpring{321.5, 7.25}}, {}};
  std::unique_ptr<SceneWorld> world = kBox2DV24SceneBackend.build(build, error);
  ASSERT_TRUE(world);
  auto& box2d = dynamic_cast<Box2DScene&>(*world);
  auto* d = static_cast<b2DistanceJoint*>(box2d.joints()[0]);
  EXPECT_FLOAT_EQ(d->GetStiffness(), 321.5f);
  EXPECT_FLOAT_EQ(d->GetDamping(), 7.25f);
}

TEST(Box2DBackend, FieldsReadBackAsTheSpring) {
  const Scene s = box2d_backend_hanging();
  const engines::Parameters typed = kBox2DV24SceneBackend.fields(s, 0, {321.5, 7.25}, {});
  ASSERT_EQ(typed.size(), 2u);
  EXPECT_EQ(typed[0].name, "b2DistanceJointDef::stiffness");
  EXPECT_EQ(typed[1].name, "b2DistanceJointDef::damping");
  FieldError error;
  const auto spring = kBox2DV24SceneBackend.parse(s, 0, typed, {}, error);
  ASSERT_TRUE(spring);
  EXPECT_EQ(spring->stiffness, 321.5);
  EXPECT_EQ(spring->damping, 7.25);
  EXPECT_FALSE(kBox2DV24SceneBackend.parse(s, 0, {typed[0]}, {}, error));
  EXPECT_EQ(error.field, "b2DistanceJointDef::damping");
}

}  // namespace
}  // namespace softtune::scene
