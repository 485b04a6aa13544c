#pragma once
// A scene: bodies, soft joints tuned in designer units, a world, a camera, probes and the expectations its
// preset test checks. Plain settings with a default on every member (docs/conventions.md, "Settings are plain structs"); the
// runtime state lives in the runner. Nothing here knows about JSON or Box2D.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/methods.h"
#include "softtune/tune.h"

namespace softtune::scene {

enum class ShapeKind { box, circle, polygon };

struct ShapeSettings {
  ShapeKind kind = ShapeKind::box;
  double width = 1.0;                      ///< m, box
  double height = 1.0;                     ///< m, box
  double radius = 0.5;                     ///< m, circle
  std::vector<Eigen::Vector2d> vertices;   ///< m, polygon, body frame, convex, 3..8 (Box2D's b2_maxPolygonVertices)
};

struct BodySettings {
  std::string id;
  ShapeSettings shape;
  bool is_static = false;
  std::optional<double> mass;              ///< kg; when set, the density is chosen to give this mass
  double density = 1.0;                    ///< kg/m^2, used when mass is absent
  Eigen::Vector2d position{0, 0};          ///< m, world position of the body origin (the shape's centre)
  double angle = 0.0;                      ///< rad
  Eigen::Vector2d linear_velocity{0, 0};   ///< m/s
  double angular_velocity = 0.0;           ///< rad/s
  double friction = 0.6;
  double restitution = 0.0;
  bool fixed_rotation = false;             ///< a body without rotation needs no inertia
};

enum class JointKind {
  distance,  ///< b2DistanceJoint: soft along the anchor-to-anchor line when tuned, rigid rod otherwise
  wheel,     ///< b2WheelJoint: soft along `axis` (suspension), rigid across it, free rotation, optional motor
  weld,      ///< b2WeldJoint: soft in rotation when tuned, rigid in translation
  mouse,     ///< b2MouseJoint: body_b's anchor pulled to `target`, soft when tuned
  revolute,  ///< b2RevoluteJoint: a rigid pin (chains, bridge decks); never tuned
};

/// Which mass turns the designer's frequency into k = m omega^2, c = 2 m zeta omega.
enum class MassModel {
  effective,      ///< 1 / (J M^-1 J^T) at the joint's configuration, rotation included (the talk's choice)
  box2d_reduced,  ///< what b2LinearStiffness / b2AngularStiffness use: mA mB / (mA + mB), rotation ignored
};

/// A joint's spring as the designer typed it into Box2D 2.4 (`typed` in a scene document, under the joint def's
/// own names: "b2WheelJointDef::stiffness", "b2WheelJointDef::damping"; a mouse joint's "b2MouseJointDef::maxForce"
/// is its max_force). Such a joint is not tuned: the scene runs these values and measures what they do.
struct TypedSpring {
  double stiffness = 0.0;                  ///< N/m (weld: N m/rad), > 0
  double damping = 0.0;                    ///< N s/m (weld: N m s/rad); damping + h stiffness > 0 (Box2D's gamma)
};

struct JointSettings {
  std::string id;
  JointKind kind = JointKind::distance;
  std::string body_a;                      ///< body id; empty for a mouse joint (Box2D wants a ground body)
  std::string body_b;
  Eigen::Vector2d anchor_a{0, 0};          ///< m, world point on body_a at the start
  Eigen::Vector2d anchor_b{0, 0};          ///< m, world point on body_b at the start
  Eigen::Vector2d axis{0, 1};              ///< wheel: suspension direction in the world at the start
  std::optional<double> length;            ///< m, distance: rest length; default = the starting distance
  Eigen::Vector2d target{0, 0};            ///< m, mouse: the point the anchor is pulled to from the start
  double max_force = 1.0e9;                ///< N, mouse: Box2D's maxForce (0 would mean no pull at all)
  double motor_speed = 0.0;                ///< rad/s, wheel motor (0 = no motor)
  double max_motor_torque = 0.0;           ///< N m, wheel motor
  double motor_start_s = 0.0;              ///< s, wheel motor switches on at this time
  bool collide_connected = false;
  /// The designer's tuning (response_frames / frequency_hz, oscillation / damping_ratio, mode); fps, substeps
  /// and the effective mass are filled in by the runner. Empty: a rigid joint.
  std::optional<TuneRequest> tuning;
  std::optional<TypedSpring> typed;        ///< the values as typed instead of a tuning (never both)
  /// Set by a modal tuning (modal_tuning.cpp), never decoded: the group's solved k, c, given to Box2D as they
  /// are; `tuning` then holds their equivalent request on the joint's own mass (its softness, its engines).
  std::optional<SpringConstants> solved_spring;
};

/// The Box2D 2.4 joint def a joint kind is built from ("b2WheelJointDef"), whose names `typed` and the
/// answer's engines.box2d_v2_4.parameters use.
std::string_view box2d_joint_def(JointKind k);

/// A 1-D oscillator run on the core integrators only (no Box2D): the talk's first scene, and the explicit /
/// semi-implicit comparison of the stiff scene.
struct OscillatorSettings {
  std::string id;
  Method method = Method::soft;
  std::optional<double> effective_mass;    ///< kg; or take it from `joint`
  std::string joint;                       ///< a tuned joint whose m_eff, tuning and fps this oscillator copies
  std::optional<TuneRequest> tuning;       ///< when not copied from `joint`
  double initial_displacement = 0.1;       ///< m
  double initial_velocity = 0.0;           ///< m/s
};

enum class ProbeKind {
  displacement,  ///< a body's centre displacement from its start, along `axis`, m
  angle,         ///< a body's rotation from its start, rad
  joint_length,  ///< distance: length; wheel: translation along the axis; mouse: anchor-to-target; m
  joint_angle,   ///< weld: relative rotation minus the reference angle, rad
  joint_error,   ///< the joint's rigid error: revolute/weld anchor gap, wheel off-axis drift, rigid rod stretch, m
  oscillator,    ///< a core-integrator oscillator's x, m
};

struct ProbeSettings {
  std::string id;
  ProbeKind kind = ProbeKind::displacement;
  std::string body;                        ///< displacement, angle
  std::string joint;                       ///< joint probes; for body probes, the joint whose request applies
                                           ///< (joint_error probes have no request: they measure a rigid row)
  std::string oscillator;                  ///< oscillator probes
  Eigen::Vector2d axis{0, 1};              ///< displacement direction (normalised by the runner)
  double from_s = 0.0;                     ///< s, start of the window the response is measured on
  std::optional<double> to_s;              ///< s, end of the window (default: the end of the run)
  std::optional<double> requested_frequency_hz;  ///< Hz, when no tuned joint states the request
  std::optional<double> requested_damping_ratio;
  /// false: the probe's joint carries a modal solve, whose per-joint equivalent request is nothing the designer
  /// asked; the probe is compared with its target's request (set above by modal_tuning.cpp) or with none.
  bool joint_request = true;
};

enum class Metric {
  frequency_error,        ///< |f_measured / f_requested - 1|
  damping_ratio_error,    ///< |zeta_measured - zeta_requested|
  measured_frequency_hz,
  measured_damping_ratio,
  overshoot,
  settle_frames,          ///< frames at the rate being run; a probe that never settles fails any bound on it
  max_abs_value,          ///< max |value| over the window (blow-up: units of the probe)
  max_constraint_error,   ///< m, scene-wide largest rigid-joint error
  finite,                 ///< scene-wide: no NaN or infinity anywhere (bounds ignored)
  in_world,               ///< scene-wide: every body stays inside world.bounds (bounds ignored)
  settle_s,               ///< s, settle_frames / fps: the same bound at every frame rate a preset ships at
};

struct Expectation {
  std::string probe;                       ///< empty for scene-wide metrics
  Metric metric = Metric::finite;
  std::optional<double> min;
  std::optional<double> max;
  std::optional<MassModel> mass_model;     ///< checked on a run with this mass model (default: the scene's)
  std::string note;                        ///< why the bound is what it is (shown by `softtune check`)
  /// Checked only at these frame rates (Hz) / substep counts; empty: at every rate. A bound that holds at one
  /// rate only (implicit Euler's 5.4 % at 60 fps) says so here, so `softtune check --fps` can run the others.
  std::vector<double> at_fps;
  std::vector<int> at_substeps;
};

/// The rates a preset ships at (`rates` in its JSON): `softtune check` runs it at every fps x substeps pair.
/// Empty lists: the world's own fps / substeps.
struct ShipRates {
  std::vector<double> fps;                 ///< Hz
  std::vector<int> substeps;
};

struct WorldSettings {
  Eigen::Vector2d gravity{0, -10};         ///< m/s^2
  double fps = 60.0;                       ///< Hz, frames per second
  int substeps = 1;                        ///< b2World::Step calls per frame, each of 1 / (fps substeps) s
  int velocity_iterations = 8;
  int position_iterations = 3;
  double duration_s = 5.0;                 ///< s
  Eigen::Vector4d bounds{-1000, -1000, 1000, 1000};  ///< m, [x_min, y_min, x_max, y_max]: "the world"
  bool allow_sleeping = false;             ///< off by default: a sleeping body would freeze a measurement
};

struct CameraSettings {
  Eigen::Vector2d center{0, 0};            ///< m, when `fit` is false
  double width_m = 20.0;                   ///< m of world across the picture: fixed, or followed (at least)
  bool fit = true;                         ///< previews: frame the action over the whole run (or `follow`)
  std::string follow;                      ///< body id the preview camera follows; empty: none
};

/// A body mode the designer tunes (docs/scenes.md, "Tuning the modes"): named by a body and its motion
/// (`body` + `motion`: "heave" y, "pitch" rotation, "surge" x) or by a displacement / angle probe on it. With
/// body and motion, `probe` (any kind) is only what measures the mode in Box2D.
struct ModeTargetSettings {
  std::string probe;
  std::string body;
  std::string motion;
  /// response_frames (+ basis_fps) or frequency_hz, oscillation or damping_ratio; read by the tune codec.
  TuneRequest tuning;
};

/// Joints that share one tuning (the front and rear springs, all hangers).
struct JointGroupSettings {
  std::string id;
  std::vector<std::string> joints;
};

/// Targets on the scene's modes: the groups' k, c are solved so that each targeted mode has the asked
/// frequency and damping ratio (scene/modal_tuning.h); the joints' own tunings are the solve's first guess.
struct ModalTuningSettings {
  std::vector<JointGroupSettings> groups;
  std::vector<ModeTargetSettings> targets;
  SoftMode mode = SoftMode::standard;   ///< exact: the discrete poles at the scene's step land on the request
  std::optional<double> at_s;           ///< s, linearise at this time instead of at rest
};

struct Scene {
  std::string name;
  std::string description;
  WorldSettings world;
  CameraSettings camera;
  MassModel mass_model = MassModel::effective;
  std::vector<BodySettings> bodies;
  std::vector<JointSettings> joints;
  std::vector<OscillatorSettings> oscillators;
  std::vector<ProbeSettings> probes;
  std::vector<Expectation> expectations;
  std::optional<ModalTuningSettings> modal_tuning;
  ShipRates rates;
};

/// Ranges and references (ids that exist, kinds that fit); the first violation with its dotted path
/// ("joints.2.body_a"), or nothing. Designer fields are checked by validate_tune_request at run time.
std::optional<FieldError> validate_scene(const Scene& scene);

/// Whether expectation `e` is checked at the world's fps and substeps (its at_fps / at_substeps lists).
bool applies_at(const Expectation& e, const WorldSettings& world);

/// Number of frames a scene runs: round(duration_s fps).
int frame_count(const WorldSettings& world);

std::string_view joint_kind_name(JointKind k);
std::string_view mass_model_name(MassModel m);
std::string_view probe_kind_name(ProbeKind k);
std::string_view metric_name(Metric m);

}  // namespace softtune::scene
