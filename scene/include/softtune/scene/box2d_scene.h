#pragma once
// A scene built as a Box2D 2.4 world: bodies, then each joint tuned (joint_tuning.h, tune_scene_joints) from
// the bodies' mass data, then the joints. Owns the b2World. It is the Box2D 2.4 scene backend's world
// (box2d_backend.h): the runner steps it and reads its bodies' poses; the linearisation and the stability sweep
// read the b2World itself; the benchmark steps the same world in a raw loop to measure the runner's overhead.

#include <box2d/box2d.h>

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/scene/joint_tuning.h"
#include "softtune/scene/scene.h"
#include "softtune/scene/scene_world.h"

namespace softtune::scene {

class Box2DScene final : public SceneWorld {
 public:
  /// Builds the world. On a joint tuning error `error()` is set and the world has no joints. `springs`
  /// (indexed like scene.joints; SceneBuild::springs) replaces the tunings' k, c where given.
  Box2DScene(const Scene& scene, MassModel model, std::span<const std::optional<JointSpring>> springs = {});

  const std::optional<FieldError>& error() const { return error_; }
  b2World& world() { return *world_; }
  const std::vector<b2Body*>& bodies() const { return bodies_; }   ///< indexed like scene.bodies
  const std::vector<b2Joint*>& joints() const { return joints_; }  ///< indexed like scene.joints
  const std::vector<JointTuning>& tunings() const { return tunings_; }

  /// One frame: `substeps` b2World::Step calls of 1 / (fps substeps) s; switches wheel motors on at their time.
  void step_frame(int frame) override;
  BodyState body(std::size_t i) const override;
  std::vector<ContactSnapshot> contacts() const override;

  /// The body's mass data as the core sees it: mass, inertia about the centre of mass, world centre.
  static Body2D core_body(const b2Body* body);

 private:
  const Scene& scene_;
  std::unique_ptr<b2World> world_;
  b2Body* ground_ = nullptr;  // the static body a mouse joint's bodyA must be
  std::vector<b2Body*> bodies_;
  std::vector<b2Joint*> joints_;
  std::vector<JointTuning> tunings_;
  std::optional<FieldError> error_;
};


}  // namespace softtune::scene
