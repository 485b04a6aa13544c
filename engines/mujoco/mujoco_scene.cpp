#include "mujoco_scene.h"

#include <mujoco/mujoco.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <utility>

#include "softtune/designer.h"
#include "softtune/engines/mujoco.h"
#include "softtune/scene/scene_geometry.h"
#include "softtune/support/run_limit.h"
#include "softtune/support/xml_escape.h"

namespace softtune::engines {
namespace {

using scene::BodySettings;
using scene::JointKind;
using scene::JointSettings;
using scene::Scene;
using scene::SceneBuild;

constexpr double kHalfDepth = 0.5;  // m, half the depth of every prism across the plane (it does not matter)

constexpr std::array<std::string_view, 3> kIntegratorChoices = {"Euler", "RK4", "implicit"};
constexpr std::array<std::string_view, 3> kSolverChoices = {"PGS", "CG", "Newton"};
constexpr std::array<std::string_view, 2> kConeChoices = {"pyramidal", "elliptic"};
constexpr std::array<SettingSpec, kMujocoSceneSettingCount> kSettings = {{
    {"integrator", 0, 0, 2, true, kIntegratorChoices, "",
     "mjOption integrator: Euler (semi-implicit, joint damping implicit), RK4, implicit (passive and actuator "
     "velocity derivatives implicit)"},
    {"iterations", 100, 1, 1000, true, {}, "", "mjOption iterations: the constraint solver's maximum per step"},
    {"solver", 2, 0, 2, true, kSolverChoices, "", "mjOption solver: the constraint solver"},
    {"cone", 0, 0, 1, true, kConeChoices, "", "mjOption cone: the contacts' friction cone"},
    {"tolerance", 1e-8, 0, 1, false, {}, "", "mjOption tolerance: the solver stops when the cost improves less"},
}};

double setting(const SceneBuild& b, int i) {
  return static_cast<std::size_t>(i) < b.settings.size() ? b.settings[i] : kSettings[i].default_value;
}
std::string_view choice(const SceneBuild& b, int i) {
  return kSettings[i].choices[static_cast<std::size_t>(setting(b, i))];
}

int index_of(const Scene& s, const std::string& id) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (s.bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

Eigen::Vector2d rotate(const Eigen::Vector2d& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}
Eigen::Vector2d cross(double w, const Eigen::Vector2d& r) { return {-w * r.y(), w * r.x()}; }

// The kinematic tree: which scene joint nests which body in which (see the header).
struct Tree {
  std::vector<int> parent;       // per body: the parent body, -1 for the world
  std::vector<int> nested_by;    // per body: the scene joint that nests it, -1
  std::vector<std::string> hinge;  // per body: the name of its hinge joint, empty when it has none
};

bool is_ancestor(const Tree& t, int ancestor, int body) {
  for (int b = body; b >= 0; b = t.parent[b]) {
    if (b == ancestor) return true;
  }
  return false;
}

std::optional<FieldError> refuse(std::string field, std::string why) {
  return FieldError{std::move(field), "mujoco (MuJoCo 2.2.2): " + std::move(why)};
}

std::optional<FieldError> plan_tree(const SceneBuild& build, Tree& t) {
  const Scene& s = *build.scene;
  if (build.springs.size() != s.joints.size()) return refuse("joints", "the build has no spring slot for every joint");
  if (s.world.allow_sleeping) return refuse("world.allow_sleeping", "MuJoCo 2.2.2 has no sleeping bodies");
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (s.bodies[i].restitution != 0.0) {
      return refuse("bodies." + std::to_string(i) + ".restitution",
                    "MuJoCo has no restitution: its contacts are soft constraints (solref) that do not bounce "
                    "by a coefficient");
    }
  }
  t.parent.assign(s.bodies.size(), -1);
  t.nested_by.assign(s.bodies.size(), -1);
  t.hinge.assign(s.bodies.size(), "");
  for (std::size_t i = 0; i < s.joints.size(); ++i) {
    const JointSettings& j = s.joints[i];
    if (j.kind != JointKind::wheel && j.kind != JointKind::weld && j.kind != JointKind::revolute) continue;
    const int a = index_of(s, j.body_a), b = index_of(s, j.body_b);
    const BodySettings& body_b = s.bodies[b];
    std::string why;
    if (body_b.is_static) why = "body_b \"" + body_b.id + "\" is static";
    else if (t.nested_by[b] >= 0) why = "body_b \"" + body_b.id + "\" is already nested by joint " + s.joints[t.nested_by[b]].id;
    else if (is_ancestor(t, b, a)) why = "nesting body_b \"" + body_b.id + "\" in body_a would close a loop";
    else if (body_b.fixed_rotation && j.kind != JointKind::revolute) why = "body_b \"" + body_b.id + "\" has fixed_rotation, and nested in body_a it would turn with it";
    if (why.empty()) {
      t.parent[b] = a;
      t.nested_by[b] = static_cast<int>(i);
      const bool soft_weld = j.kind == JointKind::weld && build.springs[i];
      if (j.kind == JointKind::wheel && !body_b.fixed_rotation) t.hinge[b] = j.id + "/spin";
      if ((j.kind == JointKind::revolute && !body_b.fixed_rotation) || soft_weld) t.hinge[b] = j.id;
      if (j.kind == JointKind::revolute && body_b.fixed_rotation) {  // pinned but never turning: a connect
        t.parent[b] = -1;
        t.nested_by[b] = -1;
      }
    } else if (j.kind != JointKind::revolute) {
      return refuse("joints." + std::to_string(i) + ".body_b",
                    "a " + std::string(scene::joint_kind_name(j.kind)) +
                        " joint is built by nesting body_b in body_a (MuJoCo's kinematic tree), and " + why);
    }
  }
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    if (t.parent[b] < 0 && !s.bodies[b].is_static && !s.bodies[b].fixed_rotation) t.hinge[b] = s.bodies[b].id + "/rot";
  }
  return std::nullopt;
}

// Numbers written with 17 digits: the MJCF holds exactly the doubles the backend computed.
struct Xml {
  std::ostringstream s;
  Xml() { s.precision(17); }
  // A scene point or direction (x, y) as MuJoCo's (x, 0, y).
  std::string v3(const Eigen::Vector2d& p) {
    std::ostringstream o;
    o.precision(17);
    o << p.x() << " 0 " << p.y();
    return o.str();
  }
};

// The body frame's rotation about MuJoCo's -y by `angle` (the scene's counter-clockwise angle).
std::string quat_of(double angle) {
  std::ostringstream o;
  o.precision(17);
  o << std::cos(angle / 2) << " 0 " << -std::sin(angle / 2) << " 0";
  return o.str();
}

struct Site {
  std::string name;
  Eigen::Vector2d world;
};

// The velocity servo's gain: the wheel's inertia about its hinge over the step, so a free wheel reaches the
// motor speed in one step (a deadbeat servo, stable for any larger load: MuJoCo applies it explicitly).
double motor_gain(const Scene& s, const JointSettings& j, double h) {
  const BodySettings& b = s.bodies[index_of(s, j.body_b)];
  const scene::MassData md = scene::body_mass(b);
  const Eigen::Vector2d com = b.position + rotate(md.local_centre, b.angle);
  return (md.inertia + md.mass * (j.anchor_b - com).squaredNorm()) / h;
}

class Writer {
 public:
  Writer(const SceneBuild& b, const Tree& t) : b_(b), s_(*b.scene), t_(t), sites_(s_.bodies.size()) {}

