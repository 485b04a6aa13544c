#pragma once
// A scene stepped in a JavaScript engine through the node worker (node_worker.h): the build request of the
// worker protocol made from the engine-neutral scene, and a SceneWorld whose step_frame is one round trip.
// The Rapier and Jolt scene backends (engines/rapier/rapier_scene.h, engines/jolt/jolt_scene.h) are this
// with their engine's name, settings and field names.

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string_view>

#include "node_worker.h"
#include "softtune/scene/scene_world.h"

namespace softtune::node_worker {

/// The worker's build request for `engine` (scene_worker.mjs's protocol): each body's mass data from
/// scene::body_mass(), each joint's anchors as Box2D 2.4 uses them (wheel: both at anchor_b; weld and
/// revolute: both at anchor_a), its rest length resolved, its spring or null, the settings by name.
nlohmann::json build_request(std::string_view engine, std::span<const engines::SettingSpec> specs,
                             const scene::SceneBuild& build);

/// Builds the scene in `engine` on `worker`. A refusal (the engine module's {field, message}) or a worker
/// that cannot run (node or the module missing) returns null and sets `error`.
std::unique_ptr<scene::SceneWorld> build_node_scene(std::string_view engine, std::span<const engines::SettingSpec> specs,
                                                    const scene::SceneBuild& build, std::optional<FieldError>& error,
                                                    NodeWorker& worker = shared_worker());

/// Whether joint `joint`'s spring acts on the rotation (a weld's: N m/rad), not along a line (N/m).
bool angular_spring(const scene::Scene& scene, std::size_t joint);

/// Reads a spring typed under two numeric field names (stiffness > 0, damping >= 0, both finite) and an
/// optional choice field that must hold `choice`; the error names the missing or illegal field.
std::optional<scene::JointSpring> parse_spring(const engines::Parameters& typed, std::string_view stiffness_field,
                                               std::string_view damping_field, std::string_view choice_field,
                                               std::string_view choice, FieldError& error);

}  // namespace softtune::node_worker
