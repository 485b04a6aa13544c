#include "node_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "softtune/scene/scene_geometry.h"
#include "softtune/support/run_limit.h"

namespace softtune::node_worker {
namespace {

using nlohmann::json;
using scene::BodyState;

json vec(const Eigen::Vector2d& v) { return json::array({v.x(), v.y()}); }

int index_of(const scene::Scene& s, const std::string& id) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (s.bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

json shape_json(const scene::ShapeSettings& shape) {
  switch (shape.kind) {
    case scene::ShapeKind::box: return {{"type", "box"}, {"width", shape.width}, {"height", shape.height}};
    case scene::ShapeKind::circle: return {{"type", "circle"}, {"radius", shape.radius}};
    case scene::ShapeKind::polygon: {
      json vertices = json::array();
      for (const Eigen::Vector2d& v : shape.vertices) vertices.push_back(vec(v));
      return {{"type", "polygon"}, {"vertices", vertices}};
    }
  }
  return {};
}

double number(const json& v) {
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();  // null: not finite
}

BodyState state_of(const json& row) {
  if (!row.is_array() || row.size() != 8) throw WorkerError("node worker: a body state is not 8 numbers");
  BodyState s;
  s.origin = {number(row[0]), number(row[1])};
  s.centre = {number(row[2]), number(row[3])};
  s.angle = number(row[4]);
  s.velocity = {number(row[5]), number(row[6])};
  s.angular_velocity = number(row[7]);
  return s;
}

// What a body is before the first step: its pose and velocity as the scene gives them.
BodyState initial_state(const scene::BodySettings& b) {
  const scene::MassData m = scene::body_mass(b);
  const Eigen::Rotation2Dd r(b.angle);
  BodyState s;
  s.origin = b.position;
  s.centre = b.position + r * m.local_centre;
  s.angle = b.angle;
  if (!b.is_static) {
    s.velocity = b.linear_velocity;
    s.angular_velocity = b.angular_velocity;
  }
  return s;
}

WorkerError answer_error(std::string_view engine, const json& answer) {
  return WorkerError(std::string(engine) + ": " + answer.value("message", std::string("the worker answered ") + answer.dump()));
}

class NodeSceneWorld final : public scene::SceneWorld {
 public:
  NodeSceneWorld(NodeWorker& worker, std::string_view engine, int id, int generation, const scene::Scene& s,
                 bool contacts)
      : worker_(worker), engine_(engine), id_(id), generation_(generation), contacts_(contacts),
        frames_(scene::frame_count(s.world)) {
    for (const scene::BodySettings& b : s.bodies) states_.push_back(initial_state(b));
  }
  ~NodeSceneWorld() override {
    try {
      worker_.call({{"op", "destroy"}, {"world", id_}}, generation_);
    } catch (const WorkerError&) {
      // the worker is gone, and the world with it
    }
  }

  // A run that reads no contacts steps ahead: one `run` round trip for up to kStepAhead frames (the states
  // after each), served frame by frame. A round trip with 16 bodies costs about 4x the stepping of a frame of
  // Rapier's vehicle, so frame-by-frame calls were most of a run. A run that reads contacts steps one frame per
  // call, so contacts() is always of the frame just stepped.
  void step_frame(int frame) override {
    support::check_run_limit();
    if (!contacts_ && ahead_.is_array() && next_ < ahead_.size() && frame == ahead_frame_ + static_cast<int>(next_)) {
      read_states(ahead_[next_++]);
      return;
    }
    const int remaining = std::max(1, frames_ - frame);
    if (contacts_ || remaining == 1) {
      const json answer = worker_.call({{"op", "step"}, {"world", id_}, {"frame", frame}}, generation_);
      if (!answer.contains("bodies")) throw answer_error(engine_, answer);
      read_states(answer["bodies"]);
      return;
    }
    const int count = std::min(kStepAhead, remaining);
    json answer = worker_.call({{"op", "run"}, {"world", id_}, {"frame", frame}, {"frames", count}}, generation_);
    if (!answer.contains("frames") || !answer["frames"].is_array() || answer["frames"].size() != static_cast<std::size_t>(count)) {
      throw answer_error(engine_, answer);
    }
    ahead_ = std::move(answer["frames"]);
    ahead_frame_ = frame;
    next_ = 0;
    read_states(ahead_[next_++]);
  }

  BodyState body(std::size_t i) const override { return states_.at(i); }

  std::vector<scene::ContactSnapshot> contacts() const override {
    const json answer = worker_.call({{"op", "contacts"}, {"world", id_}}, generation_);
    if (!answer.contains("contacts") || !answer["contacts"].is_array()) throw answer_error(engine_, answer);
    std::vector<scene::ContactSnapshot> out;
    for (const json& c : answer["contacts"]) {
      if (!c.is_array() || c.size() != 4) throw WorkerError("node worker: a contact is not 4 numbers");
      scene::ContactSnapshot snap;
      snap.point = {number(c[0]), number(c[1])};
      snap.normal = {number(c[2]), number(c[3])};
      out.push_back(snap);
    }
    return out;
  }

 private:
  static constexpr int kStepAhead = 30;  // frames per `run` round trip: half a second at 60 fps

  void read_states(const json& rows) {
    if (!rows.is_array() || rows.size() != states_.size()) throw answer_error(engine_, rows);
    for (std::size_t i = 0; i < states_.size(); ++i) states_[i] = state_of(rows[i]);
  }

  NodeWorker& worker_;
  std::string_view engine_;
  int id_;
  int generation_;
  bool contacts_;
  int frames_;           // the scene's frames: no step ahead past its end
  json ahead_;           // states after frames ahead_frame_, ahead_frame_ + 1, ... (a `run` answer)
  int ahead_frame_ = 0;
  std::size_t next_ = 0; // into ahead_
  std::vector<BodyState> states_;
};

}  // namespace

json build_request(std::string_view engine, std::span<const engines::SettingSpec> specs, const scene::SceneBuild& build) {
  const scene::Scene& s = *build.scene;
  json settings = json::object();
  for (std::size_t i = 0; i < specs.size() && i < build.settings.size(); ++i) {
    settings[std::string(specs[i].name)] = build.settings[i];
  }
  json bodies = json::array();
  for (const scene::BodySettings& b : s.bodies) {
    const scene::MassData m = scene::body_mass(b);
    bodies.push_back({{"id", b.id},
                      {"static", b.is_static},
                      {"shape", shape_json(b.shape)},
                      {"position", vec(b.position)},
                      {"angle", b.angle},
                      {"linear_velocity", vec(b.linear_velocity)},
                      {"angular_velocity", b.angular_velocity},
                      {"friction", b.friction},
                      {"restitution", b.restitution},
                      {"fixed_rotation", b.fixed_rotation},
                      {"mass", m.mass},
                      {"inertia", m.inertia},
                      {"local_centre", vec(m.local_centre)}});
  }
  json joints = json::array();
  for (std::size_t i = 0; i < s.joints.size(); ++i) {
    const scene::JointSettings& j = s.joints[i];
    Eigen::Vector2d anchor_a = j.anchor_a, anchor_b = j.anchor_b;
    // Box2D 2.4's Initialize(bodyA, bodyB, anchor...) of each def (box2d_scene.cpp create_joint).
    if (j.kind == scene::JointKind::wheel) anchor_a = j.anchor_b;
    if (j.kind == scene::JointKind::weld || j.kind == scene::JointKind::revolute) anchor_b = j.anchor_a;
    json spring = nullptr;
    if (i < build.springs.size() && build.springs[i]) {
      spring = {{"stiffness", build.springs[i]->stiffness}, {"damping", build.springs[i]->damping}};
    }
    joints.push_back({{"id", j.id},
                      {"type", std::string(scene::joint_kind_name(j.kind))},
                      {"body_a", j.kind == scene::JointKind::mouse ? -1 : index_of(s, j.body_a)},
                      {"body_b", index_of(s, j.body_b)},
                      {"anchor_a", vec(anchor_a)},
                      {"anchor_b", vec(anchor_b)},
                      {"axis", vec(j.axis.normalized())},
                      {"length", j.length.value_or((j.anchor_b - j.anchor_a).norm())},
                      {"target", vec(j.target)},
                      {"max_force", j.max_force},
                      {"motor_speed", j.motor_speed},
                      {"max_motor_torque", j.max_motor_torque},
                      {"motor_start_s", j.motor_start_s},
                      {"collide_connected", j.collide_connected},
                      {"spring", spring}});
  }
  return {{"op", "build"},
          {"engine", std::string(engine)},
          {"settings", settings},
          {"world", {{"gravity", vec(s.world.gravity)}, {"fps", s.world.fps}, {"substeps", s.world.substeps}}},
          {"bodies", bodies},
          {"joints", joints}};
}

std::unique_ptr<scene::SceneWorld> build_node_scene(std::string_view engine, std::span<const engines::SettingSpec> specs,
                                                    const scene::SceneBuild& build, std::optional<FieldError>& error,
                                                    NodeWorker& worker) {
  json answer;
  int generation = 0;
  try {
    answer = worker.call(build_request(engine, specs, build));
    generation = worker.generation();
  } catch (const WorkerError& e) {
    error = FieldError{"engine", std::string(engine) + " cannot run: " + e.what()};
    return nullptr;
  }
  if (answer.value("ok", false) && answer.contains("world") && answer["world"].is_number_integer()) {
    return std::make_unique<NodeSceneWorld>(worker, engine, answer["world"].get<int>(), generation, *build.scene,
                                            build.contacts);
  }
  error = FieldError{answer.value("field", std::string("engine")),
                     answer.value("message", std::string(engine) + ": the worker answered " + answer.dump())};
  return nullptr;
}

bool angular_spring(const scene::Scene& scene, std::size_t joint) {
  return joint < scene.joints.size() && scene.joints[joint].kind == scene::JointKind::weld;
}

std::optional<scene::JointSpring> parse_spring(const engines::Parameters& typed, std::string_view stiffness_field,
                                               std::string_view damping_field, std::string_view choice_field,
                                               std::string_view choice, FieldError& error) {
  const engines::Parameter* k = nullptr;
  const engines::Parameter* c = nullptr;
  for (const engines::Parameter& p : typed) {
    if (p.name == stiffness_field) k = &p;
    if (p.name == damping_field) c = &p;
    if (!choice_field.empty() && p.name == choice_field && p.choice != choice) {
      error = FieldError{std::string(choice_field), "must be " + std::string(choice) + " (the scene's springs are built so)"};
      return std::nullopt;
    }
  }
  if (!k || !c) {
    const std::string_view missing = !k ? stiffness_field : damping_field;
    error = FieldError{std::string(missing), "is required: the joint's spring is typed as " + std::string(stiffness_field) +
                                                 " and " + std::string(damping_field)};
    return std::nullopt;
  }
  if (!std::isfinite(k->value) || !(k->value > 0.0)) {
    error = FieldError{std::string(stiffness_field), "must be a finite number > 0"};
    return std::nullopt;
  }
  if (!std::isfinite(c->value) || c->value < 0.0) {
    error = FieldError{std::string(damping_field), "must be a finite number >= 0"};
    return std::nullopt;
  }
  return scene::JointSpring{k->value, c->value};
}

}  // namespace softtune::node_worker
