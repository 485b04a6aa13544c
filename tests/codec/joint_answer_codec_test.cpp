// A scene joint's answer and its `typed` values (joint_answer_codec.cpp): `typed` takes exactly the names of
// the joint's own Box2D 2.4 def and refuses the rest naming the field; the answer names each joint's values in
// its def (a mouse joint's maxForce is the scene's) and a typed joint's values as it ran them.
#include "codec/joint_answer_codec.h"

#include <gtest/gtest.h>

#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "softtune/scene/runner.h"

namespace softtune::codec {
namespace {

using nlohmann::json;
using namespace softtune::scene;

std::string refused_field(const json& typed, JointKind kind) {
  const json doc = {{"typed", typed}};
  ObjectReader r(doc, "joints.2");
  JointSettings j;
  j.kind = kind;
  try {
    read_typed(r, "joints.2", j);
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    return p.field;
  }
  return "(accepted)";
}

TEST(JointAnswerCodec, TypedTakesTheDefsNamesOnly) {
  EXPECT_EQ(refused_field({{"b2WheelJointDef::stiffness", 1.0}, {"b2WheelJointDef::damping", 0.5}}, JointKind::wheel), "(accepted)");
  EXPECT_EQ(refused_field({{"stiffness", 1.0}, {"b2WheelJointDef::damping", 0.5}}, JointKind::wheel), "joints.2.typed.stiffness");
  EXPECT_EQ(refused_field({{"b2WheelJointDef::stiffness", 1.0}, {"b2WheelJointDef::damping", 0.5}}, JointKind::distance),
            "joints.2.typed.b2WheelJointDef::damping");  // the first wrong name in key order
  EXPECT_EQ(refused_field({{"b2WheelJointDef::stiffness", true}, {"b2WheelJointDef::damping", 0.5}}, JointKind::wheel),
            "joints.2.typed.b2WheelJointDef::stiffness");
  EXPECT_EQ(refused_field({{"b2WheelJointDef::damping", 0.5}}, JointKind::wheel), "joints.2.typed.b2WheelJointDef::stiffness");
  EXPECT_EQ(refused_field({{"b2RevoluteJointDef::stiffness", 1.0}}, JointKind::revolute), "joints.2.typed");
  EXPECT_EQ(refused_field(json::array({1.0}), JointKind::weld), "joints.2.typed");
  // maxForce is a mouse joint's only, and sets the joint's max_force.
  EXPECT_EQ(refused_field({{"b2WheelJointDef::maxForce", 1.0}, {"b2WheelJointDef::stiffness", 1.0}, {"b2WheelJointDef::damping", 0.5}},
                          JointKind::wheel),
            "joints.2.typed.b2WheelJointDef::maxForce");
  const json doc = {{"typed", {{"b2MouseJointDef::stiffness", 80.0}, {"b2MouseJointDef::damping", 4.0}, {"b2MouseJointDef::maxForce", 500.0}}}};
  ObjectReader r(doc, "joints.0");
  JointSettings mouse;
  mouse.kind = JointKind::mouse;
  const auto typed = read_typed(r, "joints.0", mouse);
  ASSERT_TRUE(typed);
  EXPECT_EQ(typed->stiffness, 80.0);
  EXPECT_EQ(typed->damping, 4.0);
  EXPECT_EQ(mouse.max_force, 500.0);
}

// A weld's spring is named on b2WeldJointDef (the Box2D 2.4 model's own names are b2DistanceJointDef's), and a
// typed joint reports the values it ran under the same names.
TEST(JointAnswerCodec, ValuesAreNamedInTheJointsDef) {
  const json doc = {
      {"name", "weld"},
      {"world", {{"gravity", {0, 0}}, {"duration_s", 1}}},
      {"bodies", {{{"id", "wall"}, {"static", true}, {"shape", {{"type", "box"}, {"width", 0.2}, {"height", 2}}}, {"position", {0, 0}}},
                  {{"id", "door"}, {"mass", 2}, {"shape", {{"type", "box"}, {"width", 1}, {"height", 0.1}}}, {"position", {0.6, 0}}, {"angular_velocity", 1}},
                  {{"id", "door2"}, {"mass", 2}, {"shape", {{"type", "box"}, {"width", 1}, {"height", 0.1}}}, {"position", {0.6, 0.9}}}}},
      {"joints", {{{"id", "hinge"}, {"type", "weld"}, {"body_a", "wall"}, {"body_b", "door"}, {"anchor_a", {0.1, 0}},
                   {"frequency_hz", 2}, {"damping_ratio", 0.3}},
                  {{"id", "typed"}, {"type", "weld"}, {"body_a", "wall"}, {"body_b", "door2"}, {"anchor_a", {0.1, 0.9}},
                   {"typed", {{"b2WeldJointDef::stiffness", 12.5}, {"b2WeldJointDef::damping", 0.25}}}}}},
  };
  const Scene scene = decode_scene(doc);
  const SceneResult run = run_scene(scene);
  ASSERT_FALSE(run.error);
  const json tuned = scene_joint_json(scene, run, 0);
  const json& box2d = tuned["engines"]["box2d_v2_4"];
  EXPECT_EQ(box2d["parameters"]["b2WeldJointDef::stiffness"].get<double>(), run.joints[0].stiffness);
  EXPECT_EQ(box2d["parameters"]["b2WeldJointDef::damping"].get<double>(), run.joints[0].damping);
  EXPECT_FALSE(box2d["parameters"].contains("b2DistanceJointDef::stiffness"));
  const json typed = scene_joint_json(scene, run, 1);
  EXPECT_TRUE(typed["typed"].get<bool>());
  EXPECT_FALSE(typed["tuned"].get<bool>());
  EXPECT_EQ(typed["as_typed"], json({{"b2WeldJointDef::stiffness", 12.5}, {"b2WeldJointDef::damping", 0.25}}));
}

}  // namespace
}  // namespace softtune::codec
