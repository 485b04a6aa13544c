#pragma once
// A scene built as a Box2D 2.4 world: bodies, then each joint tuned (joint_tuning.h) from the bodies' real
// mass data, then the joints. Owns the b2World. The runner steps it and reads probes; the benchmark steps the
// same world in a raw loop to measure the runner's overhead.

#include <box2d/box2d.h>

#include <memory>
#include <optional>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/scene/joint_tuning.h"
#include "softtune/scene/scene.h"

namespace softtune::scene {

class Box2DScene {
 public:
  /// Builds the world. On a joint tuning error `error()` is set and the world has no joints.
  Box2DScene(const Scene& scene, MassModel model);
  Box2DScene(const Box2DScene&) = delete;
  Box2DScene& operator=(const Box2DScene&) = delete;

  const std::optional<FieldError>& error() const { return error_; }
  b2World& world() { return *world_; }
  const std::vector<b2Body*>& bodies() const { return bodies_; }   ///< indexed like scene.bodies
  const std::vector<b2Joint*>& joints() const { return joints_; }  ///< indexed like scene.joints
  const std::vector<JointTuning>& tunings() const { return tunings_; }

  /// One frame: `substeps` b2World::Step calls of 1 / (fps substeps) s; switches wheel motors on at their time.
  void step_frame(int frame);

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

/// Joint coordinates the probes read (see ProbeKind). `joint` must belong to `scene`.
double joint_length(const JointSettings& settings, const b2Joint* joint);
double joint_angle(const b2Joint* joint);
double joint_error(const JointSettings& settings, const b2Joint* joint);

}  // namespace softtune::scene