  std::string mjcf() {
    for (std::size_t i = 0; i < s_.joints.size(); ++i) {
      const JointSettings& j = s_.joints[i];
      const int bb = index_of(s_, j.body_b);
      if (j.kind == JointKind::distance) {
        sites_[index_of(s_, j.body_a)].push_back({j.id + "/a", j.anchor_a});
        sites_[bb].push_back({j.id + "/b", j.anchor_b});
      } else if (j.kind == JointKind::mouse) {
        sites_[bb].push_back({j.id + "/b", j.anchor_b});
      }
    }
    std::ostringstream& o = x_.s;
    const double h = step_size(s_.world.fps, s_.world.substeps);
    o << "<mujoco model=\"" << support::xml_escape(s_.name) << "\">\n"
      << "  <option timestep=\"" << h << "\" gravity=\"" << x_.v3(s_.world.gravity) << "\" integrator=\""
      << choice(b_, kMujocoSceneIntegrator) << "\" iterations=\"" << setting(b_, kMujocoSceneIterations)
      << "\" solver=\"" << choice(b_, kMujocoSceneSolver) << "\" cone=\"" << choice(b_, kMujocoSceneCone)
      << "\" tolerance=\"" << setting(b_, kMujocoSceneTolerance) << "\">\n"
      << "    <flag filterparent=\"disable\"/>\n  </option>\n";
    meshes();
    o << "  <worldbody>\n";
    for (const JointSettings& j : s_.joints) {
      if (j.kind == JointKind::mouse) o << "    <site name=\"" << support::xml_escape(j.id) << "/target\" pos=\"" << x_.v3(j.target) << "\"/>\n";
    }
    for (std::size_t i = 0; i < s_.bodies.size(); ++i) {
      if (t_.parent[i] < 0) body(static_cast<int>(i), 2);
    }
    o << "  </worldbody>\n";
    tendons();
    equalities();
    actuators();
    contacts();
    o << "</mujoco>\n";
    return o.str();
  }

