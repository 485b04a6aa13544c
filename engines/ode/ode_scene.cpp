#include "ode_scene.h"

#include <ode/ode.h>

#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "ode_global.h"
#include "softtune/designer.h"
#include "softtune/scene/scene_geometry.h"
#include "softtune/support/run_limit.h"

namespace softtune::scene {
namespace {

constexpr std::array<std::string_view, 2> kStepperChoices = {"dWorldStep", "dWorldQuickStep"};
constexpr std::size_t kStepper = 0, kIterations = 1, kSorW = 2, kErp = 3, kCfm = 4;
// ODE's own defaults (objects.cpp dxWorld::dxWorld, dxQuickStepParameters); the stepper as the 1-D model's.
constexpr std::array<engines::SettingSpec, 5> kSettings = {{
    {"stepper", 0, 0, 1, true, kStepperChoices, "",
     "dWorldStep solves the rows exactly; dWorldQuickStep runs SOR sweeps"},
    {"dWorldSetQuickStepNumIterations", 20, 1, 10000, true, {}, "", "dWorldQuickStep's SOR sweeps per step"},
    {"dWorldSetQuickStepW", 1.3, 0.01, 1.99, false, {}, "", "dWorldQuickStep's over-relaxation"},
    {"dWorldSetERP", 0.2, 0, 1, false, {}, "", "the global ERP: contacts' and rigid joints' error reduction per step"},
    {"dWorldSetCFM", 1e-10, 0, 1, false, {}, "", "the global CFM: contacts' and rigid joints' softness"},
}};

constexpr double kUncappedMouseForce = 1.0e9;  // JointSettings::max_force's default: Box2D's unbounded pull
constexpr double kDepth = 1.0;
constexpr int kMaxContacts = 8;

constexpr std::string_view kErpName = "dParamERP", kCfmName = "dParamCFM";
constexpr std::string_view kStopErpName = "dParamStopERP", kStopCfmName = "dParamStopCFM";
constexpr std::string_view kSuspensionErpName = "dParamSuspensionERP", kSuspensionCfmName = "dParamSuspensionCFM";

int body_index(const Scene& scene, const std::string& id) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

// The joint's spring as ODE's ERP and CFM at step h (ode.cpp's implicit Euler: ERP = h k / (h k + c),
// CFM = 1 / (h k + c)) and back.
std::pair<double, double> erp_cfm(const JointSpring& s, double h) {
  const double d = h * s.stiffness + s.damping;
  return {h * s.stiffness / d, 1.0 / d};
}
JointSpring spring_of(double erp, double cfm, double h) { return {erp / (h * cfm), (1.0 - erp) / cfm}; }

double scene_step(const Scene& s) { return step_size(s.world.fps, s.world.substeps); }

class OdeWorld final : public SceneWorld {
 public:
  explicit OdeWorld(const SceneBuild& build);
  ~OdeWorld() override;
  bool build(const SceneBuild& build, std::optional<FieldError>& error);
  void step_frame(int frame) override;
  BodyState body(std::size_t i) const override;
  std::vector<ContactSnapshot> contacts() const override { return contacts_; }

 private:
  static void near_callback(void* data, dGeomID a, dGeomID b);
  void collide(dGeomID a, dGeomID b);
  bool add_joint(std::size_t i, const std::optional<JointSpring>& s, std::optional<FieldError>& error);
  void keep_planar(dBodyID b);

