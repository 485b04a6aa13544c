#include "rapier_scene.h"

#include <array>

#include "node_scene.h"

namespace {

using softtune::FieldError;
namespace engines = softtune::engines;
namespace scene = softtune::scene;

// rapier::dynamics::IntegrationParameters (rapier2d-compat's IntegrationParameters), Rapier 0.21's defaults.
constexpr std::array<engines::SettingSpec, 2> kSettings = {{
    {"IntegrationParameters::numSolverIterations", 4, 1, 1024, true, {}, "",
     "the substeps of each World.step (its soft constraints and contacts are solved once per substep)"},
    {"IntegrationParameters::numInternalPgsIterations", 1, 1, 1024, true, {}, "",
     "PGS iterations inside each substep"},
}};

// Every soft joint of the scene is a Rapier joint motor built ForceBased (rapier_scene.mjs: the spring joint,
// the wheel's prismatic motor, the soft weld's angular motor, the mouse's spring), so k and c are typed as
// they are: N/m and N s/m (weld: N m/rad, N m s/rad), as core/src/engines/rapier.cpp's ForceBased report.
engines::Parameters rapier_fields(const scene::Scene& s, std::size_t joint, const scene::JointSpring& spring,
                                  const engines::SettingValues&) {
  return {{"JointMotor::model", 0.0, "", "ForceBased"},
          {"JointMotor::stiffness", spring.stiffness, softtune::node_worker::angular_spring(s, joint) ? "N m/rad" : "N/m"},
          {"JointMotor::damping", spring.damping, softtune::node_worker::angular_spring(s, joint) ? "N m s/rad" : "N s/m"}};
}

std::optional<scene::JointSpring> rapier_parse(const scene::Scene&, std::size_t, const engines::Parameters& typed,
                                               const engines::SettingValues&, FieldError& error) {
  return softtune::node_worker::parse_spring(typed, "JointMotor::stiffness", "JointMotor::damping", "JointMotor::model",
                                             "ForceBased", error);
}

std::unique_ptr<scene::SceneWorld> rapier_build(const scene::SceneBuild& build, std::optional<FieldError>& error) {
  return softtune::node_worker::build_node_scene("rapier", kSettings, build, error);
}

}  // namespace

const softtune::scene::SceneBackend kRapierSceneBackend{
    "rapier", "Rapier 0.21.0 (@dimforge/rapier2d-compat, WebAssembly under node)", kSettings,
    rapier_build, rapier_fields, rapier_parse};