 private:
  void meshes() {
    std::ostringstream& o = x_.s;
    bool any = false;
    for (const BodySettings& body : s_.bodies) {
      if (body.shape.kind != scene::ShapeKind::polygon) continue;
      if (!any) o << "  <asset>\n";
      any = true;
      o << "    <mesh name=\"" << support::xml_escape(body.id) << "\" vertex=\"";
      for (const Eigen::Vector2d& v : body.shape.vertices) {
        o << v.x() << ' ' << -kHalfDepth << ' ' << v.y() << ' ' << v.x() << ' ' << kHalfDepth << ' ' << v.y() << ' ';
      }
      o << "\"/>\n";
    }
    if (any) o << "  </asset>\n";
  }

  void body(int i, int depth) {
    std::ostringstream& o = x_.s;
    const std::string in(static_cast<std::size_t>(depth) * 2, ' ');
    const BodySettings& body = s_.bodies[i];
    const int p = t_.parent[i];
    const Eigen::Vector2d parent_pos = p >= 0 ? s_.bodies[p].position : Eigen::Vector2d(0, 0);
    const double parent_angle = p >= 0 ? s_.bodies[p].angle : 0.0;
    const Eigen::Vector2d rel = rotate(body.position - parent_pos, -parent_angle);
    o << in << "<body name=\"" << support::xml_escape(body.id) << "\" pos=\"" << x_.v3(rel) << "\" quat=\""
      << quat_of(body.angle - parent_angle) << "\">\n";
    // A world direction or point in this body's frame at the start.
    auto local_dir = [&](const Eigen::Vector2d& d) { return rotate(d, -body.angle); };
    auto local_point = [&](const Eigen::Vector2d& w) { return rotate(w - body.position, -body.angle); };
    const std::string hinge_axis = "axis=\"0 -1 0\"";
    if (!body.is_static && p < 0 && t_.nested_by[i] < 0) {
      const std::string id = support::xml_escape(body.id);
      o << in << "  <joint name=\"" << id << "/x\" type=\"slide\" axis=\"" << x_.v3(local_dir({1, 0})) << "\"/>\n"
        << in << "  <joint name=\"" << id << "/z\" type=\"slide\" axis=\"" << x_.v3(local_dir({0, 1})) << "\"/>\n";
      if (!t_.hinge[i].empty()) o << in << "  <joint name=\"" << id << "/rot\" type=\"hinge\" " << hinge_axis << "/>\n";
    } else if (t_.nested_by[i] >= 0) {
      const std::size_t k = static_cast<std::size_t>(t_.nested_by[i]);
      const JointSettings& j = s_.joints[k];
      const std::optional<scene::JointSpring>& spring = b_.springs[k];
      std::ostringstream soft;
      soft.precision(17);
      if (spring) soft << " stiffness=\"" << spring->stiffness << "\" damping=\"" << spring->damping << '"';
      if (j.kind == JointKind::wheel) {
        o << in << "  <joint name=\"" << support::xml_escape(j.id) << "\" type=\"slide\" pos=\"" << x_.v3(local_point(j.anchor_b))
          << "\" axis=\"" << x_.v3(local_dir(j.axis.normalized())) << '"' << soft.str() << "/>\n";
        if (!t_.hinge[i].empty()) {
          o << in << "  <joint name=\"" << support::xml_escape(t_.hinge[i]) << "\" type=\"hinge\" pos=\""
            << x_.v3(local_point(j.anchor_b)) << "\" " << hinge_axis << "/>\n";
        }
      } else if (!t_.hinge[i].empty()) {  // revolute, soft weld: a hinge at the anchor
        o << in << "  <joint name=\"" << support::xml_escape(j.id) << "\" type=\"hinge\" pos=\"" << x_.v3(local_point(j.anchor_a))
          << "\" " << hinge_axis << soft.str() << "/>\n";
      }
    }
    if (!body.is_static) {
      const scene::MassData md = scene::body_mass(body);
      // The inertia about the plane normal is Box2D's; the other two axes never move (any positive value).
      const double inertia = md.inertia > 0.0 ? md.inertia : md.mass;
      o << in << "  <inertial pos=\"" << x_.v3(md.local_centre) << "\" mass=\"" << md.mass << "\" diaginertia=\""
        << inertia << ' ' << inertia << ' ' << inertia << "\"/>\n";
    }
    o << in << "  <geom name=\"" << support::xml_escape(body.id) << "\" ";
    switch (body.shape.kind) {
      case scene::ShapeKind::box:
        o << "type=\"box\" size=\"" << body.shape.width / 2 << ' ' << kHalfDepth << ' ' << body.shape.height / 2 << '"';
        break;
      case scene::ShapeKind::circle: o << "type=\"sphere\" size=\"" << body.shape.radius << '"'; break;
      case scene::ShapeKind::polygon: o << "type=\"mesh\" mesh=\"" << support::xml_escape(body.id) << '"'; break;
    }
    o << " friction=\"" << body.friction << " 0.005 0.0001\"/>\n";
    for (const Site& site : sites_[i]) {
      o << in << "  <site name=\"" << support::xml_escape(site.name) << "\" pos=\"" << x_.v3(local_point(site.world)) << "\"/>\n";
    }
    for (std::size_t c = 0; c < s_.bodies.size(); ++c) {
      if (t_.parent[c] == i) this->body(static_cast<int>(c), depth + 1);
    }
    o << in << "</body>\n";
  }