  const Scene& scene_;
  engines::SettingValues settings_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contact_group_ = nullptr;
  std::vector<dBodyID> bodies_;   // null for static bodies
  std::vector<dBodyID> anchors_;  // what joints attach to: the body, or a static body's kinematic stand-in
  std::vector<dGeomID> geoms_;
  std::vector<Eigen::Vector2d> local_centres_;
  std::vector<std::pair<std::size_t, std::size_t>> no_collide_;  // scene body indices of jointed pairs
  std::vector<std::pair<std::size_t, dJointID>> motors_;  // wheel joints with a motor: scene index, hinge-2
  std::vector<bool> motor_on_;
  std::vector<ContactSnapshot> contacts_;
};

OdeWorld::OdeWorld(const SceneBuild& build) : scene_(*build.scene), settings_(build.settings) {
  for (std::size_t i = settings_.size(); i < kSettings.size(); ++i) settings_.push_back(kSettings[i].default_value);
}

bool OdeWorld::build(const SceneBuild& build, std::optional<FieldError>& error) {
  // Refusals first: nothing is created for a scene ODE cannot build.
  for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
    if (scene_.bodies[i].shape.kind == ShapeKind::polygon) {
      error = FieldError{"bodies." + std::to_string(i) + ".shape.type",
                         "ode: a dCreateConvex prism touches a box at one contact point at a time, so a "
                         "polygon rocks and slides where Box2D's rests (measured: a triangle dropped on the "
                         "ground creeps at 1 cm/s); softtune's ode backend refuses polygons"};
      return false;
    }
  }
  world_ = dWorldCreate();
  space_ = dSimpleSpaceCreate(nullptr);
  contact_group_ = dJointGroupCreate(0);
  dWorldSetGravity(world_, scene_.world.gravity.x(), scene_.world.gravity.y(), 0);
  dWorldSetQuickStepNumIterations(world_, static_cast<int>(settings_[kIterations]));
  dWorldSetQuickStepW(world_, settings_[kSorW]);
  dWorldSetERP(world_, settings_[kErp]);
  dWorldSetCFM(world_, settings_[kCfm]);
  dWorldSetAutoDisableFlag(world_, scene_.world.allow_sleeping ? 1 : 0);

