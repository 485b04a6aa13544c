#include "box2d_v2_4_run.h"

#include <box2d/box2d.h>

#include <cmath>
#include <memory>

namespace softtune::engines {
namespace {

enum class Joint { distance = 0, wheel = 1, mouse = 2 };

double parameter_or(const Parameters& parameters, std::string_view name, double fallback) {
  const std::optional<double> v = parameter_value(parameters, name);
  return v ? *v : fallback;
}

b2Vec2 vec(float x, float y) {
  b2Vec2 v;
  v.Set(x, y);
  return v;
}

RunTrajectory run(const EngineRun& r) {
  const Joint joint = r.settings.empty() ? Joint::distance : static_cast<Joint>(static_cast<int>(r.settings[0]));
  const int velocity_iterations = r.settings.size() > 1 ? static_cast<int>(r.settings[1]) : 8;
  const char* def_name = joint == Joint::wheel ? "b2WheelJointDef" : joint == Joint::mouse ? "b2MouseJointDef"
                                                                                           : "b2DistanceJointDef";
  const std::string stiffness_name = std::string(def_name) + "::stiffness";
  const std::string damping_name = std::string(def_name) + "::damping";
  const float stiffness = static_cast<float>(parameter_or(r.parameters, stiffness_name, 0.0));
  const float damping = static_cast<float>(parameter_or(r.parameters, damping_name, 0.0));

  auto world = std::make_unique<b2World>(vec(0.0f, 0.0f));
  world->SetAllowSleeping(false);  // a decaying spring must keep moving, not freeze at the sleep tolerance

  b2BodyDef ground_def;
  ground_def.position = vec(0.0f, 0.0f);
  ground_def.linearVelocity = vec(0.0f, 0.0f);
  b2Body* ground = world->CreateBody(&ground_def);

  // Where the anchor starts: the distance joint's rest length plus x0 along x, else x0.
  const float x0 = static_cast<float>(r.x0);
  const float rest = joint == Joint::distance ? kBox2DV24RestLength : 0.0f;
  const bool plank = r.body == RunBody::rotating_plank;
  const PlankGeometry g = rotating_plank(r.effective_mass);
  const b2Vec2 local_anchor = plank ? vec(0.0f, static_cast<float>(g.offset)) : vec(0.0f, 0.0f);

  b2BodyDef body_def;
  body_def.type = b2_dynamicBody;
  body_def.fixedRotation = !plank;
  body_def.position = vec(rest + x0 - local_anchor.x, -local_anchor.y);
  body_def.linearVelocity = vec(0.0f, 0.0f);
  body_def.angle = 0.0f;
  body_def.angularVelocity = 0.0f;
  b2Body* body = world->CreateBody(&body_def);
  b2MassData mass{};
  mass.mass = static_cast<float>(plank ? g.mass : r.effective_mass);
  mass.center.SetZero();
  mass.I = plank ? static_cast<float>(g.inertia) : 0.0f;
  body->SetMassData(&mass);

  b2MouseJoint* mouse = nullptr;
  switch (joint) {
    case Joint::distance: {
      b2DistanceJointDef def;
      def.bodyA = ground;
      def.bodyB = body;
      def.localAnchorA = vec(0.0f, 0.0f);
      def.localAnchorB = local_anchor;
      def.length = kBox2DV24RestLength;
      def.minLength = 0.0f;
      def.maxLength = 1000.0f * kBox2DV24RestLength;
      def.stiffness = stiffness;
      def.damping = damping;
      world->CreateJoint(&def);
      break;
    }
    case Joint::wheel: {
      b2WheelJointDef def;
      def.bodyA = ground;
      def.bodyB = body;
      def.localAnchorA = vec(0.0f, 0.0f);
      def.localAnchorB = local_anchor;
      def.localAxisA = vec(1.0f, 0.0f);
      def.enableLimit = false;
      def.enableMotor = false;
      def.stiffness = stiffness;
      def.damping = damping;
      world->CreateJoint(&def);
      break;
    }
    case Joint::mouse: {
      // The def's target fixes the body's anchor (m_localAnchorB = b2MulT(xfB, target)); then the target
      // moves to the origin, x0 away.
      b2MouseJointDef def;
      def.bodyA = ground;
      def.bodyB = body;
      def.target = body->GetWorldPoint(local_anchor);
      def.maxForce = static_cast<float>(parameter_or(r.parameters, "b2MouseJointDef::maxForce", kBox2DV24MouseMaxForce));
      def.stiffness = stiffness;
      def.damping = damping;
      mouse = static_cast<b2MouseJoint*>(world->CreateJoint(&def));
      mouse->SetTarget(vec(0.0f, 0.0f));
      break;
    }
  }

  auto stretch = [&]() -> double {
    const b2Vec2 anchor = body->GetWorldPoint(local_anchor);
    if (joint == Joint::distance) return static_cast<double>(anchor.Length()) - static_cast<double>(kBox2DV24RestLength);
    return static_cast<double>(anchor.x);  // wheel: translation along x; mouse: anchor minus target (origin)
  };

  RunTrajectory x;
  x.reserve(static_cast<std::size_t>(r.steps) + 1);
  x.push_back(stretch());
  for (int i = 0; i < r.steps; ++i) {
    world->Step(static_cast<float>(r.dt), velocity_iterations, 3);
    x.push_back(stretch());
  }
  return x;
}

}  // namespace

const RealEngine kBox2DV24Engine = {"box2d_v2_4", "Box2D 2.4.1 (libbox2d-dev)", run};

}  // namespace softtune::engines