  void tendons() {
    std::ostringstream& o = x_.s;
    bool any = false;
    for (std::size_t i = 0; i < s_.joints.size(); ++i) {
      const JointSettings& j = s_.joints[i];
      if (j.kind != JointKind::distance && j.kind != JointKind::mouse) continue;
      if (!any) o << "  <tendon>\n";
      any = true;
      const std::string id = support::xml_escape(j.id);
      o << "    <spatial name=\"" << id << '"';
      if (j.kind == JointKind::distance && b_.springs[i]) {
        o << " stiffness=\"" << b_.springs[i]->stiffness << "\" damping=\"" << b_.springs[i]->damping
          << "\" springlength=\"" << j.length.value_or((j.anchor_b - j.anchor_a).norm()) << '"';
      }
      o << ">\n      <site site=\"" << id << (j.kind == JointKind::mouse ? "/target" : "/a") << "\"/>\n"
        << "      <site site=\"" << id << "/b\"/>\n    </spatial>\n";
    }
    if (any) o << "  </tendon>\n";
  }

  void equalities() {
    std::ostringstream& o = x_.s;
    std::ostringstream e;
    e.precision(17);
    for (std::size_t i = 0; i < s_.joints.size(); ++i) {
      const JointSettings& j = s_.joints[i];
      if (j.kind == JointKind::distance && !b_.springs[i]) {
        // A rigid rod: the tendon's length held at its rest length; polycoef[0] is the offset from the length
        // at the start (engine_core_constraint.c, mj_instantiateEquality, mjEQ_TENDON: L - L0 - data[0]).
        const double start = (j.anchor_b - j.anchor_a).norm();
        e << "    <tendon tendon1=\"" << support::xml_escape(j.id) << "\" polycoef=\"" << j.length.value_or(start) - start
          << " 0 0 0 0\"/>\n";
      } else if (j.kind == JointKind::revolute && t_.nested_by[index_of(s_, j.body_b)] != static_cast<int>(i)) {
        const BodySettings& a = s_.bodies[index_of(s_, j.body_a)];
        e << "    <connect body1=\"" << support::xml_escape(j.body_a) << "\" body2=\"" << support::xml_escape(j.body_b) << "\" anchor=\""
          << x_.v3(rotate(j.anchor_a - a.position, -a.angle)) << "\"/>\n";
      }
    }
    if (!e.str().empty()) o << "  <equality>\n" << e.str() << "  </equality>\n";
  }

