#include "bullet_scene.h"

#include <btBulletDynamicsCommon.h>

#include <array>
#include <cmath>
#include <string>

#include "softtune/designer.h"
#include "softtune/engines/bullet.h"
#include "softtune/scene/scene_geometry.h"
#include "softtune/support/run_limit.h"

namespace softtune::scene {
namespace {

constexpr std::array<std::string_view, 2> kOffOn = {"false", "true"};
constexpr std::size_t kIterations = 0, kErp = 1, kErp2 = 2, kSplitImpulse = 3;
// btContactSolverInfo's own defaults (btContactSolverInfo.h, btContactSolverInfoData's constructor).
constexpr std::array<engines::SettingSpec, 4> kSettings = {{
    {"m_numIterations", 10, 1, 1000, true, {}, "",
     "btContactSolverInfo::m_numIterations, the solver's sweeps per step"},
    {"m_erp", 0.2, 0, 1, false, {}, "", "btContactSolverInfo::m_erp, the joints' error reduction per step"},
    {"m_erp2", 0.2, 0, 1, false, {}, "", "btContactSolverInfo::m_erp2, the contacts' error reduction per step"},
    {"m_splitImpulse", 1, 0, 1, true, kOffOn, "",
     "btContactSolverInfo::m_splitImpulse: contact penetration is pushed out by a separate velocity"},
}};

// The largest mouse force that means "no cap" (JointSettings::max_force's default, Box2D's unbounded pull).
constexpr double kUncappedMouseForce = 1.0e9;
constexpr btScalar kMargin = btScalar(0.01);  // b2_polygonRadius: Box2D's polygon skin
constexpr btScalar kHalfDepth = btScalar(0.5);

btScalar sc(double v) { return static_cast<btScalar>(v); }
btVector3 vec3(const Eigen::Vector2d& v) { return btVector3(sc(v.x()), sc(v.y()), 0); }

int body_index(const Scene& scene, const std::string& id) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

// A world basis whose x column is `x` (unit, in the plane), z the plane normal.
btMatrix3x3 plane_basis(const Eigen::Vector2d& x) {
  return btMatrix3x3(sc(x.x()), sc(-x.y()), 0, sc(x.y()), sc(x.x()), 0, 0, 0, 1);
}

// The constraint frame of a world point and world basis, in a body's centre-of-mass frame.
btTransform local_frame(const btRigidBody& body, const btVector3& point, const btMatrix3x3& basis) {
  return body.getCenterOfMassTransform().inverse() * btTransform(basis, point);
}

double plane_angle(const btTransform& t) {
  const btMatrix3x3& m = t.getBasis();
  return std::atan2(static_cast<double>(m[1][0]), static_cast<double>(m[0][0]));
}

// Free every row of a 6-DoF (lower > upper) before the joint kind locks or springs its own.
void free_all(btGeneric6DofSpring2Constraint& c) {
  c.setLinearLowerLimit(btVector3(1, 1, 1));
  c.setLinearUpperLimit(btVector3(-1, -1, -1));
  c.setAngularLowerLimit(btVector3(1, 1, 1));
  c.setAngularUpperLimit(btVector3(-1, -1, -1));
}

void lock(btGeneric6DofSpring2Constraint& c, int axis, double at = 0.0) {
  if (axis < 3) {
    c.getTranslationalLimitMotor()->m_lowerLimit[axis] = sc(at);
    c.getTranslationalLimitMotor()->m_upperLimit[axis] = sc(at);
  } else {
    c.getRotationalLimitMotor(axis - 3)->m_loLimit = sc(at);
    c.getRotationalLimitMotor(axis - 3)->m_hiLimit = sc(at);
  }
}

// The spring on a free axis, k and c as typed (limitIfNeeded false), its equilibrium at `rest`.
void spring(btGeneric6DofSpring2Constraint& c, int axis, const JointSpring& s, double rest = 0.0) {
  c.enableSpring(axis, true);
  c.setStiffness(axis, sc(s.stiffness), false);
  c.setDamping(axis, sc(s.damping), false);
  c.setEquilibriumPoint(axis, sc(rest));
}

// Whether the spring row's step (semi-implicit Euler on the m get_limit_motor_info2 computes: the dynamic
// body's mass, mA mB / (mA + mB) for two; inertias for the weld's rotation, the anchors' lever arms left out)
// stays bounded: core/engines/bullet.h's step map.
bool explicit_spring_stable(const btRigidBody& a, const btRigidBody& b, bool rotational, const JointSpring& s,
                            double h) {
  auto inverse = [&](const btRigidBody& r) {
    return static_cast<double>(rotational ? r.getInvInertiaDiagLocal().z() : r.getInvMass());
  };
  const double inv = inverse(a) + inverse(b);
  if (!(inv > 0.0)) return true;
  const double m = 1.0 / inv;
  return engines::predict_from_step_map(engines::bullet_spring2_step_map(m, s.stiffness, s.damping, h), h).stable;
}

struct BulletJoint {
  const JointSettings* settings = nullptr;
  std::unique_ptr<btGeneric6DofSpring2Constraint> constraint;
  int a = -1, b = -1;                       // body indices; a = -1: the fixed body
  btVector3 local_a{0, 0, 0}, local_b{0, 0, 0};  // distance: the anchors in the bodies' centre-of-mass frames
  bool motor_on = false;
};

class BulletWorld final : public SceneWorld {
 public:
  BulletWorld(const SceneBuild& build, std::optional<FieldError>& error);
  ~BulletWorld() override;
  void step_frame(int frame) override;
  BodyState body(std::size_t i) const override;
  std::vector<ContactSnapshot> contacts() const override;
  bool ok() const { return ok_; }

