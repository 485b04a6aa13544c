#pragma once
// A scene stepped in one real engine: the contract every scene backend (Box2D 2.4 in scene/, MuJoCo, Bullet,
// ODE in their engines/<engine>/ rooms, Jolt and Rapier through the node worker) implements, so the runner,
// the modal tuning, the preview and `check` read every engine the same way (docs/scene-backends.md).
//
// A backend builds the engine-neutral scene (scene.h: the presets and inline scenes) in its engine, with each
// soft joint's spring as physical k, c (JointSpring) which it writes into its engine's own fields, steps it
// frame by frame at the scene's rate, and reports each body's pose and velocity in the scene's plane. The
// probes, the joints' coordinates and the snapshots are computed from those poses by one engine-neutral code
// path (scene_geometry.h), so every engine is measured by the same ruler.
//
// A feature the engine cannot represent is refused when the world is built: a FieldError (422) whose field
// names the scene feature ("joints.2.type") and whose message names the engine -- never a silent substitute.

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/engines/engine_model.h"
#include "softtune/scene/scene.h"
#include "softtune/scene/snapshot.h"

namespace softtune::scene {

/// One body's state in the scene's plane (x right, y up; 3-D engines map the plane to their own axes).
struct BodyState {
  Eigen::Vector2d origin{0, 0};         ///< m, world position of the body origin (the shape's centre)
  Eigen::Vector2d centre{0, 0};         ///< m, world centre of mass
  double angle = 0.0;                   ///< rad, counter-clockwise
  Eigen::Vector2d velocity{0, 0};       ///< m/s, of the centre of mass
  double angular_velocity = 0.0;        ///< rad/s
};

/// A soft joint's spring in physical units: N/m and N s/m (weld: N m/rad, N m s/rad), along the joint's soft
/// row (distance: the anchor line; wheel: the axis; mouse: the pull; weld: the rotation). Each backend writes
/// it into its own fields (SceneBackend::fields) and reads typed fields back (SceneBackend::parse).
struct JointSpring {
  double stiffness = 0.0;
  double damping = 0.0;
};

/// What a backend builds from.
struct SceneBuild {
  const Scene* scene = nullptr;                   ///< passed validate_scene(); outlives the world
  /// Indexed like scene->joints: the spring of a soft joint, empty for a rigid one (a revolute pin, an
  /// untuned distance rod, a weld's rigid rotation).
  std::vector<std::optional<JointSpring>> springs;
  engines::SettingValues settings;                ///< indexed like the backend's settings, within their ranges
  /// The run reads contacts() (it records snapshots). A backend may step ahead of the frame it was asked for
  /// only when this is false: contacts must be those of the frame just stepped.
  bool contacts = false;
};

/// A scene built in one engine. Not copyable: it owns the engine's world.
class SceneWorld {
 public:
  SceneWorld() = default;
  SceneWorld(const SceneWorld&) = delete;
  SceneWorld& operator=(const SceneWorld&) = delete;
  virtual ~SceneWorld() = default;

  /// One frame of the scene: world.substeps engine steps of 1 / (fps substeps) s each. A wheel motor switches
  /// on when the frame's start time reaches its motor_start_s (frame / fps >= motor_start_s).
  virtual void step_frame(int frame) = 0;

  /// Body `i` (indexed like scene.bodies) now. Static bodies report their fixed pose and zero velocity.
  virtual BodyState body(std::size_t i) const = 0;

  /// Every point of every touching contact now, in the plane (for the preview; may be empty when the engine
  /// does not expose its contacts).
  virtual std::vector<ContactSnapshot> contacts() const = 0;
};

/// One engine's scene backend: what it is, its settings, how it builds and how its joints' fields read.
struct SceneBackend {
  std::string_view name;                          ///< the engine's name, as in the tune answer ("mujoco")
  std::string_view version;                       ///< the engine version it runs ("MuJoCo 2.2.2")
  std::span<const engines::SettingSpec> settings; ///< the engine's own settings a scene run may set
  /// Builds the world; on a refusal returns null and sets `error` (field: the scene feature, message: the
  /// engine and why).
  std::unique_ptr<SceneWorld> (*build)(const SceneBuild& build, std::optional<FieldError>& error);
  /// The values to type into the engine for joint `joint` of `scene` with this spring, under the engine's own
  /// field names ("btGeneric6DofSpring2Constraint::setStiffness").
  engines::Parameters (*fields)(const Scene& scene, std::size_t joint, const JointSpring& spring,
                                const engines::SettingValues& settings);
  /// The spring that fields typed under those names give, or an error naming the missing or illegal field.
  std::optional<JointSpring> (*parse)(const Scene& scene, std::size_t joint, const engines::Parameters& typed,
                                      const engines::SettingValues& settings, FieldError& error);
};

}  // namespace softtune::scene