  void actuators() {
    std::ostringstream& o = x_.s;
    std::ostringstream a;
    a.precision(17);
    const double h = step_size(s_.world.fps, s_.world.substeps);
    for (std::size_t i = 0; i < s_.joints.size(); ++i) {
      const JointSettings& j = s_.joints[i];
      const std::string id = support::xml_escape(j.id);
      if (j.kind == JointKind::wheel && j.max_motor_torque > 0.0 && !t_.hinge[index_of(s_, j.body_b)].empty()) {
        a << "    <velocity name=\"" << id << "/motor\" joint=\"" << id << "/spin\" kv=\""
          << motor_gain(s_, j, h) << "\" forcelimited=\"true\" forcerange=\"" << -j.max_motor_torque << ' '
          << j.max_motor_torque << "\"/>\n";
      } else if (j.kind == JointKind::mouse) {
        const scene::JointSpring spring = b_.springs[i].value_or(scene::JointSpring{});
        a << "    <general name=\"" << id << "\" tendon=\"" << id << "\" gainprm=\"0\" biastype=\"affine\" biasprm=\"0 "
          << -spring.stiffness + 0.0 << ' ' << -spring.damping + 0.0 << "\" forcelimited=\"true\" forcerange=\""
          << -j.max_force << ' ' << j.max_force << "\"/>\n";
      }
    }
    if (!a.str().empty()) o << "  <actuator>\n" << a.str() << "  </actuator>\n";
  }

  void contacts() {
    std::ostringstream& o = x_.s;
    std::ostringstream c;
    c.precision(17);
    std::set<std::pair<int, int>> excluded;
    for (const JointSettings& j : s_.joints) {
      if (j.kind == JointKind::mouse || j.collide_connected) continue;
      const int a = index_of(s_, j.body_a), b = index_of(s_, j.body_b);
      if (s_.bodies[a].is_static && s_.bodies[b].is_static) continue;
      if (excluded.insert({std::min(a, b), std::max(a, b)}).second) {
        c << "    <exclude body1=\"" << support::xml_escape(j.body_a) << "\" body2=\"" << support::xml_escape(j.body_b) << "\"/>\n";
      }
    }
    // Box2D's b2MixFriction, sqrt(fa fb), where MuJoCo's max(fa, fb) differs (fa != fb).
    for (std::size_t a = 0; a < s_.bodies.size(); ++a) {
      for (std::size_t b = a + 1; b < s_.bodies.size(); ++b) {
        const BodySettings &ba = s_.bodies[a], &bb = s_.bodies[b];
        if ((ba.is_static && bb.is_static) || ba.friction == bb.friction) continue;
        if (excluded.count({static_cast<int>(a), static_cast<int>(b)})) continue;
        const double f = std::sqrt(ba.friction * bb.friction);
        c << "    <pair geom1=\"" << support::xml_escape(ba.id) << "\" geom2=\"" << support::xml_escape(bb.id) << "\" friction=\"" << f << ' '
          << f << " 0.005 0.0001 0.0001\"/>\n";
      }
    }
    if (!c.str().empty()) o << "  <contact>\n" << c.str() << "  </contact>\n";
  }

 private:
  const SceneBuild& b_;
  const Scene& s_;
  const Tree& t_;
  std::vector<std::vector<Site>> sites_;
  Xml x_;
};

// MuJoCo prints warnings and writes MUJOCO_LOG.TXT by default; the world reads mjData's counters instead.
void quiet_warning(const char*) {}

class MujocoWorld final : public scene::SceneWorld {
 public:
  MujocoWorld(const SceneBuild& build, const Tree& tree, mjModel* m) : scene_(*build.scene), m_(m), d_(mj_makeData(m)) {
    const Scene& s = scene_;
    refs_.resize(s.bodies.size());
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
      Ref& r = refs_[i];
      r.id = mj_name2id(m_, mjOBJ_BODY, s.bodies[i].id.c_str());
      r.parent = tree.parent[i];
      if (!tree.hinge[i].empty()) {
        const int jid = mj_name2id(m_, mjOBJ_JOINT, tree.hinge[i].c_str());
        r.hinge_qpos = m_->jnt_qposadr[jid];
        r.hinge_dof = m_->jnt_dofadr[jid];
      }
    }
    const double h = step_size(s.world.fps, s.world.substeps);
    for (const JointSettings& j : s.joints) {
      if (j.kind != JointKind::wheel || j.max_motor_torque <= 0.0) continue;
      const int a = mj_name2id(m_, mjOBJ_ACTUATOR, (j.id + "/motor").c_str());
      if (a < 0) continue;
      motors_.push_back({a, motor_gain(s, j, h), j.motor_speed, j.motor_start_s});
      m_->actuator_gainprm[a * mjNGAIN] = 0.0;  // off until motor_start_s
      m_->actuator_biasprm[a * mjNBIAS + 2] = 0.0;
    }
    start_velocities(tree);
    mj_forward(m_, d_);
  }
  ~MujocoWorld() override {
    mj_deleteData(d_);
    mj_deleteModel(m_);
  }