 private:
  btRigidBody& rigid(int i) { return i < 0 ? fixed_ : *bodies_[static_cast<std::size_t>(i)]; }
  bool add_joint(std::size_t i, const std::optional<JointSpring>& s, std::optional<FieldError>& error);
  void aim_distance(BulletJoint& j);

  const Scene& scene_;
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &configuration_};
  btRigidBody fixed_{0, nullptr, nullptr};  // a mouse joint's other side (not in the world, as in bullet_engine.cpp)
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<Eigen::Vector2d> local_centres_;
  std::vector<BulletJoint> joints_;
  bool ok_ = true;
};

std::unique_ptr<btCollisionShape> make_shape(const BodySettings& s, const MassData& md) {
  std::unique_ptr<btCollisionShape> shape;
  switch (s.shape.kind) {
    case ShapeKind::box:
      shape = std::make_unique<btBoxShape>(btVector3(sc(s.shape.width / 2), sc(s.shape.height / 2), kHalfDepth));
      break;
    case ShapeKind::circle:
      shape = std::make_unique<btCylinderShapeZ>(btVector3(sc(s.shape.radius), sc(s.shape.radius), kHalfDepth));
      break;
    case ShapeKind::polygon: {
      auto hull = std::make_unique<btConvexHullShape>();
      for (const Eigen::Vector2d& v : s.shape.vertices) {
        const Eigen::Vector2d p = v - md.local_centre;  // Bullet's body frame is the centre of mass
        hull->addPoint(btVector3(sc(p.x()), sc(p.y()), -kHalfDepth), false);
        hull->addPoint(btVector3(sc(p.x()), sc(p.y()), kHalfDepth), false);
      }
      hull->recalcLocalAabb();
      shape = std::move(hull);
      break;
    }
  }
  shape->setMargin(kMargin);
  return shape;
}

BulletWorld::BulletWorld(const SceneBuild& build, std::optional<FieldError>& error) : scene_(*build.scene) {
  const engines::SettingValues& v = build.settings;
  auto setting = [&](std::size_t i) { return v.size() > i ? v[i] : kSettings[i].default_value; };
  btContactSolverInfo& info = world_.getSolverInfo();
  info.m_numIterations = static_cast<int>(setting(kIterations));
  info.m_erp = sc(setting(kErp));
  info.m_erp2 = sc(setting(kErp2));
  info.m_splitImpulse = setting(kSplitImpulse) != 0.0;
  world_.setGravity(vec3(scene_.world.gravity));

  for (const BodySettings& s : scene_.bodies) {
    const MassData md = body_mass(s);
    shapes_.push_back(make_shape(s, md));
    const double inertia = md.inertia;
    btRigidBody::btRigidBodyConstructionInfo ci(sc(md.mass), nullptr, shapes_.back().get(),
                                                btVector3(sc(inertia), sc(inertia), sc(inertia)));
    const Eigen::Rotation2Dd r(s.angle);
    const Eigen::Vector2d centre = s.position + r * md.local_centre;
    ci.m_startWorldTransform = btTransform(btQuaternion(btVector3(0, 0, 1), sc(s.angle)), vec3(centre));
    ci.m_friction = sc(std::sqrt(s.friction));  // the pair's product is sqrt(fa fb): b2MixFriction
    ci.m_restitution = sc(s.restitution);
    auto body = std::make_unique<btRigidBody>(ci);
    if (!s.is_static) {
      body->setLinearFactor(btVector3(1, 1, 0));
      body->setAngularFactor(btVector3(0, 0, s.fixed_rotation ? 0 : 1));
      body->setLinearVelocity(vec3(s.linear_velocity));
      body->setAngularVelocity(btVector3(0, 0, sc(s.fixed_rotation ? 0.0 : s.angular_velocity)));
    }
    if (!scene_.world.allow_sleeping) body->setActivationState(DISABLE_DEACTIVATION);
    world_.addRigidBody(body.get());
    bodies_.push_back(std::move(body));
    local_centres_.push_back(md.local_centre);
  }
  for (std::size_t i = 0; i < scene_.joints.size() && ok_; ++i) {
    std::optional<JointSpring> s;
    if (i < build.springs.size()) s = build.springs[i];
    ok_ = add_joint(i, s, error);
  }
}

bool BulletWorld::add_joint(std::size_t i, const std::optional<JointSpring>& s, std::optional<FieldError>& error) {
  const JointSettings& j = scene_.joints[i];
  const std::string field = "joints." + std::to_string(i);
  BulletJoint out;
  out.settings = &j;
  out.a = j.kind == JointKind::mouse ? -1 : body_index(scene_, j.body_a);
  out.b = body_index(scene_, j.body_b);
  btRigidBody& a = rigid(out.a);
  btRigidBody& b = rigid(out.b);
  // Each kind's frame: a world point and basis the two bodies share at the start.
  btVector3 point = vec3(j.anchor_a);
  btMatrix3x3 basis = plane_basis({1, 0});
  switch (j.kind) {
    case JointKind::wheel: {
      const Eigen::Vector2d axis = j.axis.normalized();
      point = vec3(j.anchor_b);  // b2WheelJointDef::Initialize puts both anchors on the one anchor given
      basis = plane_basis({axis.y(), -axis.x()});  // x across the axis, y along it
      break;
    }
    case JointKind::mouse:
      if (j.max_force < kUncappedMouseForce) {
        error = FieldError{field + ".max_force",
                           "bullet has no force cap on a spring (btGeneric6DofSpring2Constraint): a mouse joint's "
                           "max_force must be at least 1e9 (uncapped)"};
        return false;
      }
      if (!s) {
        error = FieldError{field + ".type",
                           "bullet builds a mouse joint as a spring: it needs a tuning or typed values"};
        return false;
      }
      point = vec3(j.anchor_b);
      break;
    case JointKind::distance:
      point = vec3(j.anchor_a);
      break;
    default:
      break;
  }
  const double h = step_size(scene_.world.fps, scene_.world.substeps);
  if (s && !explicit_spring_stable(a, b, j.kind == JointKind::weld, *s, h)) {
    error = FieldError{field, "bullet's spring row is explicit (semi-implicit Euler on the bodies' mass, "
                              "btGeneric6DofSpring2Constraint::get_limit_motor_info2): this stiffness and damping "
                              "grow at the scene's step (omega h above 2); Bullet would blow up"};
    return false;
  }
  btTransform frame_a = local_frame(a, point, basis), frame_b = local_frame(b, point, basis);
  if (j.kind == JointKind::distance) {
    out.local_a = a.getCenterOfMassTransform().inverse() * vec3(j.anchor_a);
    out.local_b = b.getCenterOfMassTransform().inverse() * vec3(j.anchor_b);
    frame_b = local_frame(b, vec3(j.anchor_b), basis);
  }
  if (j.kind == JointKind::mouse) {
    // The fixed body's frame at the target, body B's at its anchor: the spring pulls the anchor to the target.
    frame_a = btTransform(basis, vec3(j.target));
  }
  out.constraint = std::make_unique<btGeneric6DofSpring2Constraint>(a, b, frame_a, frame_b);
  btGeneric6DofSpring2Constraint& c = *out.constraint;
  free_all(c);
  switch (j.kind) {
    case JointKind::wheel:
      lock(c, 0);
      if (s) spring(c, 1, *s); else lock(c, 1);
      if (j.max_motor_torque > 0.0) {
        // The rotational motor on z. Its rows measure A's rotation relative to B (get_limit_motor_info2's
        // "rotational ? -1 : 1"), so Box2D's speed of B relative to A is typed with the other sign.
        c.setTargetVelocity(5, sc(-j.motor_speed));
        c.setMaxMotorForce(5, sc(j.max_motor_torque));
      }
      break;
    case JointKind::distance: {
      const double length = j.length.value_or((j.anchor_b - j.anchor_a).norm());
      if (s) spring(c, 0, *s, length); else lock(c, 0, length);
      break;
    }
    case JointKind::weld:
      lock(c, 0);
      lock(c, 1);
      if (s) spring(c, 5, *s); else lock(c, 5);
      break;
    case JointKind::mouse:
      spring(c, 0, *s);
      spring(c, 1, *s);
      break;
    case JointKind::revolute:
      lock(c, 0);
      lock(c, 1);
      break;
  }
  world_.addConstraint(out.constraint.get(), !j.collide_connected);
  joints_.push_back(std::move(out));
  if (j.kind == JointKind::distance) aim_distance(joints_.back());
  return true;
}

// A distance joint's frames along the anchor line as it is now: the sprung (or locked) x row then acts
// along the line, as b2DistanceJoint's does, and measures the anchors' distance.
void BulletWorld::aim_distance(BulletJoint& j) {
  btRigidBody& a = rigid(j.a);
  btRigidBody& b = rigid(j.b);
  const btVector3 pa = a.getCenterOfMassTransform() * j.local_a, pb = b.getCenterOfMassTransform() * j.local_b;
  const btVector3 d = pb - pa;
  const btScalar n = d.length();
  if (!(n > btScalar(1e-6))) return;  // anchors together: keep the last direction
  const btMatrix3x3 basis = plane_basis({d.x() / n, d.y() / n});
  j.constraint->setFrames(local_frame(a, pa, basis), local_frame(b, pb, basis));
}

BulletWorld::~BulletWorld() {
  for (BulletJoint& j : joints_) world_.removeConstraint(j.constraint.get());
  for (auto& b : bodies_) world_.removeRigidBody(b.get());
}

void BulletWorld::step_frame(int frame) {
  support::check_run_limit();
  const WorldSettings& w = scene_.world;
  const double t = frame / w.fps;
  for (BulletJoint& j : joints_) {
    const JointSettings& s = *j.settings;
    if (s.kind == JointKind::wheel && s.max_motor_torque > 0.0 && !j.motor_on && t >= s.motor_start_s) {
      j.constraint->enableMotor(5, true);
      j.motor_on = true;
    }
  }
  const btScalar h = sc(step_size(w.fps, w.substeps));
  for (int i = 0; i < w.substeps; ++i) {
    for (BulletJoint& j : joints_) {
      if (j.settings->kind == JointKind::distance) aim_distance(j);
    }
    world_.stepSimulation(h, 0);
  }
}

BodyState BulletWorld::body(std::size_t i) const {
  const btRigidBody& b = *bodies_[i];
  const btTransform& t = b.getCenterOfMassTransform();
  BodyState out;
  out.centre = {t.getOrigin().x(), t.getOrigin().y()};
  out.angle = plane_angle(t);
  out.origin = out.centre - Eigen::Rotation2Dd(out.angle) * local_centres_[i];
  if (!b.isStaticObject()) {
    out.velocity = {b.getLinearVelocity().x(), b.getLinearVelocity().y()};
    out.angular_velocity = b.getAngularVelocity().z();
  }
  return out;
}

std::vector<ContactSnapshot> BulletWorld::contacts() const {
  std::vector<ContactSnapshot> out;
  auto& dispatcher = const_cast<btCollisionDispatcher&>(dispatcher_);
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& cp = manifold->getContactPoint(p);
      if (cp.getDistance() > 0) continue;
      // Bullet's normal points from B to A (m_normalWorldOnB); the snapshot's from A to B.
      const btVector3 pt = cp.getPositionWorldOnB(), n = -cp.m_normalWorldOnB;
      out.push_back({{pt.x(), pt.y()}, Eigen::Vector2d(n.x(), n.y())});
    }
  }
  return out;
}

