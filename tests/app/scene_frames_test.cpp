// Scene snapshots to the draw model (scene_frames.cpp): each body as a polygon or a circle in its role
// (static, dynamic, probed), springy joints (distance, wheel, mouse) as springs with their rest length, every
// joint's two anchors as dots, a caption with scene, time and frame, and the scene's fixed camera.
#include "app/scene_frames.h"

#include <gtest/gtest.h>

namespace softtune::app {
namespace {

scene::Snapshot two_bodies_and_three_joints() {
  scene::Snapshot s;
  s.frame = 30;
  s.time_s = 0.5;
  scene::BodySnapshot ground;
  ground.id = "ground";
  ground.is_static = true;
  ground.vertices = {{-5, -1}, {5, -1}, {5, 0}, {-5, 0}};
  scene::BodySnapshot crate;
  crate.id = "crate";
  crate.probed = true;
  crate.vertices = {{0, 1}, {1, 1}, {1, 2}, {0, 2}};
  scene::BodySnapshot wheel;
  wheel.id = "wheel";
  wheel.is_circle = true;
  wheel.center = {3, 0.4};
  wheel.radius = 0.4;
  wheel.angle = 1.25;
  s.bodies = {ground, crate, wheel};
  scene::JointSnapshot rope{"rope", "distance", {0, 3}, {0.5, 2}, 1.0, 1.118};
  scene::JointSnapshot weld{"weld", "weld", {1, 1}, {1, 1}, std::nullopt, 0.0};
  scene::JointSnapshot drag{"drag", "mouse", {2, 2}, {1, 1.5}, std::nullopt, 1.118};
  s.joints = {rope, weld, drag};
  return s;
}

TEST(SceneFrames, BodiesInTheirRolesAndSpringyJointsAsSprings) {
  scene::Scene scene;
  scene.name = "yard";
  const render::DrawFrame f = scene_frame(scene, two_bodies_and_three_joints(), 2, 10);
  ASSERT_EQ(f.polygons.size(), 2u);
  EXPECT_EQ(f.polygons[0].role, render::Role::static_body);
  EXPECT_EQ(f.polygons[1].role, render::Role::probed);
  ASSERT_EQ(f.polygons[1].vertices_m.size(), 4u);
  EXPECT_DOUBLE_EQ(f.polygons[1].vertices_m[2].y, 2.0);
  ASSERT_EQ(f.circles.size(), 1u);
  EXPECT_EQ(f.circles[0].role, render::Role::dynamic_body);
  EXPECT_DOUBLE_EQ(f.circles[0].centre_m.x, 3.0);
  EXPECT_DOUBLE_EQ(f.circles[0].radius_m, 0.4);
  EXPECT_DOUBLE_EQ(f.circles[0].angle_rad, 1.25);
  // The weld is no spring; the mouse joint has no rest length, drawn neutral (0).
  ASSERT_EQ(f.springs.size(), 2u);
  EXPECT_DOUBLE_EQ(f.springs[0].rest_length_m, 1.0);
  EXPECT_DOUBLE_EQ(*f.springs[0].current_length_m, 1.118);
  EXPECT_DOUBLE_EQ(f.springs[0].a_m.y, 3.0);
  EXPECT_DOUBLE_EQ(f.springs[1].rest_length_m, 0.0);
  EXPECT_EQ(f.anchors.size(), 6u);
  EXPECT_EQ(f.caption, "yard  t = 0.50 s  frame 3/10");
}

TEST(SceneFrames, EverySnapshotAFrameWithTheScenesCamera) {
  scene::Scene scene;
  scene.name = "yard";
  scene.camera.center = {1.5, -2.0};
  scene.camera.width_m = 12.0;
  const std::vector<scene::Snapshot> snapshots(4, two_bodies_and_three_joints());
  const render::FrameSet set = scene_frames(scene, snapshots);
  EXPECT_FALSE(set.camera.auto_fit);
  EXPECT_DOUBLE_EQ(set.camera.centre_m.x, 1.5);
  EXPECT_DOUBLE_EQ(set.camera.centre_m.y, -2.0);
  EXPECT_DOUBLE_EQ(set.camera.width_m, 12.0);
  ASSERT_EQ(set.frames.size(), 4u);
  EXPECT_EQ(set.frames.back().caption, "yard  t = 0.50 s  frame 4/4");
  EXPECT_TRUE(scene_frames(scene, {}).frames.empty());
}

}  // namespace
}  // namespace softtune::app