  void step_frame(int frame) override {
    support::check_run_limit();
    const double t = frame / scene_.world.fps;
    for (Motor& motor : motors_) {
      if (motor.on || t < motor.start_s) continue;
      m_->actuator_gainprm[motor.actuator * mjNGAIN] = motor.kv;
      m_->actuator_biasprm[motor.actuator * mjNBIAS + 2] = -motor.kv;
      d_->ctrl[motor.actuator] = motor.speed;
      motor.on = true;
    }
    for (int i = 0; i < scene_.world.substeps; ++i) mj_step(m_, d_);
    // mj_checkPos / Vel / Acc reset the state on a bad number: that is a blow-up, not the start again.
    if (d_->warning[mjWARN_BADQACC].number || d_->warning[mjWARN_BADQVEL].number || d_->warning[mjWARN_BADQPOS].number) {
      diverged_ = true;
    }
    // mj_step leaves xpos, xipos and cvel at the step's start: bring them to its end.
    mj_kinematics(m_, d_);
    mj_comPos(m_, d_);
    mj_comVel(m_, d_);
  }

  scene::BodyState body(std::size_t i) const override {
    scene::BodyState st;
    if (diverged_ && !scene_.bodies[i].is_static) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      st.origin = st.centre = st.velocity = {nan, nan};
      st.angle = st.angular_velocity = nan;
      return st;
    }
    const int id = refs_[i].id;
    st.origin = {d_->xpos[3 * id], d_->xpos[3 * id + 2]};
    st.centre = {d_->xipos[3 * id], d_->xipos[3 * id + 2]};
    st.angle = angle(static_cast<int>(i));
    if (scene_.bodies[i].is_static) return st;
    st.angular_velocity = angular_velocity(static_cast<int>(i));
    mjtNum v[6];
    mj_objectVelocity(m_, d_, mjOBJ_BODY, id, v, 0);  // (rotation, linear) at the centre of mass, world axes
    st.velocity = {v[3], v[5]};
    return st;
  }

  std::vector<scene::ContactSnapshot> contacts() const override {
    std::vector<scene::ContactSnapshot> out;
    for (int i = 0; i < d_->ncon; ++i) {
      const mjContact& c = d_->contact[i];
      // frame[0..2]: the normal, from geom1 to geom2
      out.push_back({{c.pos[0], c.pos[2]}, {c.frame[0], c.frame[2]}});
    }
    return out;
  }

 private:
  struct Ref {
    int id = -1, parent = -1, hinge_qpos = -1, hinge_dof = -1;
  };
  struct Motor {
    int actuator = -1;
    double kv = 0.0, speed = 0.0, start_s = 0.0;
    bool on = false;
  };

  // Unwrapped, as Box2D's: the parent's angle, the start's relative angle and the hinge's turn.
  double angle(int i) const {
    const Ref& r = refs_[i];
    double a = scene_.bodies[i].angle;
    if (r.parent >= 0) a += angle(r.parent) - scene_.bodies[r.parent].angle;
    return a + (r.hinge_qpos >= 0 ? d_->qpos[r.hinge_qpos] : 0.0);
  }
  double angular_velocity(int i) const {
    const Ref& r = refs_[i];
    return (r.parent >= 0 ? angular_velocity(r.parent) : 0.0) + (r.hinge_dof >= 0 ? d_->qvel[r.hinge_dof] : 0.0);
  }

  // The bodies' starting linear (of the centre of mass) and angular velocities, in the joints' coordinates.
  void start_velocities(const Tree& tree) {
    const Scene& s = scene_;
    auto com_of = [&](std::size_t i) {
      return Eigen::Vector2d(s.bodies[i].position + rotate(scene::body_mass(s.bodies[i]).local_centre, s.bodies[i].angle));
    };
    auto point_velocity = [&](std::size_t i, const Eigen::Vector2d& p) -> Eigen::Vector2d {
      if (s.bodies[i].is_static) return {0, 0};
      return s.bodies[i].linear_velocity + cross(s.bodies[i].angular_velocity, p - com_of(i));
    };
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
      const BodySettings& b = s.bodies[i];
      if (b.is_static) continue;
      const int parent = tree.parent[i];
      const double parent_w = parent >= 0 && !s.bodies[parent].is_static ? s.bodies[parent].angular_velocity : 0.0;
      if (refs_[i].hinge_dof >= 0) d_->qvel[refs_[i].hinge_dof] = b.angular_velocity - parent_w;
      if (tree.nested_by[i] < 0) {  // a child of the world: slide x, slide z
        const Eigen::Vector2d v = point_velocity(i, b.position);
        const int x = mj_name2id(m_, mjOBJ_JOINT, (b.id + "/x").c_str());
        const int z = mj_name2id(m_, mjOBJ_JOINT, (b.id + "/z").c_str());
        d_->qvel[m_->jnt_dofadr[x]] = v.x();
        d_->qvel[m_->jnt_dofadr[z]] = v.y();
      } else {
        const JointSettings& j = s.joints[static_cast<std::size_t>(tree.nested_by[i])];
        if (j.kind == JointKind::wheel) {
          const Eigen::Vector2d rel = point_velocity(i, j.anchor_b) - point_velocity(static_cast<std::size_t>(parent), j.anchor_b);
          const int slide = mj_name2id(m_, mjOBJ_JOINT, j.id.c_str());
          d_->qvel[m_->jnt_dofadr[slide]] = rel.dot(j.axis.normalized());
        }
      }
    }
  }

  const Scene& scene_;
  mjModel* m_;
  mjData* d_;
  std::vector<Ref> refs_;
  std::vector<Motor> motors_;
  bool diverged_ = false;
};

