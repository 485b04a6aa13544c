#pragma once
// JSON of one scene joint in a simulate answer (docs/scenes.md, "What to type"): what was asked of it, what
// to type into each engine and what that achieves, in the joint's own Box2D 2.4 definition (b2WheelJointDef
// for a wheel joint), and the `typed` values a scene document may carry instead of a request.
//
// One answer per joint: a joint a modal tuning solved carries the solved k, c everywhere -- Box2D 2.4's
// `parameters` and `exact` are the values the scene ran, measured on the target's mode -- and its `requested`
// is the target it serves, never the solve's per-joint equivalent. Another engine's values for such a joint
// come from a per-joint model (the joint alone doing what Box2D 2.4's joint does), and say so.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "codec/json_reader.h"
#include "softtune/scene/runner.h"
#include "softtune/scene/scene.h"

namespace softtune::codec {

/// joints[i] of a simulate answer: id, type, tuned, typed, masses, stiffness, damping, requested, warnings,
/// engines, engine_settings, `parameters` ({engine, values}: what to type into the engine that ran, from
/// SceneResult::joint_fields, when the joint has a spring) and, for a solved joint, `answer` (the tune-shaped object the page draws, with the
/// joint's `engines` beside it rather than inside).
nlohmann::json scene_joint_json(const scene::Scene& scene, const scene::SceneResult& run, std::size_t i);

/// The engines of tuned joint `t` (its own tune, or a solved joint's, with Box2D 2.4 in the joint's def).
nlohmann::json scene_joint_engines_json(const scene::Scene& scene, const scene::SceneResult& run, const scene::JointTuning& t);

/// What a modal target measured in the run: {mode, probe, frequency_hz, damping_ratio}, both null with `why`
/// (no probe measures the mode, or its window shows no second-order motion to fit) when it has none.
nlohmann::json target_measurement(const scene::SceneResult& run, const scene::ModalTargetResult& target);

/// Reads a joint's `typed` object: exactly the names of the joint def's Box2D 2.4 parameters
/// ("b2WheelJointDef::stiffness", "b2WheelJointDef::damping"; a mouse joint's "b2MouseJointDef::maxForce" too,
/// which sets `max_force`). A name that is not the def's, or a value that is not a number, is refused (422)
/// naming `<path>.typed.<name>`. Empty when the joint has no `typed`.
std::optional<scene::TypedSpring> read_typed(ObjectReader& r, const std::string& path, scene::JointSettings& joint);

}  // namespace softtune::codec
