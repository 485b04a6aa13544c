#include "softtune/scene/box2d_scene.h"

#include <cmath>

#include "softtune/designer.h"
#include "softtune/support/run_limit.h"

namespace softtune::scene {
namespace {

b2Vec2 vec(const Eigen::Vector2d& v) { return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y())); }

int index_of(const std::vector<BodySettings>& bodies, const std::string& id) {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

b2Body* create_body(b2World& world, const BodySettings& s) {
  b2BodyDef bd;
  bd.type = s.is_static ? b2_staticBody : b2_dynamicBody;
  bd.position = vec(s.position);
  bd.angle = static_cast<float>(s.angle);
  bd.linearVelocity = vec(s.linear_velocity);
  bd.angularVelocity = static_cast<float>(s.angular_velocity);
  bd.fixedRotation = s.fixed_rotation;
  b2Body* body = world.CreateBody(&bd);

  b2PolygonShape polygon;
  b2CircleShape circle;
  b2FixtureDef fd;
  switch (s.shape.kind) {
    case ShapeKind::box:
      polygon.SetAsBox(static_cast<float>(s.shape.width / 2), static_cast<float>(s.shape.height / 2));
      fd.shape = &polygon;
      break;
    case ShapeKind::circle:
      circle.m_radius = static_cast<float>(s.shape.radius);
      fd.shape = &circle;
      break;
    case ShapeKind::polygon: {
      std::vector<b2Vec2> points;
      for (const auto& v : s.shape.vertices) points.push_back(vec(v));
      polygon.Set(points.data(), static_cast<int32>(points.size()));
      fd.shape = &polygon;
      break;
    }
  }
  fd.density = s.is_static ? 0.0f : static_cast<float>(s.density);
  fd.friction = static_cast<float>(s.friction);
  fd.restitution = static_cast<float>(s.restitution);
  body->CreateFixture(&fd);

  // A given mass scales Box2D's own mass data (mass and inertia both scale with density).
  if (!s.is_static && s.mass) {
    b2MassData md;
    body->GetMassData(&md);
    const float scale = static_cast<float>(*s.mass) / md.mass;
    md.mass *= scale;
    md.I *= scale;
    body->SetMassData(&md);
  }
  return body;
}

}  // namespace

Body2D Box2DScene::core_body(const b2Body* body) {
  Body2D b;
  b.is_static = body->GetType() != b2_dynamicBody;
  b.mass = body->GetMass();
  // b2Body::GetInertia is about the body origin; the core wants it about the centre of mass.
  const b2Vec2 lc = body->GetLocalCenter();
  if (!b.is_static && !body->IsFixedRotation()) b.inertia = body->GetInertia() - body->GetMass() * b2Dot(lc, lc);
  const b2Vec2 c = body->GetWorldCenter();
  b.position = {c.x, c.y};
  b.angle = body->GetAngle();
  return b;
}

namespace {

// The Box2D 2.4 joint for one scene joint, with its tuning's stiffness and damping.
b2Joint* create_joint(b2World& world, const JointSettings& j, const JointTuning& t, b2Body* body_a, b2Body* body_b) {
  // Every soft joint def of Box2D 2.4 takes stiffness (N/m, or N m/rad for the weld) and damping.
  auto create = [&](auto& def) {
    def.stiffness = static_cast<float>(t.stiffness);
    def.damping = static_cast<float>(t.damping);
    def.collideConnected = j.collide_connected;
    return world.CreateJoint(&def);
  };
  switch (j.kind) {
    case JointKind::distance: {
      // b2DistanceJointDef (v2.4.1 include/box2d/b2_distance_joint.h): soft when stiffness > 0 and
      // minLength < maxLength; minLength == maxLength makes it a rigid rod.
      b2DistanceJointDef d;
      d.bodyA = body_a;
      d.bodyB = body_b;
      d.localAnchorA = body_a->GetLocalPoint(vec(j.anchor_a));
      d.localAnchorB = body_b->GetLocalPoint(vec(j.anchor_b));
      d.length = static_cast<float>(j.length.value_or((j.anchor_b - j.anchor_a).norm()));
      d.minLength = t.soft() ? 0.0f : d.length;
      d.maxLength = t.soft() ? FLT_MAX : d.length;
      return create(d);
    }
    case JointKind::wheel: {
      b2WheelJointDef w;
      w.Initialize(body_a, body_b, vec(j.anchor_b), vec(j.axis.normalized()));
      w.motorSpeed = static_cast<float>(j.motor_speed);
      w.maxMotorTorque = static_cast<float>(j.max_motor_torque);
      w.enableMotor = j.max_motor_torque > 0.0 && j.motor_start_s <= 0.0;
      return create(w);
    }
    case JointKind::weld: {
      // b2WeldJointDef: stiffness in N m (per rad), damping in N m s; 0 = rigid.
      b2WeldJointDef w;
      w.Initialize(body_a, body_b, vec(j.anchor_a));
      return create(w);
    }
    case JointKind::mouse: {
      // b2MouseJointDef::target is where body B is grabbed (the joint stores it as localAnchorB);
      // SetTarget then moves the point it is pulled to.
      b2MouseJointDef m;
      m.bodyA = body_a;
      m.bodyB = body_b;
      m.target = vec(j.anchor_b);
      m.maxForce = static_cast<float>(j.max_force);
      auto* mouse = static_cast<b2MouseJoint*>(create(m));
      mouse->SetTarget(vec(j.target));
      return mouse;
    }
    case JointKind::revolute: {
      b2RevoluteJointDef r;
      r.Initialize(body_a, body_b, vec(j.anchor_a));
      r.collideConnected = j.collide_connected;
      return world.CreateJoint(&r);
    }
  }
  return nullptr;
}

}  // namespace

