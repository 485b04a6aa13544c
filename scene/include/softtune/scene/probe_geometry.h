#pragma once
// What the probes, the constraint error and the snapshots read, computed from the bodies' poses alone
// (BodyState, scene_world.h): one ruler for every engine a scene runs in. A joint's anchors and axis are fixed
// in its bodies' frames at the start, as Box2D 2.4.1's joint defs fix them (b2WheelJointDef::Initialize,
// b2RevoluteJointDef::Initialize, b2WeldJointDef::Initialize: the local anchors of one world point; a distance
// joint's two anchors; a mouse joint's anchor on body B and its target in the world).

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "softtune/scene/scene.h"
#include "softtune/scene/scene_world.h"
#include "softtune/scene/snapshot.h"

namespace softtune::scene {

/// A joint fixed in its bodies' frames at the start.
struct JointFrame {
  int body_a = -1;                     ///< index into scene.bodies; -1: the world (a mouse joint)
  int body_b = -1;
  Eigen::Vector2d local_a{0, 0};       ///< m, anchor in body A's frame (the world point when body_a is -1)
  Eigen::Vector2d local_b{0, 0};       ///< m, anchor in body B's frame
  Eigen::Vector2d local_axis{0, 1};    ///< wheel: unit axis in body A's frame
  double reference_angle = 0.0;        ///< rad, angle_b - angle_a at the start
  std::optional<double> rest_length;   ///< m, distance joints: `length` or the starting distance
};

/// Every joint's frame, indexed like scene.joints (the scene passed validate_scene()).
std::vector<JointFrame> joint_frames(const Scene& scene);

/// A point fixed in a body's frame, in the world now.
Eigen::Vector2d world_point(const BodyState& body, const Eigen::Vector2d& local);

/// The world anchors of a joint now (a: the world point for a mouse joint's target side is the target).
Eigen::Vector2d anchor_a(const JointFrame& f, std::span<const BodyState> bodies);
Eigen::Vector2d anchor_b(const JointFrame& f, std::span<const BodyState> bodies);

/// ProbeKind::joint_length: distance: the anchor gap; wheel: translation along the axis (b2WheelJoint::
/// GetJointTranslation); mouse: anchor B's offset from the target along the pull direction; m.
double joint_length(const JointSettings& joint, const JointFrame& f, std::span<const BodyState> bodies);
/// ProbeKind::joint_angle: angle_b - angle_a - the reference angle, rad.
double joint_angle(const JointFrame& f, std::span<const BodyState> bodies);
/// ProbeKind::joint_error: the rigid row's error (revolute / weld anchor gap, wheel off-axis drift, rigid rod
/// stretch); 0 for springs (a soft distance joint, a mouse joint), m.
double joint_error(const JointSettings& joint, const JointFrame& f, std::span<const BodyState> bodies);

/// One recorded frame of the scene from its bodies' poses and the engine's contacts.
Snapshot snapshot(const Scene& scene, const std::vector<JointFrame>& frames, std::span<const BodyState> bodies,
                  std::vector<ContactSnapshot> contacts, int frame);

}  // namespace softtune::scene
