#include "softtune/scene/joint_tuning.h"

#include <algorithm>
#include <cmath>

#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"
#include "softtune/engines/box2d_v2_4.h"
#include "softtune/engines/engine_model.h"

#include "softtune/scene/scene_geometry.h"
#include "softtune/validation.h"

namespace softtune::scene {
namespace {

Eigen::Vector2d unit_or(const Eigen::Vector2d& v, const Eigen::Vector2d& fallback) {
  const double n = v.norm();
  return n > 0.0 ? Eigen::Vector2d(v / n) : fallback;
}

// b2AngularStiffness (box2d v2.4.1 src/dynamics/b2_joint.cpp) uses IA IB / (IA + IB) from b2Body::GetInertia,
// i.e. the same reduction as b2LinearStiffness, on rotational inertia.
double reduced_angular_inertia(const Body2D& a, const Body2D& b) {
  const bool static_a = a.is_static || !a.inertia, static_b = b.is_static || !b.inertia;
  return box2d_reduced_mass(a.inertia.value_or(0.0), static_a, b.inertia.value_or(0.0), static_b);
}

std::size_t box2d_model_index() {
  const auto models = engines::engine_models();
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i] == &engines::kBox2DV24Model) return i;
  }
  return 0;
}

}  // namespace

engines::SettingValues box2d_joint_settings(const JointSettings& j, const Constraint2D& c, const WorldSettings& world) {
  // The model's settings, in its order: joint (distance 0, wheel 1, mouse 2), velocityIterations, rotationShare.
  double joint = 0.0, rotation_share = 0.0;
  if (j.kind == JointKind::wheel) joint = 1.0;
  if (j.kind == JointKind::mouse) {
    joint = 2.0;
    const double k_inverse = inverse_effective_mass(c);
    if (c.body_b.inertia && *c.body_b.inertia > 0.0 && k_inverse > 0.0) {
      const Eigen::Vector2d r = c.anchor_b - c.body_b.position;
      const double r_cross_n = r.x() * c.axis.y() - r.y() * c.axis.x();
      rotation_share = std::clamp(r_cross_n * r_cross_n / *c.body_b.inertia / k_inverse, 0.0, 1.0);
    }
  }
  return {joint, static_cast<double>(world.velocity_iterations), rotation_share};
}

TuneRequest implicit_euler_request(double m, double k, double c, const WorldSettings& world) {
  const double h = step_size(world.fps, world.substeps), d = m + c * h + k * h * h;
  const RecurrencePoles poles = poles_of_recurrence((2.0 * m + c * h) / d, -m / d, h);
  TuneRequest q;
  q.fps = world.fps;
  q.substeps = world.substeps;
  q.mode = SoftMode::exact;
  q.frequency_hz = poles.frequency_hz.value_or(0.0);
  q.damping_ratio = poles.damping_ratio.value_or(0.0);
  q.effective_mass = m;
  return q;
}

Constraint2D joint_constraint(const JointSettings& j, const Body2D& body_a, const Body2D& body_b) {
  Constraint2D c;
  c.body_a = body_a;
  c.body_b = body_b;
  c.anchor_a = j.anchor_a;
  c.anchor_b = j.anchor_b;
  switch (j.kind) {
    case JointKind::distance:
      c.axis = unit_or(j.anchor_b - j.anchor_a, {0, 1});
      break;
    case JointKind::wheel:
      // Box2D's lever for body A is d + rA = pB - cA: body B's anchor seen from A's centre.
      c.anchor_a = j.anchor_b;
      c.axis = unit_or(j.axis, {0, 1});
      break;
    case JointKind::mouse:
      c.body_a = Body2D{};
      c.body_a.is_static = true;
      c.anchor_a = j.target;
      c.axis = unit_or(j.target - j.anchor_b, {1, 0});
      break;
    case JointKind::weld:
    case JointKind::revolute:
      c.type = ConstraintType::angular;
      break;
  }
  return c;
}

