#include "jolt_scene.h"

#include <array>

#include "node_scene.h"

namespace {

using softtune::FieldError;
namespace engines = softtune::engines;
namespace scene = softtune::scene;

// JPH::PhysicsSettings (Jolt's PhysicsSettings.h), Jolt's defaults.
constexpr std::array<engines::SettingSpec, 2> kSettings = {{
    {"PhysicsSettings::mNumVelocitySteps", 10, 1, 255, true, {}, "",
     "velocity iterations of each step (a soft row converges in the first)"},
    {"PhysicsSettings::mNumPositionSteps", 2, 0, 255, true, {}, "",
     "position iterations of each step (skipped for rows whose spring is active)"},
}};

// Jolt's SpringSettings in mode StiffnessAndDamping take k and c as they are (SpringPart.h
// CalculateSpringPropertiesWithStiffness), as core/src/engines/jolt.cpp's StiffnessAndDamping report.
engines::Parameters jolt_fields(const scene::Scene& s, std::size_t joint, const scene::JointSpring& spring,
                                const engines::SettingValues&) {
  return {{"SpringSettings::mMode", 0.0, "", "StiffnessAndDamping"},
          {"SpringSettings::mStiffness", spring.stiffness, softtune::node_worker::angular_spring(s, joint) ? "N m/rad" : "N/m"},
          {"SpringSettings::mDamping", spring.damping, softtune::node_worker::angular_spring(s, joint) ? "N m s/rad" : "N s/m"}};
}

std::optional<scene::JointSpring> jolt_parse(const scene::Scene&, std::size_t, const engines::Parameters& typed,
                                             const engines::SettingValues&, FieldError& error) {
  return softtune::node_worker::parse_spring(typed, "SpringSettings::mStiffness", "SpringSettings::mDamping",
                                             "SpringSettings::mMode", "StiffnessAndDamping", error);
}

std::unique_ptr<scene::SceneWorld> jolt_build(const scene::SceneBuild& build, std::optional<FieldError>& error) {
  return softtune::node_worker::build_node_scene("jolt", kSettings, build, error);
}

}  // namespace

const softtune::scene::SceneBackend kJoltSceneBackend{
    "jolt", "Jolt Physics (jolt-physics 1.1.0, WebAssembly under node)", kSettings, jolt_build, jolt_fields,
    jolt_parse};
