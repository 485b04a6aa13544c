#include "softtune/scene/probe_geometry.h"

#include <cmath>

#include "softtune/scene/scene_geometry.h"

namespace softtune::scene {
namespace {

int body_index(const Scene& scene, const std::string& id) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

Eigen::Vector2d rotate(double angle, const Eigen::Vector2d& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// The local point of a world point on a body as it starts.
Eigen::Vector2d local_point(const BodySettings& body, const Eigen::Vector2d& world) {
  return rotate(-body.angle, world - body.position);
}

Eigen::Vector2d pull_direction(const JointSettings& s) {
  const Eigen::Vector2d d = s.target - s.anchor_b;
  return d.norm() > 0.0 ? Eigen::Vector2d(d.normalized()) : Eigen::Vector2d(1, 0);
}

}  // namespace

std::vector<JointFrame> joint_frames(const Scene& scene) {
  std::vector<JointFrame> frames;
  for (const JointSettings& j : scene.joints) {
    JointFrame f;
    f.body_a = j.kind == JointKind::mouse ? -1 : body_index(scene, j.body_a);
    f.body_b = body_index(scene, j.body_b);
    const BodySettings& b = scene.bodies[f.body_b];
    const double angle_a = f.body_a >= 0 ? scene.bodies[f.body_a].angle : 0.0;
    f.reference_angle = b.angle - angle_a;
    // The world point each body holds: Initialize's one anchor for wheel, weld and revolute joints.
    Eigen::Vector2d world_a = j.anchor_a, world_b = j.anchor_b;
    if (j.kind == JointKind::wheel) world_a = world_b = j.anchor_b;
    if (j.kind == JointKind::weld || j.kind == JointKind::revolute) world_a = world_b = j.anchor_a;
    if (j.kind == JointKind::mouse) world_a = j.target;
    f.local_a = f.body_a >= 0 ? local_point(scene.bodies[f.body_a], world_a) : world_a;
    f.local_b = local_point(b, world_b);
    if (j.kind == JointKind::wheel) f.local_axis = rotate(-angle_a, j.axis.normalized());
    if (j.kind == JointKind::distance) f.rest_length = j.length.value_or((j.anchor_b - j.anchor_a).norm());
    frames.push_back(f);
  }
  return frames;
}

Eigen::Vector2d world_point(const BodyState& body, const Eigen::Vector2d& local) {
  return body.origin + rotate(body.angle, local);
}

Eigen::Vector2d anchor_a(const JointFrame& f, std::span<const BodyState> bodies) {
  return f.body_a >= 0 ? world_point(bodies[f.body_a], f.local_a) : f.local_a;
}

Eigen::Vector2d anchor_b(const JointFrame& f, std::span<const BodyState> bodies) {
  return world_point(bodies[f.body_b], f.local_b);
}

double joint_length(const JointSettings& joint, const JointFrame& f, std::span<const BodyState> bodies) {
  const Eigen::Vector2d gap = anchor_b(f, bodies) - anchor_a(f, bodies);
  switch (joint.kind) {
    case JointKind::wheel: return gap.dot(rotate(bodies[f.body_a].angle, f.local_axis));
    case JointKind::mouse: return (anchor_b(f, bodies) - joint.target).dot(pull_direction(joint));
    default: return gap.norm();
  }
}

double joint_angle(const JointFrame& f, std::span<const BodyState> bodies) {
  const double angle_a = f.body_a >= 0 ? bodies[f.body_a].angle : 0.0;
  return bodies[f.body_b].angle - angle_a - f.reference_angle;
}

double joint_error(const JointSettings& joint, const JointFrame& f, std::span<const BodyState> bodies) {
  // Springs have no rigid row.
  if (joint.kind == JointKind::mouse || (joint.kind == JointKind::distance && (joint.tuning || joint.typed))) return 0.0;
  const Eigen::Vector2d gap = anchor_b(f, bodies) - anchor_a(f, bodies);
  switch (joint.kind) {
    case JointKind::wheel: {
      const Eigen::Vector2d axis = rotate(bodies[f.body_a].angle, f.local_axis);
      return std::abs(gap.dot(Eigen::Vector2d(-axis.y(), axis.x())));
    }
    case JointKind::distance: return std::abs(gap.norm() - f.rest_length.value_or(0.0));
    default: return gap.norm();  // revolute, weld: the anchors coincide
  }
}

Snapshot snapshot(const Scene& scene, const std::vector<JointFrame>& frames, std::span<const BodyState> bodies,
                  std::vector<ContactSnapshot> contacts, int frame) {
  Snapshot out;
  out.frame = frame;
  out.time_s = frame / scene.world.fps;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const BodySettings& s = scene.bodies[i];
    const BodyState& state = bodies[i];
    BodySnapshot b;
    b.id = s.id;
    b.is_static = s.is_static;
    for (const ProbeSettings& p : scene.probes) b.probed = b.probed || p.body == b.id;
    b.center = state.origin;
    b.angle = state.angle;
    b.mass_centre = state.centre;
    if (s.shape.kind == ShapeKind::circle) {
      b.is_circle = true;
      b.radius = s.shape.radius;
    } else {
      for (const Eigen::Vector2d& v : local_outline(s.shape)) b.vertices.push_back(world_point(state, v));
    }
    out.bodies.push_back(std::move(b));
  }
  for (std::size_t i = 0; i < scene.joints.size(); ++i) {
    JointSnapshot s;
    s.id = scene.joints[i].id;
    s.kind = joint_kind_name(scene.joints[i].kind);
    s.anchor_a = anchor_a(frames[i], bodies);
    s.anchor_b = anchor_b(frames[i], bodies);
    s.rest_length = frames[i].rest_length;
    s.current_length = (s.anchor_b - s.anchor_a).norm();
    out.joints.push_back(std::move(s));
  }
  out.contacts = std::move(contacts);
  return out;
}

}  // namespace softtune::scene
