#include "softtune/scene/box2d_backend.h"

#include <string>

#include "softtune/scene/box2d_scene.h"

namespace softtune::scene {
namespace {

// The world's iterations are the scene's own (world.velocity_iterations, world.position_iterations), so the
// backend adds no settings of its own.
std::unique_ptr<SceneWorld> build(const SceneBuild& b, std::optional<FieldError>& error) {
  auto world = std::make_unique<Box2DScene>(*b.scene, b.scene->mass_model, b.springs);
  if (world->error()) {
    error = world->error();
    return nullptr;
  }
  return world;
}

// The soft joint defs' own fields (b2DistanceJointDef, b2WheelJointDef, b2WeldJointDef, b2MouseJointDef all
// take stiffness and damping in Box2D 2.4.1), as `typed` spells them.
std::string field(const Scene& scene, std::size_t joint, std::string_view member) {
  return std::string(box2d_joint_def(scene.joints[joint].kind)) + "::" + std::string(member);
}

engines::Parameters fields(const Scene& scene, std::size_t joint, const JointSpring& spring, const engines::SettingValues&) {
  const bool angular = scene.joints[joint].kind == JointKind::weld;
  // The names are static strings (engines::Parameter holds a string_view): one per joint kind and member.
  static const auto names = [] {
    std::vector<std::string> n;
    for (JointKind k : {JointKind::distance, JointKind::wheel, JointKind::weld, JointKind::mouse, JointKind::revolute}) {
      n.push_back(std::string(box2d_joint_def(k)) + "::stiffness");
      n.push_back(std::string(box2d_joint_def(k)) + "::damping");
    }
    return n;
  }();
  const std::size_t kind = static_cast<std::size_t>(scene.joints[joint].kind);
  return {{names[2 * kind], spring.stiffness, angular ? "N m/rad" : "N/m"},
          {names[2 * kind + 1], spring.damping, angular ? "N m s/rad" : "N s/m"}};
}

std::optional<JointSpring> parse(const Scene& scene, std::size_t joint, const engines::Parameters& typed,
                                 const engines::SettingValues&, FieldError& error) {
  const std::string k = field(scene, joint, "stiffness"), c = field(scene, joint, "damping");
  const auto stiffness = engines::parameter_value(typed, k), damping = engines::parameter_value(typed, c);
  if (!stiffness || !damping) {
    error = {stiffness ? c : k, "is required: box2d_v2_4 takes the joint's spring as stiffness and damping"};
    return std::nullopt;
  }
  return JointSpring{*stiffness, *damping};
}

}  // namespace

const SceneBackend kBox2DV24SceneBackend{"box2d_v2_4", "Box2D 2.4.1", {}, build, fields, parse};

}  // namespace softtune::scene
