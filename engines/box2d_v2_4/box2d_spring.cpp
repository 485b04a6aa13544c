#include "box2d_spring.h"

#include <box2d/box2d.h>

namespace softtune {

std::vector<double> run_box2d_spring(const Oscillator& spring, double x0, double h, int steps) {
  b2World world(b2Vec2(0.0f, 0.0f));
  world.SetAllowSleeping(false);  // a decaying spring must keep moving, not freeze at the sleep tolerance

  b2BodyDef ground_def;
  b2Body* ground = world.CreateBody(&ground_def);

  b2BodyDef body_def;
  body_def.type = b2_dynamicBody;
  body_def.fixedRotation = true;
  body_def.position.Set(kBox2DRestLength + static_cast<float>(x0), 0.0f);
  b2Body* body = world.CreateBody(&body_def);
  // b2Vec2's default constructor leaves x and y unset, so `b2MassData{}` does not zero the centre: a
  // garbage centre of mass made every position NaN whenever the stack held garbage (ASan's fake stack).
  b2MassData mass{};
  mass.mass = static_cast<float>(spring.mass);
  mass.center.SetZero();
  mass.I = 0.0f;
  body->SetMassData(&mass);

  b2DistanceJointDef joint;
  joint.bodyA = ground;
  joint.bodyB = body;
  joint.localAnchorA.Set(0.0f, 0.0f);
  joint.localAnchorB.Set(0.0f, 0.0f);
  joint.length = kBox2DRestLength;
  joint.minLength = 0.0f;
  joint.maxLength = 1000.0f * kBox2DRestLength;
  joint.stiffness = static_cast<float>(spring.stiffness);
  joint.damping = static_cast<float>(spring.damping);
  world.CreateJoint(&joint);

  std::vector<double> x;
  x.reserve(static_cast<std::size_t>(steps) + 1);
  x.push_back(x0);
  for (int i = 0; i < steps; ++i) {
    world.Step(static_cast<float>(h), 8, 3);
    x.push_back(static_cast<double>(body->GetPosition().x) - kBox2DRestLength);
  }
  return x;
}

}  // namespace softtune
