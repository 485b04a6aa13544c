#include "softtune/scene/linearise.h"

#include <algorithm>
#include <cmath>

#include "softtune/designer.h"
#include "softtune/scene/box2d_scene.h"
#include "softtune/scene/limits.h"

namespace softtune::scene {
namespace {

using modes::AxisFrame;
using modes::Row;

Eigen::Vector2d eig(const b2Vec2& v) { return {v.x, v.y}; }
Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

bool at_rest(const std::vector<b2Body*>& bodies) {
  for (const b2Body* b : bodies) {
    if (b->GetType() != b2_dynamicBody) continue;
    if (b->GetLinearVelocity().Length() + std::abs(b->GetAngularVelocity()) >= kRestSpeed) return false;
  }
  return true;
}

// The frame the state is read after: `at_s`, else the end of the run or the first motor's start (a driven
// scene leaves its rest there), whichever is first; settling may stop it earlier.
int last_frame(const Scene& scene, const LinearisationOptions& options) {
  if (options.at_s) return static_cast<int>(std::lround(*options.at_s * scene.world.fps));
  int frames = frame_count(scene.world);
  for (const JointSettings& j : scene.joints) {
    if (j.kind == JointKind::wheel && j.max_motor_torque > 0.0 && j.motor_start_s > 0.0) {
      frames = std::min(frames, static_cast<int>(std::floor(j.motor_start_s * scene.world.fps)));
    }
  }
  return frames;
}

class RowBuilder {
 public:
  RowBuilder(LinearisedScene& out, const std::vector<b2Body*>& bodies) : out_(out), bodies_(bodies) {}

  int index(const b2Body* body) const {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      if (bodies_[i] == body) return out_.model_body[i];
    }
    return -1;  // a mouse joint's ground body
  }
  // An anchor as a Row wants it: from the body's centre of mass, or the world point itself for a static body.
  Eigen::Vector2d offset(const b2Body* body, const Eigen::Vector2d& world_point) const {
    return index(body) < 0 ? world_point : Eigen::Vector2d(world_point - eig(body->GetWorldCenter()));
  }
  Row linear(const b2Body* a, const Eigen::Vector2d& pa, const b2Body* b, const Eigen::Vector2d& pb, const Eigen::Vector2d& axis,
             AxisFrame frame, int joint) const {
    Row r;
    r.body_a = index(a);
    r.body_b = index(b);
    r.r_a = offset(a, pa);
    r.r_b = offset(b, pb);
    r.axis = axis;
    r.frame = frame;
    r.rigid = true;
    r.joint = joint;
    return r;
  }
  void add(Row r) {
    if (r.body_a >= 0 || r.body_b >= 0) out_.model.rows.push_back(r);
  }

 private:
  LinearisedScene& out_;
  const std::vector<b2Body*>& bodies_;
};

Row soften(Row r, const JointTuning& t, double position) {
  r.rigid = false;
  r.stiffness = t.stiffness;
  r.damping = t.damping;
  r.force = -t.stiffness * position;
  return r;
}

void joint_rows(const Scene& scene, std::size_t i, b2Joint* joint, const JointTuning& t, RowBuilder& rows) {
  const JointSettings& s = scene.joints[i];
  b2Body* a = joint->GetBodyA();
  b2Body* b = joint->GetBodyB();
  const Eigen::Vector2d pa = eig(joint->GetAnchorA()), pb = eig(joint->GetAnchorB());
  const int id = static_cast<int>(i);
  const bool soft = t.soft() && t.stiffness > 0.0;
  switch (s.kind) {
    case JointKind::distance: {
      Row r = rows.linear(a, pa, b, pb, (pb - pa).normalized(), AxisFrame::along_anchors, id);
      const double length = static_cast<b2DistanceJoint*>(joint)->GetLength();
      rows.add(soft ? soften(r, t, (pb - pa).norm() - length) : r);
      break;
    }
    case JointKind::wheel: {
      auto* w = static_cast<b2WheelJoint*>(joint);
      const Eigen::Vector2d axis = eig(a->GetWorldVector(w->GetLocalAxisA()));
      const Row along = rows.linear(a, pa, b, pb, axis, AxisFrame::body_a, id);
      if (soft) rows.add(soften(along, t, w->GetJointTranslation()));
      rows.add(rows.linear(a, pa, b, pb, perp(axis), AxisFrame::body_a, id));
      break;
    }
    case JointKind::mouse: {
      for (const Eigen::Vector2d& axis : {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)}) {
        Row r = rows.linear(nullptr, s.target, b, pb, axis, AxisFrame::world, id);
        r.body_a = -1;
        r.r_a = s.target;
        rows.add(soft ? soften(r, t, axis.dot(pb - s.target)) : r);
      }
      break;
    }
    case JointKind::weld:
    case JointKind::revolute: {
      for (const Eigen::Vector2d& axis : {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)}) {
        rows.add(rows.linear(a, pa, b, pb, axis, AxisFrame::world, id));
      }
      if (s.kind == JointKind::weld) {
        Row r = rows.linear(a, pa, b, pb, {0, 0}, AxisFrame::world, id);
        r.angular = true;
        const double angle = b->GetAngle() - a->GetAngle() - static_cast<b2WeldJoint*>(joint)->GetReferenceAngle();
        rows.add(soft ? soften(r, t, angle) : r);
      }
      break;
    }
  }
}