std::unique_ptr<SceneWorld> build_world(const SceneBuild& build, std::optional<FieldError>& error) {
  auto world = std::make_unique<BulletWorld>(build, error);
  if (!world->ok()) return nullptr;
  return world;
}

// The unit of a joint's stiffness and damping: the weld's spring is on the rotation.
bool angular(const Scene& scene, std::size_t joint) { return scene.joints[joint].kind == JointKind::weld; }

engines::Parameters fields(const Scene& scene, std::size_t joint, const JointSpring& s, const engines::SettingValues&) {
  const bool rot = angular(scene, joint);
  return {{engines::kBulletStiffness, static_cast<double>(sc(s.stiffness)), rot ? "N m/rad" : "N/m"},
          {engines::kBulletDamping, static_cast<double>(sc(s.damping)), rot ? "N m s/rad" : "N s/m"},
          {engines::kBulletStiffnessLimit, 0.0, "", engines::kBulletFalse},
          {engines::kBulletDampingLimit, 0.0, "", engines::kBulletFalse}};
}

std::optional<JointSpring> parse(const Scene&, std::size_t, const engines::Parameters& typed,
                                 const engines::SettingValues&, FieldError& error) {
  const std::optional<double> k = engines::parameter_value(typed, engines::kBulletStiffness);
  const std::optional<double> c = engines::parameter_value(typed, engines::kBulletDamping);
  if (!k || !c) {
    error = {std::string(k ? engines::kBulletDamping : engines::kBulletStiffness),
             "bullet needs this field: the joint's spring"};
    return std::nullopt;
  }
  if (!(*k > 0.0) || !(*c >= 0.0) || !std::isfinite(*k) || !std::isfinite(*c)) {
    error = {std::string(*k > 0.0 ? engines::kBulletDamping : engines::kBulletStiffness),
             "bullet's spring needs a finite stiffness > 0 and damping >= 0"};
    return std::nullopt;
  }
  for (const engines::Parameter& p : typed) {
    if ((p.name == engines::kBulletStiffnessLimit || p.name == engines::kBulletDampingLimit) &&
        p.choice != engines::kBulletFalse) {
      error = {std::string(p.name), "bullet scenes run limitIfNeeded false: with true Bullet replaces k by "
                                    "m / (16 h^2) or c by m / h where they are large"};
      return std::nullopt;
    }
  }
  return JointSpring{*k, *c};
}

}  // namespace

const SceneBackend kBulletSceneBackend = {"bullet", "Bullet 3.24 (float)", kSettings, build_world, fields, parse};

}  // namespace softtune::scene