mjModel* load_xml(const std::string& xml, std::string& error) {
  static const bool quiet = (mju_user_warning = quiet_warning, true);
  (void)quiet;
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* file = "scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), file, static_cast<int>(xml.size())) != 0) {
    error = "the MJCF does not fit MuJoCo's VFS";
    return nullptr;
  }
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), file)], xml.data(), xml.size());
  char message[1000] = "";
  mjModel* m = mj_loadXML(file, vfs.get(), message, sizeof(message));
  mj_deleteVFS(vfs.get());
  if (!m) error = message;
  return m;
}

// mj_Euler's step of a coordinate whose damping is implicit (a joint's dof_damping; under the implicit
// integrator every passive and actuator damping): (1 + h beta) v1 = v0 - h kappa r0, r1 = r0 + h v1.
Eigen::Matrix2d implicit_damping_step_map(double beta, double kappa, double h) {
  const double g = 1.0 / (1.0 + h * beta);
  Eigen::Matrix2d step;
  step << 1.0 - h * h * kappa * g, h * g, -h * kappa * g, g;
  return step;
}

// MuJoCo applies a spring explicitly (mj_passive, or the mouse's actuator bias): a stiffness whose step grows
// on the coordinate's inverse effective mass at the start (dof_invweight0 / tendon_invweight0, the exact
// J M^-1 J' engine_setconst.c computes at qpos0) is refused, as MuJoCo would blow up (stiff's 20 Hz at 60 fps).
std::optional<FieldError> check_springs(const SceneBuild& build, const mjModel* m) {
  const Scene& s = *build.scene;
  const double h = step_size(s.world.fps, s.world.substeps);
  const auto integrator = static_cast<MujocoIntegrator>(static_cast<int>(setting(build, kMujocoSceneIntegrator)));
  for (std::size_t i = 0; i < s.joints.size(); ++i) {
    const JointSettings& j = s.joints[i];
    if (!build.springs[i] || j.kind == JointKind::revolute) continue;
    const bool tendon = j.kind == JointKind::distance || j.kind == JointKind::mouse;
    double inverse_mass = 0.0;
    if (tendon) {
      inverse_mass = m->tendon_invweight0[mj_name2id(m, mjOBJ_TENDON, j.id.c_str())];
    } else {
      const int joint = mj_name2id(m, mjOBJ_JOINT, j.id.c_str());
      if (joint < 0) continue;  // a rigid weld: no joint
      inverse_mass = m->dof_invweight0[m->jnt_dofadr[joint]];
    }
    const double beta = build.springs[i]->damping * inverse_mass, kappa = build.springs[i]->stiffness * inverse_mass;
    const bool implicit_damping = integrator == MujocoIntegrator::implicit || (integrator == MujocoIntegrator::euler && !tendon);
    const Eigen::Matrix2d step = implicit_damping ? implicit_damping_step_map(beta, kappa, h) : mujoco_step_map(integrator, beta, kappa, h);
    if (!predict_from_step_map(step, h).stable) {
      return refuse("joints." + std::to_string(i),
                    "MuJoCo applies this spring explicitly (mj_passive): its stiffness and damping grow at the "
                    "scene's step on the joint's J M^-1 J' (omega h above 2), MuJoCo would blow up");
    }
  }
  return std::nullopt;
}