// A circle touches at its rim, but rolls: its normal row is anchored at its centre (a fixed body point on the
// rim would add a spurious stiffness to rolling). A polygon touches at a vertex, a fixed body point.
Eigen::Vector2d normal_anchor(const b2Fixture* f, const Eigen::Vector2d& point) {
  if (f->GetShape()->GetType() != b2Shape::e_circle) return point;
  return eig(f->GetBody()->GetWorldPoint(static_cast<const b2CircleShape*>(f->GetShape())->m_p));
}

}  // namespace

std::optional<FieldError> check_linearisable(const Scene& scene, std::optional<double> at_s, const std::string& at_field) {
  if (scene.bodies.empty()) return FieldError{"bodies", "modes need Box2D bodies on joints (this scene has none)"};
  const auto dynamic = std::count_if(scene.bodies.begin(), scene.bodies.end(), [](const BodySettings& b) { return !b.is_static; });
  if (static_cast<std::size_t>(dynamic) > limits::kMaxModeBodies)
    return FieldError{"bodies", "modes take at most " + std::to_string(limits::kMaxModeBodies) + " dynamic bodies"};
  if (at_s && !(*at_s >= 0.0 && *at_s <= scene.world.duration_s)) return FieldError{at_field, "must be within [0, world.duration_s] s"};
  return std::nullopt;
}

std::optional<FieldError> linearise_scene(const Scene& scene, MassModel mass_model, const LinearisationOptions& options,
                                          LinearisedScene& out) {
  out = LinearisedScene{};
  Box2DScene world(scene, mass_model);
  if (world.error()) return world.error();
  out.joints = world.tunings();
  out.h = step_size(scene.world.fps, scene.world.substeps);

  const int frames = last_frame(scene, options);
  int quiet = 0, frame = 0;
  for (; frame < frames; ++frame) {
    world.step_frame(frame);
    quiet = at_rest(world.bodies()) ? quiet + 1 : 0;
    if (!options.at_s && quiet >= kRestFrames) {
      out.settled = true;
      ++frame;
      break;
    }
  }
  out.settled = out.settled || (options.at_s && at_rest(world.bodies()));
  out.at_s = frame / scene.world.fps;

  out.model.gravity = scene.world.gravity;
  out.model_body.assign(scene.bodies.size(), -1);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const b2Body* b = world.bodies()[i];
    if (b->GetType() != b2_dynamicBody) continue;
    const Body2D core = Box2DScene::core_body(b);
    out.model_body[i] = static_cast<int>(out.model.bodies.size());
    out.scene_body.push_back(static_cast<int>(i));
    // A locked rotation keeps a unit inertia for the algebra and a rigid angular row below.
    out.model.bodies.push_back({scene.bodies[i].id, core.mass, core.inertia.value_or(1.0), core.position});
  }

  RowBuilder rows(out, world.bodies());
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (out.model_body[i] < 0 || !scene.bodies[i].fixed_rotation) continue;
    Row r;
    r.body_b = out.model_body[i];
    r.angular = true;
    r.rigid = true;
    rows.add(r);
  }
  for (std::size_t i = 0; i < scene.joints.size(); ++i) joint_rows(scene, i, world.joints()[i], out.joints[i], rows);

  for (b2Contact* c = world.world().GetContactList(); c; c = c->GetNext()) {
    if (!c->IsTouching() || !c->IsEnabled()) continue;
    const b2Fixture* fa = c->GetFixtureA();
    const b2Fixture* fb = c->GetFixtureB();
    b2WorldManifold wm;
    c->GetWorldManifold(&wm);
    const Eigen::Vector2d n = eig(wm.normal);  // from A to B
    for (int p = 0; p < c->GetManifold()->pointCount; ++p) {
      const Eigen::Vector2d point = eig(wm.points[p]);
      rows.add(rows.linear(fa->GetBody(), normal_anchor(fa, point), fb->GetBody(), normal_anchor(fb, point), n, AxisFrame::world, -1));
      if (c->GetFriction() > 0.0f) rows.add(rows.linear(fa->GetBody(), point, fb->GetBody(), point, perp(n), AxisFrame::world, -1));
      ++out.contact_points;
    }
  }
  out.balance_residual = modes::rigid_row_forces(out.model);
  return std::nullopt;
}

std::vector<int> spring_rows(const LinearisedScene& s, int joint) {
  std::vector<int> out;
  for (std::size_t i = 0; i < s.model.rows.size(); ++i) {
    if (s.model.rows[i].joint == joint && !s.model.rows[i].rigid) out.push_back(static_cast<int>(i));
  }
  return out;
}

}  // namespace softtune::scene