std::optional<FieldError> tune_joint(const JointSettings& j, const Constraint2D& c, const WorldSettings& world,
                                     MassModel model, const std::string& path, JointTuning& out) {
  out = JointTuning{};
  out.joint = j.id;
  out.mass_model = model;
  out.angular = c.type == ConstraintType::angular;
  const double k_inverse = inverse_effective_mass(c);
  out.effective_mass = k_inverse > 0.0 ? 1.0 / k_inverse : 0.0;
  out.box2d_reduced_mass = out.angular ? reduced_angular_inertia(c.body_a, c.body_b)
                                       : box2d_reduced_mass(c.body_a.mass, c.body_a.is_static, c.body_b.mass, c.body_b.is_static);
  out.model_mass = model == MassModel::effective ? out.effective_mass : out.box2d_reduced_mass;
  if (j.typed) {
    out.typed = true;
    out.stiffness = j.typed->stiffness;
    out.damping = j.typed->damping;
    return std::nullopt;
  }
  if (!j.tuning) {
    out.model_mass = 0.0;
    return std::nullopt;
  }

  out.tuned = true;
  TuneRequest request = *j.tuning;
  request.fps = world.fps;
  request.substeps = world.substeps;
  request.effective_mass = out.model_mass;
  request.constraint.reset();
  request.engine_settings.assign(engines::engine_models().size(), {});
  request.engine_settings[box2d_model_index()] = box2d_joint_settings(j, c, world);
  if (auto e = validate_tune_request(request)) {
    // A rotation-locked or infinite-mass pair gives m = 0: name the joint's bodies, not an input field.
    if (e->field == "effective_mass") return FieldError{path + ".body_b", "the joint's bodies give no usable mass: " + e->rule};
    return FieldError{path + "." + e->field, e->rule};
  }
  out.request = request;
  out.result = tune(request);
  out.requested_frequency_hz = requested_frequency_hz(request);
  out.requested_damping_ratio = requested_damping_ratio(request);
  SpringConstants spring = out.result.spring;
  // Box2D 2.4 divides by h (c + h k); exact mode at zeta = 0 makes that 0, which Box2D reads as "rigid".
  const double denominator = spring.damping + out.result.h * spring.stiffness;
  if (!(denominator > 0.0) || !std::isfinite(denominator)) {
    out.fell_back_to_standard = true;
    spring = out.result.standard_spring;
  }
  if (j.solved_spring) spring = *j.solved_spring;  // the solve's own numbers, not their round trip through f, zeta
  out.stiffness = spring.stiffness;
  out.damping = spring.damping;
  out.predicted_frequency_hz = out.result.frequency_hz * std::sqrt(out.model_mass / out.effective_mass);
  return std::nullopt;
}

Body2D start_body(const BodySettings& body) {
  Body2D b;
  b.is_static = body.is_static;
  b.angle = body.angle;
  const MassData m = body_mass(body);
  const double c = std::cos(body.angle), s = std::sin(body.angle);
  b.position = body.position + Eigen::Vector2d(c * m.local_centre.x() - s * m.local_centre.y(),
                                               s * m.local_centre.x() + c * m.local_centre.y());
  if (body.is_static) return b;
  b.mass = m.mass;
  if (!body.fixed_rotation) b.inertia = m.inertia;
  return b;
}

std::optional<FieldError> tune_scene_joints(const Scene& scene, MassModel model, std::vector<JointTuning>& out) {
  out.assign(scene.joints.size(), JointTuning{});
  auto body_of = [&scene](const std::string& id) {
    for (const BodySettings& b : scene.bodies) {
      if (b.id == id) return start_body(b);
    }
    Body2D ground;  // a mouse joint pulls against the ground
    ground.is_static = true;
    return ground;
  };
  for (std::size_t i = 0; i < scene.joints.size(); ++i) {
    const JointSettings& j = scene.joints[i];
    const Constraint2D c = joint_constraint(j, body_of(j.body_a), body_of(j.body_b));
    if (auto e = tune_joint(j, c, scene.world, model, "joints." + std::to_string(i), out[i])) return e;
  }
  return std::nullopt;
}

}  // namespace softtune::scene