std::unique_ptr<scene::SceneWorld> build_world(const SceneBuild& build, std::optional<FieldError>& error) {
  Tree tree;
  if ((error = plan_tree(build, tree))) return nullptr;
  const std::string xml = Writer(build, tree).mjcf();
  std::string message;
  mjModel* m = load_xml(xml, message);
  if (!m) {
    error = refuse("bodies", "mj_loadXML refused the scene's MJCF: " + message);
    return nullptr;
  }
  if ((error = check_springs(build, m))) {
    mj_deleteModel(m);
    return nullptr;
  }
  return std::make_unique<MujocoWorld>(build, tree, m);
}

// The element's attributes each soft joint kind's spring is typed into (see the header).
struct FieldNames {
  std::string_view stiffness, damping, stiffness_unit, damping_unit;
  double sign = 1.0;  // the mouse's biasprm holds -k, -c
};

std::optional<FieldNames> field_names(JointKind kind) {
  switch (kind) {
    case JointKind::distance: return FieldNames{"tendon/spatial/@stiffness", "tendon/spatial/@damping", "N/m", "N s/m"};
    case JointKind::wheel: return FieldNames{"joint(slide)/@stiffness", "joint(slide)/@damping", "N/m", "N s/m"};
    case JointKind::weld: return FieldNames{"joint(hinge)/@stiffness", "joint(hinge)/@damping", "N m/rad", "N m s/rad"};
    case JointKind::mouse:
      return FieldNames{"actuator/general/@biasprm[1]", "actuator/general/@biasprm[2]", "N/m", "N s/m", -1.0};
    case JointKind::revolute: return std::nullopt;
  }
  return std::nullopt;
}

Parameters fields(const Scene& s, std::size_t joint, const scene::JointSpring& spring, const SettingValues&) {
  const JointSettings& j = s.joints[joint];
  const std::optional<FieldNames> n = field_names(j.kind);
  if (!n) return {};
  Parameters p = {{n->stiffness, n->sign * spring.stiffness + 0.0, n->stiffness_unit},
                  {n->damping, n->sign * spring.damping + 0.0, n->damping_unit}};
  if (j.kind == JointKind::distance) {
    p.push_back({"tendon/spatial/@springlength", j.length.value_or((j.anchor_b - j.anchor_a).norm()), "m"});
  }
  return p;
}

std::optional<scene::JointSpring> parse(const Scene& s, std::size_t joint, const Parameters& typed, const SettingValues&,
                                        FieldError& error) {
  const JointSettings& j = s.joints[joint];
  const std::optional<FieldNames> n = field_names(j.kind);
  if (!n) {
    error = {"joints." + std::to_string(joint) + ".type", "mujoco: a revolute joint is a rigid hinge: it has no spring"};
    return std::nullopt;
  }
  scene::JointSpring out;
  for (auto [name, target] : {std::pair{n->stiffness, &out.stiffness}, std::pair{n->damping, &out.damping}}) {
    const std::optional<double> v = parameter_value(typed, name);
    if (!v) {
      error = {std::string(name), "mujoco: missing; a " + std::string(scene::joint_kind_name(j.kind)) +
                                      " joint's spring is typed as " + std::string(n->stiffness) + " and " +
                                      std::string(n->damping)};
      return std::nullopt;
    }
    if (!std::isfinite(*v) || n->sign * *v < 0.0) {
      error = {std::string(name), n->sign > 0 ? "mujoco: must be a finite number >= 0" : "mujoco: must be a finite number <= 0 (-k, -c)"};
      return std::nullopt;
    }
    *target = n->sign * *v + 0.0;
  }
  return out;
}

}  // namespace

std::string mujoco_scene_mjcf(const SceneBuild& build, std::optional<FieldError>& error) {
  Tree tree;
  if ((error = plan_tree(build, tree))) return {};
  return Writer(build, tree).mjcf();
}

const scene::SceneBackend kMujocoSceneBackend = {"mujoco", "MuJoCo 2.2.2", kSettings, build_world, fields, parse};

}  // namespace softtune::engines
