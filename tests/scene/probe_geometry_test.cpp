// The engine-neutral ruler (probe_geometry.cpp) against Box2D 2.4.1's own joint getters: after a second of a
// tumbling, rotating scene, the joint coordinates computed from the bodies' poses alone are the ones Box2D
// reports for its joints (b2WheelJoint::GetJointTranslation, b2Joint::GetAnchorA / GetAnchorB, the weld's
// relative angle), for every joint kind.
#include "softtune/scene/probe_geometry.h"

#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include "scene_builders.h"
#include "softtune/scene/box2d_scene.h"

namespace softtune::scene {
namespace {

using namespace test;

Eigen::Vector2d probe_geometry_eig(const b2Vec2& v) { return {v.x, v.y}; }

Scene tumbling_scene() {
  Scene s;
  s.world.gravity = {0, -10};
  s.bodies.push_back(box("ceiling", 20, 0.2, {0, 5}, std::nullopt, true));
  s.bodies.push_back(box("chassis", 3.0, 0.5, {0, 2}, 120.0));
  BodySettings wheel;
  wheel.id = "wheel";
  wheel.shape.kind = ShapeKind::circle;
  wheel.shape.radius = 0.4;
  wheel.mass = 15.0;
  wheel.position = {-1.1, 1.4};
  s.bodies.push_back(wheel);
  s.bodies.push_back(box("arm", 2.0, 0.3, {3, 2}, 3.0));
  s.bodies.push_back(box("crate", 1.0, 0.6, {6, 2}, 5.0));
  s.bodies[1].angular_velocity = 1.5;
  s.bodies[1].angle = 0.3;

  JointSettings hang = joint("hang", JointKind::distance, "ceiling", "chassis", designer(20, Oscillation::some));
  hang.anchor_a = {0, 4.9};
  hang.anchor_b = {0.5, 2.2};
  s.joints.push_back(hang);
  JointSettings w = joint("wheel", JointKind::wheel, "chassis", "wheel", designer(12, Oscillation::some));
  w.anchor_b = wheel.position;
  w.axis = {0.2, 1};
  s.joints.push_back(w);
  JointSettings weld = joint("weld", JointKind::weld, "chassis", "arm", designer(10, Oscillation::free));
  weld.anchor_a = {1.8, 2};
  s.joints.push_back(weld);
  JointSettings pin = joint("pin", JointKind::revolute, "arm", "crate", std::nullopt);
  pin.anchor_a = {5.2, 2};
  s.joints.push_back(pin);
  JointSettings mouse = joint("mouse", JointKind::mouse, "", "crate", designer(15, Oscillation::some));
  mouse.anchor_b = {6.2, 2.1};
  mouse.target = {7, 4};
  s.joints.push_back(mouse);
  return s;
}

TEST(ProbeGeometry, JointCoordinatesFromPosesAreBox2DsOwn) {
  const Scene s = tumbling_scene();
  ASSERT_FALSE(validate_scene(s));
  Box2DScene world(s, MassModel::effective);
  ASSERT_FALSE(world.error());
  for (int f = 0; f < 60; ++f) world.step_frame(f);
  std::vector<BodyState> now;
  for (std::size_t b = 0; b < s.bodies.size(); ++b) now.push_back(world.body(b));
  const std::vector<JointFrame> frames = joint_frames(s);
  // The chassis turned: the check would not see a frame error on an unrotated body.
  ASSERT_GT(std::abs(now[1].angle - s.bodies[1].angle), 0.2);
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    SCOPED_TRACE(s.joints[j].id);
    b2Joint* joint = world.joints()[j];
    EXPECT_LT((anchor_a(frames[j], now) - probe_geometry_eig(joint->GetAnchorA())).norm(), 1e-5);
    EXPECT_LT((anchor_b(frames[j], now) - probe_geometry_eig(joint->GetAnchorB())).norm(), 1e-5);
  }
  auto* wheel = static_cast<b2WheelJoint*>(world.joints()[1]);
  EXPECT_NEAR(joint_length(s.joints[1], frames[1], now), wheel->GetJointTranslation(), 1e-5);
  const Eigen::Vector2d axis = probe_geometry_eig(wheel->GetBodyA()->GetWorldVector(wheel->GetLocalAxisA()));
  const Eigen::Vector2d gap = probe_geometry_eig(wheel->GetAnchorB() - wheel->GetAnchorA());
  EXPECT_NEAR(joint_error(s.joints[1], frames[1], now), std::abs(gap.dot(Eigen::Vector2d(-axis.y(), axis.x()))), 1e-5);
  auto* weld = static_cast<b2WeldJoint*>(world.joints()[2]);
  EXPECT_NEAR(joint_angle(frames[2], now),
              weld->GetBodyB()->GetAngle() - weld->GetBodyA()->GetAngle() - weld->GetReferenceAngle(), 1e-6);
  auto* hang = static_cast<b2DistanceJoint*>(world.joints()[0]);
  EXPECT_NEAR(*frames[0].rest_length, hang->GetLength(), 1e-5);
  EXPECT_EQ(joint_error(s.joints[0], frames[0], now), 0.0);  // a spring has no rigid row
  EXPECT_EQ(joint_error(s.joints[4], frames[4], now), 0.0);
}

TEST(ProbeGeometry, SnapshotOutlinesFollowThePose) {
  const Scene s = tumbling_scene();
  Box2DScene world(s, MassModel::effective);
  for (int f = 0; f < 30; ++f) world.step_frame(f);
  std::vector<BodyState> now;
  for (std::size_t b = 0; b < s.bodies.size(); ++b) now.push_back(world.body(b));
  const Snapshot snap = snapshot(s, joint_frames(s), now, world.contacts(), 30);
  EXPECT_DOUBLE_EQ(snap.time_s, 0.5);
  // The chassis's outline is Box2D's fixture polygon in the world.
  const auto* poly = static_cast<const b2PolygonShape*>(world.bodies()[1]->GetFixtureList()->GetShape());
  ASSERT_EQ(snap.bodies[1].vertices.size(), static_cast<std::size_t>(poly->m_count));
  for (int k = 0; k < poly->m_count; ++k) {
    const Eigen::Vector2d p = probe_geometry_eig(world.bodies()[1]->GetWorldPoint(poly->m_vertices[k]));
    double nearest = 1e9;
    for (const Eigen::Vector2d& v : snap.bodies[1].vertices) nearest = std::min(nearest, (v - p).norm());
    EXPECT_LT(nearest, 1e-5);
  }
  EXPECT_TRUE(snap.bodies[2].is_circle);
  EXPECT_DOUBLE_EQ(snap.bodies[2].radius, 0.4);
}

}  // namespace
}  // namespace softtune::scene
