// The Box2D world a scene builds (box2d_scene.cpp): Box2D's own K, measured with unit impulses, is the core's
// 1 / m_eff for every joint kind, and k reached Box2D.
#include "softtune/scene/box2d_scene.h"

#include <gtest/gtest.h>

#include "scene_builders.h"

namespace softtune::scene {
namespace {

using namespace test;

// The talk's mental experiment, done in Box2D itself: equal and opposite unit impulses at the anchors, relative
// anchor velocity along the axis = K. Box2D's answer must be the core's 1 / m_eff for every joint kind.
double box2d_unit_impulse(b2Body* a, b2Body* b, b2Vec2 pa, b2Vec2 pb, b2Vec2 axis) {
  for (b2Body* body : {a, b}) {
    body->SetLinearVelocity(b2Vec2_zero);
    body->SetAngularVelocity(0.0f);
  }
  a->ApplyLinearImpulse(-axis, pa, true);
  b->ApplyLinearImpulse(axis, pb, true);
  return b2Dot(b->GetLinearVelocityFromWorldPoint(pb) - a->GetLinearVelocityFromWorldPoint(pa), axis);
}

TEST(SceneRunner, Box2DsOwnKAgreesWithTheCoreForEveryJointKind) {
  Scene s;
  s.name = "k";
  s.world.gravity = {0, 0};
  s.bodies.push_back(box("chassis", 3.0, 0.5, {0, 1}, 120.0));
  BodySettings wheel;
  wheel.id = "wheel";
  wheel.shape.kind = ShapeKind::circle;
  wheel.shape.radius = 0.4;
  wheel.mass = 15.0;
  wheel.position = {-1.1, 0.4};
  s.bodies.push_back(wheel);
  s.bodies.push_back(box("crate", 1.0, 0.6, {5, 0}, 5.0));
  s.bodies.push_back(box("arm", 2.0, 0.3, {9, 0}, 3.0));
  s.bodies.push_back(box("base", 1.0, 1.0, {11, 0}, 7.0));
  JointSettings w = joint("suspension", JointKind::wheel, "chassis", "wheel", designer(20, Oscillation::some));
  w.anchor_b = {-1.1, 0.4};
  w.axis = {0.3, 1.0};
  JointSettings d = joint("rope", JointKind::distance, "chassis", "crate", designer(30, Oscillation::some));
  d.anchor_a = {1.2, 1.1};
  d.anchor_b = {4.7, 0.25};
  JointSettings m = joint("drag", JointKind::mouse, "", "crate", designer(30, Oscillation::none));
  m.anchor_b = {5.4, -0.2};
  m.target = {6.0, 1.0};
  JointSettings weld = joint("weld", JointKind::weld, "arm", "base", designer(30, Oscillation::some));
  weld.anchor_a = {10.2, 0};
  s.joints = {w, d, m, weld};
  ASSERT_FALSE(validate_scene(s));
  Box2DScene world(s, MassModel::effective);
  ASSERT_FALSE(world.error());
  auto body = [&](int i) { return world.bodies()[i]; };
  auto v = [](const Eigen::Vector2d& x) { return b2Vec2(static_cast<float>(x.x()), static_cast<float>(x.y())); };

  const b2Vec2 axis_w = v(w.axis.normalized());
  EXPECT_NEAR(box2d_unit_impulse(body(0), body(1), v(w.anchor_b), v(w.anchor_b), axis_w) * world.tunings()[0].effective_mass, 1.0, 1e-5);
  const b2Vec2 axis_d = v((d.anchor_b - d.anchor_a).normalized());
  EXPECT_NEAR(box2d_unit_impulse(body(0), body(2), v(d.anchor_a), v(d.anchor_b), axis_d) * world.tunings()[1].effective_mass, 1.0, 1e-5);
  // The mouse joint pulls against a fixed target: impulse on the crate alone.
  const b2Vec2 axis_m = v((m.target - m.anchor_b).normalized());
  body(2)->SetLinearVelocity(b2Vec2_zero);
  body(2)->SetAngularVelocity(0.0f);
  body(2)->ApplyLinearImpulse(axis_m, v(m.anchor_b), true);
  EXPECT_NEAR(b2Dot(body(2)->GetLinearVelocityFromWorldPoint(v(m.anchor_b)), axis_m) * world.tunings()[2].effective_mass, 1.0, 1e-5);
  // Weld: angular, unit angular impulses.
  body(3)->SetAngularVelocity(0.0f);
  body(4)->SetAngularVelocity(0.0f);
  body(3)->ApplyAngularImpulse(-1.0f, true);
  body(4)->ApplyAngularImpulse(1.0f, true);
  EXPECT_TRUE(world.tunings()[3].angular);
  EXPECT_NEAR((body(4)->GetAngularVelocity() - body(3)->GetAngularVelocity()) * world.tunings()[3].effective_mass, 1.0, 1e-5);
  // k = m_eff omega^2 reached Box2D.
  EXPECT_NEAR(static_cast<b2WheelJoint*>(world.joints()[0])->GetStiffness(), world.tunings()[0].stiffness, 1e-3 * world.tunings()[0].stiffness);
}

}  // namespace
}  // namespace softtune::scene
