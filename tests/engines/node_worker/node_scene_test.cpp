// The node scene's build request (engines/node_worker/node_scene.cpp): each body's mass data is Box2D
// 2.4.1's (a box's m (w^2 + h^2) / 12, a disc's m r^2 / 2), each joint's anchors are where Box2D's
// Initialize puts them, and the typed spring reads back or names the field it misses.
#include "node_scene.h"

#include <gtest/gtest.h>

#include <numbers>

namespace softtune::node_worker {
namespace {

scene::Scene node_scene_test_scene() {
  scene::Scene s;
  scene::BodySettings ground;
  ground.id = "ground";
  ground.is_static = true;
  ground.shape.width = 10;
  s.bodies.push_back(ground);
  scene::BodySettings box;
  box.id = "box";
  box.mass = 6.0;
  box.shape.width = 2.0;
  box.shape.height = 1.0;
  box.position = {0, 2};
  s.bodies.push_back(box);
  scene::BodySettings wheel;
  wheel.id = "wheel";
  wheel.shape.kind = scene::ShapeKind::circle;
  wheel.shape.radius = 0.5;
  wheel.density = 2.0;
  wheel.position = {1, 1};
  s.bodies.push_back(wheel);
  scene::JointSettings wj;
  wj.id = "suspension";
  wj.kind = scene::JointKind::wheel;
  wj.body_a = "box";
  wj.body_b = "wheel";
  wj.anchor_a = {5, 5};  // unused by Box2D's b2WheelJointDef::Initialize: both anchors at anchor_b
  wj.anchor_b = {1, 1};
  wj.axis = {0, 2};
  s.joints.push_back(wj);
  scene::JointSettings rod;
  rod.id = "rod";
  rod.kind = scene::JointKind::distance;
  rod.body_a = "ground";
  rod.body_b = "box";
  rod.anchor_a = {0, 0};
  rod.anchor_b = {0, 1.5};
  s.joints.push_back(rod);
  return s;
}

TEST(NodeScene, BuildRequestCarriesBox2DMassDataAndAnchors) {
  const scene::Scene s = node_scene_test_scene();
  scene::SceneBuild build{&s, {scene::JointSpring{100, 5}, std::nullopt}, {4, 1}};
  const engines::SettingSpec specs[] = {{"a", 4, 1, 9, true}, {"b", 1, 1, 9, true}};
  const nlohmann::json r = build_request("rapier", specs, build);
  EXPECT_EQ(r["engine"], "rapier");
  EXPECT_EQ(r["settings"]["a"], 4);
  const auto& bodies = r["bodies"];
  EXPECT_EQ(bodies[0]["mass"].get<double>(), 0.0);
  EXPECT_NEAR(bodies[1]["mass"].get<double>(), 6.0, 1e-6);
  EXPECT_NEAR(bodies[1]["inertia"].get<double>(), 6.0 * (4.0 + 1.0) / 12.0, 1e-5);
  const double disc = 2.0 * std::numbers::pi * 0.25;
  EXPECT_NEAR(bodies[2]["mass"].get<double>(), disc, 1e-5);
  EXPECT_NEAR(bodies[2]["inertia"].get<double>(), disc * 0.25 / 2.0, 1e-5);
  const auto& wheel = r["joints"][0];
  EXPECT_EQ(wheel["anchor_a"], nlohmann::json::array({1.0, 1.0}));
  EXPECT_NEAR(wheel["axis"][1].get<double>(), 1.0, 1e-12);  // normalised
  EXPECT_EQ(wheel["body_a"], 1);
  EXPECT_EQ(wheel["spring"]["stiffness"], 100.0);
  const auto& rod_json = r["joints"][1];
  EXPECT_TRUE(rod_json["spring"].is_null());
  EXPECT_NEAR(rod_json["length"].get<double>(), 1.5, 1e-12);  // the starting distance
}

TEST(NodeScene, ParseSpringNamesTheMissingOrIllegalField) {
  FieldError error;
  const engines::Parameters ok = {{"M::model", 0, "", "ForceBased"}, {"M::k", 300.0}, {"M::c", 4.0}};
  const auto spring = parse_spring(ok, "M::k", "M::c", "M::model", "ForceBased", error);
  ASSERT_TRUE(spring);
  EXPECT_EQ(spring->stiffness, 300.0);
  EXPECT_EQ(spring->damping, 4.0);
  EXPECT_FALSE(parse_spring({{"M::k", 300.0}}, "M::k", "M::c", "M::model", "ForceBased", error));
  EXPECT_EQ(error.field, "M::c");
  EXPECT_FALSE(parse_spring({{"M::k", -1.0}, {"M::c", 1.0}}, "M::k", "M::c", "", "", error));
  EXPECT_EQ(error.field, "M::k");
  EXPECT_FALSE(parse_spring({{"M::model", 0, "", "AccelerationBased"}, {"M::k", 1.0}, {"M::c", 1.0}}, "M::k", "M::c",
                            "M::model", "ForceBased", error));
  EXPECT_EQ(error.field, "M::model");
}

}  // namespace
}  // namespace softtune::node_worker
