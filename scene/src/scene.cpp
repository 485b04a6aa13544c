#include "softtune/scene/scene.h"
#include "softtune/scene/modal_tuning.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "softtune/scene/limits.h"
#include "softtune/validation.h"

namespace softtune::scene {
namespace {

std::string range(double lo, double hi, const char* unit) { return finite_range_rule(lo, hi, unit); }

bool in(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

bool finite_vector(const Eigen::Vector2d& v, double bound) { return in(v.x(), -bound, bound) && in(v.y(), -bound, bound); }

std::string at(const char* list, std::size_t i) { return std::string(list) + "." + std::to_string(i); }

// A convex polygon with positive area, vertices in either winding order.
bool convex(const std::vector<Eigen::Vector2d>& v) {
  const std::size_t n = v.size();
  double sign = 0.0, area = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e1 = v[(i + 1) % n] - v[i], e2 = v[(i + 2) % n] - v[(i + 1) % n];
    const double turn = e1.x() * e2.y() - e1.y() * e2.x();
    if (std::abs(turn) < 1e-12) return false;
    if (sign == 0.0) sign = turn;
    if (turn * sign < 0.0) return false;
    area += v[i].x() * v[(i + 1) % n].y() - v[(i + 1) % n].x() * v[i].y();
  }
  return std::abs(area) > 1e-9;
}

std::optional<FieldError> check_world(const WorldSettings& w) {
  if (!finite_vector(w.gravity, limits::kMaxGravity))
    return FieldError{"world.gravity", range(-limits::kMaxGravity, limits::kMaxGravity, "m/s^2") + " in every component"};
  if (!in(w.fps, softtune::limits::kMinFps, limits::kMaxSceneFps))
    return FieldError{"world.fps", range(softtune::limits::kMinFps, limits::kMaxSceneFps, "Hz")};
  if (w.substeps < 1 || w.substeps > limits::kMaxSceneSubsteps)
    return FieldError{"world.substeps", "must be an integer in [1, " + std::to_string(limits::kMaxSceneSubsteps) + "]"};
  if (w.velocity_iterations < 1 || w.velocity_iterations > limits::kMaxIterations)
    return FieldError{"world.velocity_iterations", "must be an integer in [1, " + std::to_string(limits::kMaxIterations) + "]"};
  if (w.position_iterations < 0 || w.position_iterations > limits::kMaxIterations)
    return FieldError{"world.position_iterations", "must be an integer in [0, " + std::to_string(limits::kMaxIterations) + "]"};
  if (!in(w.duration_s, 1.0 / w.fps, limits::kMaxDurationS))
    return FieldError{"world.duration_s", range(1.0 / w.fps, limits::kMaxDurationS, "s") + " (at least one frame)"};
  if (static_cast<double>(frame_count(w)) * w.substeps > limits::kMaxSceneSteps)
    return FieldError{"world.duration_s", "duration_s * fps * substeps must not exceed " +
                                              std::to_string(static_cast<long long>(limits::kMaxSceneSteps)) + " steps"};
  for (int i = 0; i < 4; ++i) {
    if (!in(w.bounds[i], -limits::kMaxWorldCoordinate, limits::kMaxWorldCoordinate))
      return FieldError{"world.bounds", range(-limits::kMaxWorldCoordinate, limits::kMaxWorldCoordinate, "m") + " in every entry"};
  }
  if (!(w.bounds[0] < w.bounds[2]) || !(w.bounds[1] < w.bounds[3]))
    return FieldError{"world.bounds", "must be [x_min, y_min, x_max, y_max] with x_min < x_max and y_min < y_max"};
  return std::nullopt;
}

std::optional<FieldError> check_body(const BodySettings& b, const std::string& path) {
  const ShapeSettings& s = b.shape;
  if (s.kind == ShapeKind::box && (!in(s.width, limits::kMinSize, limits::kMaxSize) || !in(s.height, limits::kMinSize, limits::kMaxSize)))
    return FieldError{path + ".shape", "box width and height " + range(limits::kMinSize, limits::kMaxSize, "m")};
  if (s.kind == ShapeKind::circle && !in(s.radius, limits::kMinSize, limits::kMaxSize))
    return FieldError{path + ".shape.radius", range(limits::kMinSize, limits::kMaxSize, "m")};
  if (s.kind == ShapeKind::polygon) {
    if (s.vertices.size() < 3 || s.vertices.size() > limits::kMaxPolygonVertices)
      return FieldError{path + ".shape.vertices", "must hold 3 to " + std::to_string(limits::kMaxPolygonVertices) + " points"};
    for (const auto& v : s.vertices) {
      if (!finite_vector(v, limits::kMaxSize)) return FieldError{path + ".shape.vertices", range(-limits::kMaxSize, limits::kMaxSize, "m")};
    }
    if (!convex(s.vertices)) return FieldError{path + ".shape.vertices", "must be a convex polygon with non-zero area, no repeated or collinear points"};
    for (std::size_t i = 0; i < s.vertices.size(); ++i) {
      if ((s.vertices[(i + 1) % s.vertices.size()] - s.vertices[i]).norm() < limits::kMinJointLength)
        return FieldError{path + ".shape.vertices", "edges must be at least " + std::to_string(limits::kMinJointLength) + " m long (Box2D welds closer vertices)"};
    }
  }
  if (b.mass && !in(*b.mass, limits::kMinBodyMass, limits::kMaxBodyMass))
    return FieldError{path + ".mass", range(limits::kMinBodyMass, limits::kMaxBodyMass, "kg")};
  if (!in(b.density, limits::kMinDensity, limits::kMaxDensity))
    return FieldError{path + ".density", range(limits::kMinDensity, limits::kMaxDensity, "kg/m^2")};
  if (!finite_vector(b.position, limits::kMaxWorldCoordinate))
    return FieldError{path + ".position", range(-limits::kMaxWorldCoordinate, limits::kMaxWorldCoordinate, "m") + " in every component"};
  if (!std::isfinite(b.angle)) return FieldError{path + ".angle", "must be a finite number (rad)"};
  if (!finite_vector(b.linear_velocity, limits::kMaxSpeed))
    return FieldError{path + ".linear_velocity", range(-limits::kMaxSpeed, limits::kMaxSpeed, "m/s") + " in every component"};
  if (!in(b.angular_velocity, -limits::kMaxAngularSpeed, limits::kMaxAngularSpeed))
    return FieldError{path + ".angular_velocity", range(-limits::kMaxAngularSpeed, limits::kMaxAngularSpeed, "rad/s")};
  if (!in(b.friction, 0.0, 10.0)) return FieldError{path + ".friction", range(0.0, 10.0, "")};
  if (!in(b.restitution, 0.0, 1.0)) return FieldError{path + ".restitution", range(0.0, 1.0, "")};
  return std::nullopt;
}

int body_index(const Scene& s, const std::string& id) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (s.bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

int joint_index(const Scene& s, const std::string& id) {
  for (std::size_t i = 0; i < s.joints.size(); ++i) {
    if (s.joints[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

// A joint's typed values: what Box2D 2.4 accepts as a spring. It reads stiffness <= 0 as rigid, and builds
// gamma = 1 / (h (damping + h stiffness)) (b2_wheel_joint.cpp InitVelocityConstraints), which must stay positive.
std::optional<FieldError> check_typed(const Scene& s, const JointSettings& j, const std::string& path) {
  const std::string def = std::string(box2d_joint_def(j.kind));
  if (j.kind == JointKind::revolute) return FieldError{path + ".typed", "a revolute joint is a rigid pin: it has no spring to type"};
  if (j.tuning) return FieldError{path + ".typed", "give either typed values or a tuning (response_frames / frequency_hz ...), not both"};
  const TypedSpring& t = *j.typed;
  const std::string unit = j.kind == JointKind::weld ? "N m/rad" : "N/m";
  if (!(t.stiffness > 0.0 && t.stiffness <= limits::kMaxTypedStiffness))
    return FieldError{path + ".typed." + def + "::stiffness", "must be in (0, 1e15] " + unit + " (Box2D 2.4 reads 0 as a rigid joint)"};
  if (!(std::abs(t.damping) <= limits::kMaxTypedStiffness))
    return FieldError{path + ".typed." + def + "::damping", "must be a finite number within +-1e15"};
  const double h = 1.0 / (s.world.fps * s.world.substeps);
  if (!(t.damping + h * t.stiffness > 0.0))
    return FieldError{path + ".typed." + def + "::damping",
                      "must exceed -h stiffness (h = 1 / (fps substeps)): Box2D 2.4's gamma = 1 / (h (damping + h stiffness)) must be positive"};
  return std::nullopt;
}

std::optional<FieldError> check_joint(const Scene& s, const JointSettings& j, const std::string& path) {
  const int a = body_index(s, j.body_a), b = body_index(s, j.body_b);
  if (b < 0) return FieldError{path + ".body_b", "must name a body of this scene"};
  if (j.kind == JointKind::mouse) {
    if (!j.body_a.empty()) return FieldError{path + ".body_a", "must be left out for a mouse joint (Box2D pulls against a ground body)"};
  } else {
    if (a < 0) return FieldError{path + ".body_a", "must name a body of this scene"};
    if (a == b) return FieldError{path + ".body_b", "must differ from body_a"};
    if (s.bodies[a].is_static && s.bodies[b].is_static) return FieldError{path + ".body_b", "at least one body must be dynamic (both are static)"};
  }
  if (j.kind == JointKind::mouse && s.bodies[b].is_static) return FieldError{path + ".body_b", "must be a dynamic body for a mouse joint"};
  for (const auto& [name, v] : {std::pair{"anchor_a", j.anchor_a}, std::pair{"anchor_b", j.anchor_b}, std::pair{"target", j.target}}) {
    if (!finite_vector(v, limits::kMaxWorldCoordinate))
      return FieldError{path + "." + name, range(-limits::kMaxWorldCoordinate, limits::kMaxWorldCoordinate, "m") + " in every component"};
  }
  if (!finite_vector(j.axis, 1e6) || j.axis.norm() < softtune::limits::kMinAxisLength)
    return FieldError{path + ".axis", "must be a finite, non-zero direction"};
  const bool needs_tuning = j.kind == JointKind::wheel || j.kind == JointKind::mouse;
  if (needs_tuning && !j.tuning && !j.typed)
    return FieldError{path + ".frequency_hz", "a " + std::string(joint_kind_name(j.kind)) +
                                                  " joint must be tuned: give response_frames or frequency_hz (or typed values)"};
  if (j.kind == JointKind::revolute && j.tuning)
    return FieldError{path + ".frequency_hz", "a revolute joint is a rigid pin and takes no tuning"};
  if (j.typed) {
    if (auto e = check_typed(s, j, path)) return e;
  }
  if (j.kind == JointKind::distance) {
    if ((j.anchor_b - j.anchor_a).norm() < limits::kMinJointLength)
      return FieldError{path + ".anchor_b", "must be at least " + std::to_string(limits::kMinJointLength) + " m from anchor_a (the distance joint's axis)"};
    if (j.length && !in(*j.length, limits::kMinJointLength, limits::kMaxSize))
      return FieldError{path + ".length", range(limits::kMinJointLength, limits::kMaxSize, "m")};
  }
  if (!in(j.max_force, 1e-9, 1e15)) return FieldError{path + ".max_force", range(1e-9, 1e15, "N")};
  if (!in(j.motor_speed, -limits::kMaxAngularSpeed, limits::kMaxAngularSpeed))
    return FieldError{path + ".motor_speed", range(-limits::kMaxAngularSpeed, limits::kMaxAngularSpeed, "rad/s")};
  if (!in(j.max_motor_torque, 0.0, 1e12)) return FieldError{path + ".max_motor_torque", range(0.0, 1e12, "N m")};
  if (!in(j.motor_start_s, 0.0, limits::kMaxDurationS)) return FieldError{path + ".motor_start_s", range(0.0, limits::kMaxDurationS, "s")};
  return std::nullopt;
}

std::optional<FieldError> check_oscillator(const Scene& s, const OscillatorSettings& o, const std::string& path) {
  const bool from_joint = !o.joint.empty();
  if (from_joint) {
    const int j = joint_index(s, o.joint);
    if (j < 0 || !s.joints[j].tuning) return FieldError{path + ".joint", "must name a tuned joint of this scene"};
    if (o.effective_mass || o.tuning) return FieldError{path + ".joint", "copies mass and tuning from the joint: leave out effective_mass and the tuning fields"};
  } else {
    if (!o.effective_mass) return FieldError{path + ".effective_mass", "is required (kg) unless joint is given"};
    if (!o.tuning) return FieldError{path + ".frequency_hz", "give response_frames or frequency_hz (or joint)"};
  }
  if (!in(o.initial_displacement, -limits::kMaxWorldCoordinate, limits::kMaxWorldCoordinate))
    return FieldError{path + ".initial_displacement", range(-limits::kMaxWorldCoordinate, limits::kMaxWorldCoordinate, "m")};
  if (!in(o.initial_velocity, -limits::kMaxSpeed, limits::kMaxSpeed))
    return FieldError{path + ".initial_velocity", range(-limits::kMaxSpeed, limits::kMaxSpeed, "m/s")};
  return std::nullopt;
}

std::optional<FieldError> check_probe(const Scene& s, const ProbeSettings& p, const std::string& path) {
  switch (p.kind) {
    case ProbeKind::displacement:
    case ProbeKind::angle:
      if (body_index(s, p.body) < 0) return FieldError{path + ".body", "must name a body of this scene"};
      if (!p.joint.empty() && joint_index(s, p.joint) < 0) return FieldError{path + ".joint", "must name a joint of this scene"};
      break;
    case ProbeKind::joint_length:
    case ProbeKind::joint_angle:
    case ProbeKind::joint_error:
      if (joint_index(s, p.joint) < 0) return FieldError{path + ".joint", "must name a joint of this scene"};
      break;
    case ProbeKind::oscillator: {
      bool found = false;
      for (const auto& o : s.oscillators) found = found || o.id == p.oscillator;
      if (!found) return FieldError{path + ".oscillator", "must name an oscillator of this scene"};
      break;
    }
  }
  if (p.kind == ProbeKind::displacement && (!finite_vector(p.axis, 1e6) || p.axis.norm() < softtune::limits::kMinAxisLength))
    return FieldError{path + ".axis", "must be a finite, non-zero direction"};
  if (!in(p.from_s, 0.0, s.world.duration_s)) return FieldError{path + ".from_s", range(0.0, s.world.duration_s, "s") + " (within the run)"};
  if (p.to_s && !(in(*p.to_s, 0.0, s.world.duration_s) && *p.to_s > p.from_s))
    return FieldError{path + ".to_s", "must be after from_s and within the run (duration_s)"};
  if (p.requested_frequency_hz && !in(*p.requested_frequency_hz, 1e-6, softtune::limits::kMaxFrequencyHz))
    return FieldError{path + ".requested.frequency_hz", range(1e-6, softtune::limits::kMaxFrequencyHz, "Hz")};
  if (p.requested_damping_ratio && !in(*p.requested_damping_ratio, 0.0, softtune::limits::kMaxDampingRatio))
    return FieldError{path + ".requested.damping_ratio", range(0.0, softtune::limits::kMaxDampingRatio, "")};
  return std::nullopt;
}

// rates.fps / rates.substeps and an expectation's fps / substeps: the world's own ranges, at most kMaxRates each.
std::optional<FieldError> check_rate_lists(const std::vector<double>& fps, const std::vector<int>& substeps, const std::string& path) {
  const std::string count = "must hold at most " + std::to_string(limits::kMaxRates) + " entries";
  if (fps.size() > limits::kMaxRates) return FieldError{path + ".fps", count};
  if (substeps.size() > limits::kMaxRates) return FieldError{path + ".substeps", count};
  for (std::size_t i = 0; i < fps.size(); ++i) {
    if (!in(fps[i], softtune::limits::kMinFps, limits::kMaxSceneFps))
      return FieldError{path + ".fps." + std::to_string(i), range(softtune::limits::kMinFps, limits::kMaxSceneFps, "Hz")};
  }
  for (std::size_t i = 0; i < substeps.size(); ++i) {
    if (substeps[i] < 1 || substeps[i] > limits::kMaxSceneSubsteps)
      return FieldError{path + ".substeps." + std::to_string(i), "must be an integer in [1, " + std::to_string(limits::kMaxSceneSubsteps) + "]"};
  }
  return std::nullopt;
}

bool scene_wide(Metric m) {
  return m == Metric::max_constraint_error || m == Metric::finite || m == Metric::in_world;
}

std::optional<FieldError> check_expectation(const Scene& s, const Expectation& e, const std::string& path) {
  if (scene_wide(e.metric)) {
    if (!e.probe.empty()) return FieldError{path + ".probe", "must be left out for the scene-wide metric " + std::string(metric_name(e.metric))};
  } else {
    bool found = false;
    for (const auto& p : s.probes) found = found || p.id == e.probe;
    if (!found) return FieldError{path + ".probe", "must name a probe of this scene"};
  }
  const bool bounded = e.metric != Metric::finite && e.metric != Metric::in_world;
  if (bounded && !e.min && !e.max) return FieldError{path + ".max", "give min, max or both"};
  if ((e.min && !std::isfinite(*e.min)) || (e.max && !std::isfinite(*e.max)))
    return FieldError{path + (e.min && !std::isfinite(*e.min) ? ".min" : ".max"), "must be a finite number"};
  if (e.min && e.max && *e.min > *e.max) return FieldError{path + ".min", "must not exceed max"};
  if (auto r = check_rate_lists(e.at_fps, e.at_substeps, path)) return r;
  return std::nullopt;
}

template <typename T>
std::optional<FieldError> check_unique_ids(const std::vector<T>& items, const char* list) {
  std::set<std::string> seen;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].id.empty() || items[i].id.size() > limits::kMaxIdLength)
      return FieldError{at(list, i) + ".id", "must be 1 to " + std::to_string(limits::kMaxIdLength) + " characters"};
    if (!seen.insert(items[i].id).second) return FieldError{at(list, i) + ".id", "must be unique among " + std::string(list)};
  }
  return std::nullopt;
}

}  // namespace

bool applies_at(const Expectation& e, const WorldSettings& w) {
  const bool fps = e.at_fps.empty() || std::find(e.at_fps.begin(), e.at_fps.end(), w.fps) != e.at_fps.end();
  return fps && (e.at_substeps.empty() || std::find(e.at_substeps.begin(), e.at_substeps.end(), w.substeps) != e.at_substeps.end());
}

int frame_count(const WorldSettings& w) { return static_cast<int>(std::lround(w.duration_s * w.fps)); }

std::optional<FieldError> validate_scene(const Scene& s) {
  if (auto e = check_world(s.world)) return e;
  if (auto e = check_rate_lists(s.rates.fps, s.rates.substeps, "rates")) return e;
  if (!finite_vector(s.camera.center, limits::kMaxWorldCoordinate)) return FieldError{"camera.center", "must be finite, within the world coordinate range"};
  if (!in(s.camera.width_m, limits::kMinSize, limits::kMaxWorldCoordinate)) return FieldError{"camera.width_m", range(limits::kMinSize, limits::kMaxWorldCoordinate, "m")};
  if (!s.camera.follow.empty() && std::none_of(s.bodies.begin(), s.bodies.end(), [&](const BodySettings& b) { return b.id == s.camera.follow; })) {
    return FieldError{"camera.follow", "must name a body of the scene"};
  }
  if (s.bodies.size() > limits::kMaxBodies) return FieldError{"bodies", "must hold at most " + std::to_string(limits::kMaxBodies) + " bodies"};
  if (s.joints.size() > limits::kMaxJoints) return FieldError{"joints", "must hold at most " + std::to_string(limits::kMaxJoints) + " joints"};
  if (s.oscillators.size() > limits::kMaxOscillators) return FieldError{"oscillators", "must hold at most " + std::to_string(limits::kMaxOscillators)};
  if (s.probes.size() > limits::kMaxProbes) return FieldError{"probes", "must hold at most " + std::to_string(limits::kMaxProbes)};
  if (s.bodies.empty() && s.oscillators.empty()) return FieldError{"bodies", "a scene needs bodies or oscillators"};
  const double steps = static_cast<double>(frame_count(s.world)) * s.world.substeps;
  if (steps * static_cast<double>(s.bodies.size() + s.joints.size()) > limits::kMaxBodySteps)
    return FieldError{"world.duration_s", "duration_s * fps * substeps * (bodies + joints) must not exceed " +
                                              std::to_string(static_cast<long long>(limits::kMaxBodySteps)) + ": shorten the run or the scene"};
  if (auto e = check_unique_ids(s.bodies, "bodies")) return e;
  if (auto e = check_unique_ids(s.joints, "joints")) return e;
  if (auto e = check_unique_ids(s.oscillators, "oscillators")) return e;
  if (auto e = check_unique_ids(s.probes, "probes")) return e;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (auto e = check_body(s.bodies[i], at("bodies", i))) return e;
  }
  for (std::size_t i = 0; i < s.joints.size(); ++i) {
    if (auto e = check_joint(s, s.joints[i], at("joints", i))) return e;
  }
  for (std::size_t i = 0; i < s.oscillators.size(); ++i) {
    if (auto e = check_oscillator(s, s.oscillators[i], at("oscillators", i))) return e;
  }
  for (std::size_t i = 0; i < s.probes.size(); ++i) {
    if (auto e = check_probe(s, s.probes[i], at("probes", i))) return e;
  }
  for (std::size_t i = 0; i < s.expectations.size(); ++i) {
    if (auto e = check_expectation(s, s.expectations[i], at("expectations", i))) return e;
  }
  return validate_modal_tuning(s);
}

std::string_view joint_kind_name(JointKind k) {
  switch (k) {
    case JointKind::distance: return "distance";
    case JointKind::wheel: return "wheel";
    case JointKind::weld: return "weld";
    case JointKind::mouse: return "mouse";
    case JointKind::revolute: return "revolute";
  }
  return "unknown";
}

std::string_view box2d_joint_def(JointKind k) {
  switch (k) {
    case JointKind::distance: return "b2DistanceJointDef";
    case JointKind::wheel: return "b2WheelJointDef";
    case JointKind::weld: return "b2WeldJointDef";
    case JointKind::mouse: return "b2MouseJointDef";
    case JointKind::revolute: return "b2RevoluteJointDef";
  }
  return "b2JointDef";
}

std::string_view mass_model_name(MassModel m) { return m == MassModel::effective ? "effective" : "box2d_reduced"; }

std::string_view probe_kind_name(ProbeKind k) {
  switch (k) {
    case ProbeKind::displacement: return "displacement";
    case ProbeKind::angle: return "angle";
    case ProbeKind::joint_length: return "joint_length";
    case ProbeKind::joint_angle: return "joint_angle";
    case ProbeKind::joint_error: return "joint_error";
    case ProbeKind::oscillator: return "oscillator";
  }
  return "unknown";
}

std::string_view metric_name(Metric m) {
  switch (m) {
    case Metric::frequency_error: return "frequency_error";
    case Metric::damping_ratio_error: return "damping_ratio_error";
    case Metric::measured_frequency_hz: return "measured_frequency_hz";
    case Metric::measured_damping_ratio: return "measured_damping_ratio";
    case Metric::overshoot: return "overshoot";
    case Metric::settle_frames: return "settle_frames";
    case Metric::max_abs_value: return "max_abs_value";
    case Metric::settle_s: return "settle_s";
    case Metric::max_constraint_error: return "max_constraint_error";
    case Metric::finite: return "finite";
    case Metric::in_world: return "in_world";
  }
  return "unknown";
}

}  // namespace softtune::scene
