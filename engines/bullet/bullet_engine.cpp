#include "bullet_engine.h"

#include <btBulletDynamicsCommon.h>

#include "softtune/engines/bullet.h"

namespace softtune::engines {
namespace {

std::string_view choice_of(const Parameters& ps, std::string_view name, std::string_view fallback) {
  for (const Parameter& p : ps) {
    if (p.name == name) return p.choice;
  }
  return fallback;
}

btScalar scalar(double value) { return static_cast<btScalar>(value); }

RunTrajectory run_bullet(const EngineRun& run) {
  const bool erp_cfm = run.settings.size() > kBulletRouteSetting &&
                       run.settings[kBulletRouteSetting] == kBulletRouteErpCfm;
  const int iterations = run.settings.size() > kBulletIterationsSetting
                             ? static_cast<int>(run.settings[kBulletIterationsSetting])
                             : 10;

  btDefaultCollisionConfiguration collision_configuration;
  btCollisionDispatcher dispatcher(&collision_configuration);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &collision_configuration);
  world.setGravity(btVector3(0, 0, 0));
  world.getSolverInfo().m_numIterations = iterations;

  // The body: a point of mass m_eff on the anchor, or the plank (mass 2 m_eff, the anchor `offset` above its
  // centre, perpendicular to the x axis; isotropic inertia, so the world tensor does not change as it turns).
  const bool plank = run.body == RunBody::rotating_plank;
  const PlankGeometry geometry = rotating_plank(run.effective_mass);
  const double mass = plank ? geometry.mass : run.effective_mass;
  const double offset = plank ? geometry.offset : 0.0;
  const btVector3 inertia = plank ? btVector3(scalar(geometry.inertia), scalar(geometry.inertia),
                                              scalar(geometry.inertia))
                                  : btVector3(0, 0, 0);
  btSphereShape shape(scalar(0.05));
  btRigidBody::btRigidBodyConstructionInfo info(scalar(mass), nullptr, &shape, inertia);
  info.m_startWorldTransform.setIdentity();
  info.m_startWorldTransform.setOrigin(btVector3(scalar(run.x0), scalar(-offset), 0));
  btRigidBody body(info);
  body.setActivationState(DISABLE_DEACTIVATION);

  // The ground: static (mass 0), not in the world, its frame at the origin; the body's frame on the anchor.
  btRigidBody ground(0, nullptr, nullptr);
  btTransform frame_a, frame_b;
  frame_a.setIdentity();
  frame_b.setIdentity();
  frame_b.setOrigin(btVector3(0, scalar(offset), 0));
  btGeneric6DofSpring2Constraint joint(ground, body, frame_a, frame_b);

  if (erp_cfm) {
    joint.setLinearLowerLimit(btVector3(0, 0, 0));  // all three locked; x is the soft one
    joint.setLinearUpperLimit(btVector3(0, 0, 0));
    joint.setParam(BT_CONSTRAINT_STOP_ERP, scalar(parameter_value(run.parameters, kBulletStopErp).value_or(0.2)), 0);
    joint.setParam(BT_CONSTRAINT_STOP_CFM, scalar(parameter_value(run.parameters, kBulletStopCfm).value_or(0.0)), 0);
  } else {
    joint.setLinearLowerLimit(btVector3(1, 0, 0));  // lower > upper: x free; y, z locked
    joint.setLinearUpperLimit(btVector3(-1, 0, 0));
    joint.enableSpring(0, true);
    joint.setStiffness(0, scalar(parameter_value(run.parameters, kBulletStiffness).value_or(0.0)),
                       choice_of(run.parameters, kBulletStiffnessLimit, kBulletTrue) == kBulletTrue);
    joint.setDamping(0, scalar(parameter_value(run.parameters, kBulletDamping).value_or(0.0)),
                     choice_of(run.parameters, kBulletDampingLimit, kBulletTrue) == kBulletTrue);
  }
  if (plank) {
    joint.setAngularLowerLimit(btVector3(0, 0, 1));  // x, y locked; z free (lower > upper)
    joint.setAngularUpperLimit(btVector3(0, 0, -1));
  }

  world.addRigidBody(&body);
  world.addConstraint(&joint, true);

  RunTrajectory x;
  x.reserve(static_cast<std::size_t>(run.steps) + 1);
  x.push_back(run.x0);
  const btVector3 anchor_local(0, scalar(offset), 0);
  for (int i = 0; i < run.steps; ++i) {
    world.stepSimulation(scalar(run.dt), 0);
    x.push_back(static_cast<double>((body.getCenterOfMassTransform() * anchor_local).x()));
  }
  world.removeConstraint(&joint);
  world.removeRigidBody(&body);
  return x;
}

}  // namespace

const RealEngine kBulletEngine = {"bullet", "3.24 (float)", run_bullet};

}  // namespace softtune::engines