Box2DScene::Box2DScene(const Scene& scene, MassModel model, std::span<const std::optional<JointSpring>> springs)
    : scene_(scene) {
  world_ = std::make_unique<b2World>(vec(scene.world.gravity));
  world_->SetAllowSleeping(scene.world.allow_sleeping);
  for (const BodySettings& s : scene.bodies) bodies_.push_back(create_body(*world_, s));
  if ((error_ = tune_scene_joints(scene, model, tunings_))) return;
  for (std::size_t i = 0; i < springs.size() && i < tunings_.size(); ++i) {
    if (!springs[i]) continue;
    tunings_[i].stiffness = springs[i]->stiffness;
    tunings_[i].damping = springs[i]->damping;
  }
  for (std::size_t i = 0; i < scene.joints.size(); ++i) {
    const JointSettings& j = scene.joints[i];
    b2Body* body_a = nullptr;
    if (j.kind == JointKind::mouse) {
      if (!ground_) {
        b2BodyDef ground;
        ground_ = world_->CreateBody(&ground);
      }
      body_a = ground_;
    } else {
      body_a = bodies_[index_of(scene.bodies, j.body_a)];
    }
    joints_.push_back(create_joint(*world_, j, tunings_[i], body_a, bodies_[index_of(scene.bodies, j.body_b)]));
  }
}

void Box2DScene::step_frame(int frame) {
  // A request's or job's run-time limit (softtune/support/run_limit.h): a crowded scene's frame can take
  // 0.1-0.3 s, so the limit is checked every frame, and the run ends within one frame of it.
  support::check_run_limit();
  const WorldSettings& w = scene_.world;
  const double t = frame / w.fps;
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    const JointSettings& j = scene_.joints[i];
    if (j.kind == JointKind::wheel && j.max_motor_torque > 0.0 && t >= j.motor_start_s) {
      static_cast<b2WheelJoint*>(joints_[i])->EnableMotor(true);
    }
  }
  const float dt = static_cast<float>(step_size(w.fps, w.substeps));
  for (int s = 0; s < w.substeps; ++s) world_->Step(dt, w.velocity_iterations, w.position_iterations);
}

BodyState Box2DScene::body(std::size_t i) const {
  const b2Body* b = bodies_[i];
  BodyState out;
  out.origin = {b->GetPosition().x, b->GetPosition().y};
  out.centre = {b->GetWorldCenter().x, b->GetWorldCenter().y};
  out.angle = b->GetAngle();
  out.velocity = {b->GetLinearVelocity().x, b->GetLinearVelocity().y};
  out.angular_velocity = b->GetAngularVelocity();
  return out;
}

std::vector<ContactSnapshot> Box2DScene::contacts() const {
  std::vector<ContactSnapshot> out;
  for (const b2Contact* c = world_->GetContactList(); c; c = c->GetNext()) {
    if (!c->IsTouching() || !c->IsEnabled()) continue;
    b2WorldManifold m;
    c->GetWorldManifold(&m);
    for (int k = 0; k < c->GetManifold()->pointCount; ++k) {
      out.push_back({{m.points[k].x, m.points[k].y}, {m.normal.x, m.normal.y}});
    }
  }
  return out;
}

}  // namespace softtune::scene