  for (const BodySettings& s : scene_.bodies) {
    const MassData md = body_mass(s);
    dGeomID g = s.shape.kind == ShapeKind::circle ? dCreateSphere(space_, s.shape.radius)
                                                  : dCreateBox(space_, s.shape.width, s.shape.height, kDepth);
    dMatrix3 r;
    dRFromAxisAndAngle(r, 0, 0, 1, s.angle);
    const Eigen::Vector2d centre = s.position + Eigen::Rotation2Dd(s.angle) * md.local_centre;
    dBodyID b = nullptr;
    if (s.is_static) {
      dGeomSetPosition(g, s.position.x(), s.position.y(), 0);
      dGeomSetRotation(g, r);
      // Joints attach to a kinematic body at the static body's pose (infinite mass, never moving): attached
      // to no body, ODE reverses a joint (dJOINT_REVERSE) and a PR joint's prismatic axis would be fixed in
      // the wheel instead (pr.cpp, dxJointPR::getInfo2 reads node[0]'s frame).
      dBodyID k = dBodyCreate(world_);
      dBodySetKinematic(k);
      dBodySetPosition(k, centre.x(), centre.y(), 0);
      dBodySetRotation(k, r);
      anchors_.push_back(k);
    } else {
      b = dBodyCreate(world_);
      dMass m;
      const double inertia = s.fixed_rotation ? md.mass : md.inertia;  // any positive value when the motor holds it
      dMassSetParameters(&m, md.mass, 0, 0, 0, inertia, inertia, inertia, 0, 0, 0);
      dBodySetMass(b, &m);
      dBodySetPosition(b, centre.x(), centre.y(), 0);
      dBodySetRotation(b, r);
      dBodySetLinearVel(b, s.linear_velocity.x(), s.linear_velocity.y(), 0);
      dBodySetAngularVel(b, 0, 0, s.fixed_rotation ? 0.0 : s.angular_velocity);
      dGeomSetBody(g, b);
      dGeomSetOffsetPosition(g, -md.local_centre.x(), -md.local_centre.y(), 0);
      dJointID plane = dJointCreatePlane2D(world_, nullptr);
      dJointAttach(plane, b, nullptr);
      if (s.fixed_rotation) {
        dJointSetPlane2DAngleParam(plane, dParamVel, 0);
        dJointSetPlane2DAngleParam(plane, dParamFMax, dInfinity);
      }
    }
    dGeomSetData(g, reinterpret_cast<void*>(bodies_.size()));
    if (!s.is_static) anchors_.push_back(b);
    bodies_.push_back(b);
    geoms_.push_back(g);
    local_centres_.push_back(md.local_centre);
  }
  for (std::size_t i = 0; i < scene_.joints.size(); ++i) {
    std::optional<JointSpring> s;
    if (i < build.springs.size()) s = build.springs[i];
    if (!add_joint(i, s, error)) return false;
  }
  motor_on_.assign(motors_.size(), false);
  return true;
}

bool OdeWorld::add_joint(std::size_t i, const std::optional<JointSpring>& s, std::optional<FieldError>& error) {
  const JointSettings& j = scene_.joints[i];
  const std::string field = "joints." + std::to_string(i);
  const int ia = j.kind == JointKind::mouse ? -1 : body_index(scene_, j.body_a);
  dBodyID a = ia >= 0 ? anchors_[static_cast<std::size_t>(ia)] : nullptr;
  dBodyID b = anchors_[static_cast<std::size_t>(body_index(scene_, j.body_b))];
  const double h = scene_step(scene_);
  std::optional<std::pair<double, double>> soft;
  if (s) soft = erp_cfm(*s, h);
  dJointID joint = nullptr;
  switch (j.kind) {
    case JointKind::revolute:
      joint = dJointCreateHinge(world_, nullptr);
      dJointAttach(joint, a, b);
      dJointSetHingeAnchor(joint, j.anchor_a.x(), j.anchor_a.y(), 0);
      dJointSetHingeAxis(joint, 0, 0, 1);
      break;
    case JointKind::weld:
      if (!soft) {
        joint = dJointCreateFixed(world_, nullptr);
        dJointAttach(joint, a, b);
        dJointSetFixed(joint);
        break;
      }
      joint = dJointCreateHinge(world_, nullptr);
      dJointAttach(joint, a, b);
      dJointSetHingeAnchor(joint, j.anchor_a.x(), j.anchor_a.y(), 0);
      dJointSetHingeAxis(joint, 0, 0, 1);  // the hinge angle is 0 at the start: the weld's reference angle
      dJointSetHingeParam(joint, dParamLoStop, 0);
      dJointSetHingeParam(joint, dParamHiStop, 0);
      dJointSetHingeParam(joint, dParamStopERP, soft->first);
      dJointSetHingeParam(joint, dParamStopCFM, soft->second);
      break;
    case JointKind::wheel: {
      // ODE's car wheel (ode/demo/demo_buggy.cpp): a hinge-2 whose axis 1, fixed in body A, is the
      // suspension (a soft row along it: dParamSuspensionERP / dParamSuspensionCFM) and whose axis 2, fixed in
      // the wheel, its free spin with the motor (dParamVel2 / dParamFMax2). Steering about axis 1 is held by
      // lo = hi = 0 stops (the Plane2D joints hold it too).
      const Eigen::Vector2d axis = j.axis.normalized();
      joint = dJointCreateHinge2(world_, nullptr);
      dJointAttach(joint, a, b);
      dJointSetHinge2Anchor(joint, j.anchor_b.x(), j.anchor_b.y(), 0);
      const dReal axis1[3] = {axis.x(), axis.y(), 0}, axis2[3] = {0, 0, 1};
      dJointSetHinge2Axes(joint, axis1, axis2);
      dJointSetHinge2Param(joint, dParamLoStop, 0);
      dJointSetHinge2Param(joint, dParamHiStop, 0);
      if (soft) {
        dJointSetHinge2Param(joint, dParamSuspensionERP, soft->first);
        dJointSetHinge2Param(joint, dParamSuspensionCFM, soft->second);
      } else {
        dJointSetHinge2Param(joint, dParamSuspensionERP, settings_[kErp]);  // rigid: the world's
        dJointSetHinge2Param(joint, dParamSuspensionCFM, settings_[kCfm]);
      }
      if (j.max_motor_torque > 0.0) motors_.emplace_back(i, joint);
      break;
    }
    case JointKind::distance:
      joint = dJointCreateDBall(world_, nullptr);
      dJointAttach(joint, a, b);
      dJointSetDBallAnchor1(joint, j.anchor_a.x(), j.anchor_a.y(), 0);
      dJointSetDBallAnchor2(joint, j.anchor_b.x(), j.anchor_b.y(), 0);
      dJointSetDBallDistance(joint, j.length.value_or((j.anchor_b - j.anchor_a).norm()));
      if (soft) {
        dJointSetDBallParam(joint, dParamERP, soft->first);
        dJointSetDBallParam(joint, dParamCFM, soft->second);
      }
      break;
    case JointKind::mouse:
      if (j.max_force < kUncappedMouseForce) {
        error = FieldError{field + ".max_force", "ode has no force cap on a ball joint's rows: a mouse joint's "
                                                 "max_force must be at least 1e9 (uncapped)"};
        return false;
      }
      if (!soft) {
        error = FieldError{field + ".type", "ode builds a mouse joint as a soft ball joint: it needs a tuning or "
                                            "typed values"};
        return false;
      }
      joint = dJointCreateBall(world_, nullptr);
      dJointAttach(joint, b, nullptr);
      dJointSetBallAnchor(joint, j.anchor_b.x(), j.anchor_b.y(), 0);
      dJointSetBallAnchor2(joint, j.target.x(), j.target.y(), 0);
      dJointSetBallParam(joint, dParamERP, soft->first);
      dJointSetBallParam(joint, dParamCFM, soft->second);
      break;
  }
  if (!j.collide_connected && ia >= 0) {
    no_collide_.emplace_back(static_cast<std::size_t>(ia), static_cast<std::size_t>(body_index(scene_, j.body_b)));
  }
  return true;
}

OdeWorld::~OdeWorld() {
  const std::lock_guard lock(engines::ode_global_mutex());
  if (contact_group_) dJointGroupDestroy(contact_group_);
  if (space_) dSpaceDestroy(space_);  // destroys its geoms
  if (world_) dWorldDestroy(world_);  // destroys its bodies and joints
}

void OdeWorld::near_callback(void* data, dGeomID a, dGeomID b) { static_cast<OdeWorld*>(data)->collide(a, b); }

void OdeWorld::collide(dGeomID ga, dGeomID gb) {
  dBodyID a = dGeomGetBody(ga), b = dGeomGetBody(gb);
  if (!a && !b) return;
  const auto ia = reinterpret_cast<std::size_t>(dGeomGetData(ga)), ib = reinterpret_cast<std::size_t>(dGeomGetData(gb));
  for (const auto& [x, y] : no_collide_) {
    if ((x == ia && y == ib) || (x == ib && y == ia)) return;
  }
  std::array<dContact, kMaxContacts> cs{};
  const int n = dCollide(ga, gb, kMaxContacts, &cs[0].geom, sizeof(dContact));
  if (n <= 0) return;
  const BodySettings& sa = scene_.bodies[ia];
  const BodySettings& sb = scene_.bodies[ib];
  const double bounce = std::max(sa.restitution, sb.restitution);
  std::vector<Eigen::Vector2d> taken;
  for (int k = 0; k < n; ++k) {
    dContact& c = cs[static_cast<std::size_t>(k)];
    // A prism's face contact comes as pairs of points at z = +-depth/2 with the same (x, y): one point per
    // (x, y), moved onto the plane, as Box2D's manifold has. The twin rows would be redundant (the Plane2D
    // joints hold the tilt they resist) and leave dWorldStep's LCP singular ("LCP internal error, s <= 0").
    const Eigen::Vector2d at(c.geom.pos[0], c.geom.pos[1]);
    bool twin = false;
    for (const Eigen::Vector2d& p : taken) twin = twin || (p - at).norm() < 1e-6;
    if (twin) continue;
    taken.push_back(at);
    c.geom.pos[2] = 0;
    c.surface.mode = dContactApprox1 | (bounce > 0.0 ? dContactBounce : 0);
    c.surface.mu = std::sqrt(sa.friction * sb.friction);
    c.surface.bounce = bounce;
    c.surface.bounce_vel = 0.0;
    dJointID joint = dJointCreateContact(world_, contact_group_, &c);
    dJointAttach(joint, a, b);
    // ODE's normal points into the first geom (from gb to ga); the snapshot's from A to B.
    contacts_.push_back({{c.geom.pos[0], c.geom.pos[1]}, Eigen::Vector2d(-c.geom.normal[0], -c.geom.normal[1])});
  }
}

// ode/demo/demo_plane2d.cpp: the Plane2D joint holds velocities only, so the rotation is reset to its z
// part and the angular velocity to its z component after each step.
void OdeWorld::keep_planar(dBodyID b) {
  const dReal* q = dBodyGetQuaternion(b);
  const double norm = std::hypot(q[0], q[3]);
  const dQuaternion planar = {q[0] / norm, 0, 0, q[3] / norm};
  dBodySetQuaternion(b, planar);
  const dReal* w = dBodyGetAngularVel(b);
  dBodySetAngularVel(b, 0, 0, w[2]);
}

void OdeWorld::step_frame(int frame) {
  support::check_run_limit();
  const std::lock_guard lock(engines::ode_global_mutex());
  engines::init_ode_for_this_thread();
  const double t = frame / scene_.world.fps;
  for (std::size_t m = 0; m < motors_.size(); ++m) {
    const JointSettings& j = scene_.joints[motors_[m].first];
    if (!motor_on_[m] && t >= j.motor_start_s) {
      // The spin's rate is body 1's rotation less body 2's (as dJointGetHinge2Angle2Rate reads it): Box2D's
      // motor speed of B relative to A is typed with the other sign.
      dJointSetHinge2Param(motors_[m].second, dParamVel2, -j.motor_speed);
      dJointSetHinge2Param(motors_[m].second, dParamFMax2, j.max_motor_torque);
      motor_on_[m] = true;
    }
  }
  const double h = scene_step(scene_);
  const bool quick = settings_[kStepper] != 0.0;
  for (int s = 0; s < scene_.world.substeps; ++s) {
    contacts_.clear();
    dSpaceCollide(space_, this, &OdeWorld::near_callback);
    if (quick) dWorldQuickStep(world_, h); else dWorldStep(world_, h);
    dJointGroupEmpty(contact_group_);
    for (dBodyID b : bodies_) {
      if (b) keep_planar(b);
    }
  }
}

BodyState OdeWorld::body(std::size_t i) const {
  BodyState out;
  const BodySettings& s = scene_.bodies[i];
  if (!bodies_[i]) {
    out.origin = s.position;
    out.angle = s.angle;
    out.centre = s.position + Eigen::Rotation2Dd(s.angle) * local_centres_[i];
    return out;
  }
  dBodyID b = bodies_[i];
  const dReal* p = dBodyGetPosition(b);
  const dReal* r = dBodyGetRotation(b);  // 3x4, row major
  const dReal* v = dBodyGetLinearVel(b);
  out.centre = {p[0], p[1]};
  out.angle = std::atan2(r[4], r[0]);
  out.origin = out.centre - Eigen::Rotation2Dd(out.angle) * local_centres_[i];
  out.velocity = {v[0], v[1]};
  out.angular_velocity = dBodyGetAngularVel(b)[2];
  return out;
}

std::unique_ptr<SceneWorld> build_world(const SceneBuild& build, std::optional<FieldError>& error) {
  auto world = std::make_unique<OdeWorld>(build);
  bool ok = false;
  {
    const std::lock_guard lock(engines::ode_global_mutex());
    engines::init_ode_for_this_thread();
    ok = world->build(build, error);
  }
  if (!ok) return nullptr;  // ~OdeWorld takes the lock itself
  return world;
}

// The names a joint's row ERP and CFM are typed under: the hinge-2's suspension (wheel), the hinge's stops
// (soft weld), the joint's own (dball, ball).
std::pair<std::string_view, std::string_view> row_names(const Scene& scene, std::size_t joint) {
  switch (scene.joints[joint].kind) {
    case JointKind::wheel: return {kSuspensionErpName, kSuspensionCfmName};
    case JointKind::weld: return {kStopErpName, kStopCfmName};
    default: return {kErpName, kCfmName};
  }
}

engines::Parameters fields(const Scene& scene, std::size_t joint, const JointSpring& s, const engines::SettingValues&) {
  const auto [erp, cfm] = erp_cfm(s, scene_step(scene));
  const auto [erp_name, cfm_name] = row_names(scene, joint);
  const bool rot = scene.joints[joint].kind == JointKind::weld;
  return {{erp_name, erp, ""}, {cfm_name, cfm, rot ? "rad/(N m s)" : "m/(N s)"}};
}

std::optional<JointSpring> parse(const Scene& scene, std::size_t joint, const engines::Parameters& typed,
                                 const engines::SettingValues&, FieldError& error) {
  const auto [erp_name, cfm_name] = row_names(scene, joint);
  const std::optional<double> erp = engines::parameter_value(typed, erp_name);
  const std::optional<double> cfm = engines::parameter_value(typed, cfm_name);
  if (!erp || !cfm) {
    error = {std::string(erp ? cfm_name : erp_name), "ode needs this field: the joint's row ERP and CFM"};
    return std::nullopt;
  }
  if (!(*erp > 0.0) || !std::isfinite(*erp)) {
    error = {std::string(erp_name), "ode's spring needs ERP > 0 (ERP = h k / (h k + c))"};
    return std::nullopt;
  }
  if (!(*cfm > 0.0) || !std::isfinite(*cfm)) {
    error = {std::string(cfm_name), "ode's spring needs CFM > 0 (CFM = 1 / (h k + c))"};
    return std::nullopt;
  }
  return spring_of(*erp, *cfm, scene_step(scene));
}

}  // namespace

const SceneBackend kOdeSceneBackend = {"ode", "ODE " dODE_VERSION, kSettings, build_world, fields, parse};

}  // namespace softtune::scene
