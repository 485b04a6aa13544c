#include "codec/scene_codec.h"

#include <cmath>

#include "codec/json_reader.h"
#include "codec/joint_answer_codec.h"
#include "codec/json_writer.h"
#include "codec/modes_codec.h"
#include "codec/scene_engine_codec.h"
#include "codec/list_reader.h"
#include "codec/problem.h"
#include "codec/tune_codec.h"
#include "softtune/scene/limits.h"
#include "softtune/validation.h"

namespace softtune::codec {
namespace {

using nlohmann::json;
using namespace softtune::scene;

Eigen::Vector2d read_vec2(ObjectReader& r, std::string_view key, const Eigen::Vector2d& fallback) {
  const auto v = r.numbers(key, 2);
  return v ? Eigen::Vector2d((*v)[0], (*v)[1]) : fallback;
}

std::string required_string(ObjectReader& r, std::string_view key) {
  auto s = r.string(key);
  if (!s) throw invalid_field(r.field(key), "is required");
  return *s;
}

// The designer fields of the tune contract, read by the tune codec itself (read_tune_fields) so a joint accepts
// exactly what `softtune tune` accepts, with the same rules. The effective mass is a placeholder there: the
// joint's real one is known only once its bodies exist (the runner tunes it again with it). Empty when the
// object carries none of them: a rigid joint.
constexpr const char* kDesignerFields[] = {"response_frames", "basis_fps", "frequency_hz", "oscillation", "damping_ratio", "mode"};

}  // namespace

std::optional<TuneRequest> read_designer_fields(ObjectReader& r, const std::string& path, bool with_mode) {
  json designer = json::object();
  for (const char* key : kDesignerFields) {
    if (!with_mode && std::string_view(key) == "mode") continue;
    if (const json* v = r.raw(key)) designer[key] = *v;
  }
  if (designer.empty()) return std::nullopt;
  designer["effective_mass"] = 1.0;
  ObjectReader fields(designer, path);
  try {
    TuneRequest q = read_tune_fields(fields);
    q.effective_mass.reset();
    return q;
  } catch (const Problem& p) {
    // The core's range checks name the bare field ("response_frames"); give it the joint's path.
    if (p.field.rfind(path + ".", 0) == 0) throw;
    throw invalid_field(path + "." + p.field, p.detail);
  }
}

namespace {

WorldSettings read_world(ObjectReader& r) {
  WorldSettings w;
  w.gravity = read_vec2(r, "gravity", w.gravity);
  if (auto v = r.number("fps")) w.fps = *v;
  if (auto v = r.integer("substeps")) w.substeps = static_cast<int>(std::clamp<long long>(*v, -1, 1 << 20));
  if (auto v = r.integer("velocity_iterations")) w.velocity_iterations = static_cast<int>(std::clamp<long long>(*v, -1, 1 << 20));
  if (auto v = r.integer("position_iterations")) w.position_iterations = static_cast<int>(std::clamp<long long>(*v, -1, 1 << 20));
  if (auto v = r.number("duration_s")) w.duration_s = *v;
  if (auto b = r.numbers("bounds", 4)) w.bounds = {(*b)[0], (*b)[1], (*b)[2], (*b)[3]};
  if (const json* s = r.raw("allow_sleeping")) {
    if (!s->is_boolean()) throw invalid_field(r.field("allow_sleeping"), "must be true or false");
    w.allow_sleeping = s->get<bool>();
  }
  return w;
}


ShapeSettings read_shape(ObjectReader& r) {
  ShapeSettings s;
  const auto kind = r.choice("type", {"box", "circle", "polygon"});
  if (!kind) throw invalid_field(r.field("type"), "is required: \"box\", \"circle\" or \"polygon\"");
  s.kind = static_cast<ShapeKind>(*kind);
  if (s.kind == ShapeKind::box) {
    s.width = r.number("width").value_or(0.0);
    s.height = r.number("height").value_or(0.0);
  } else if (s.kind == ShapeKind::circle) {
    s.radius = r.number("radius").value_or(0.0);
  } else {
    const json* v = r.raw("vertices");
    if (!v || !v->is_array()) throw invalid_field(r.field("vertices"), "is required: an array of [x, y] points (m)");
    for (const json& p : *v) {
      if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
        throw invalid_field(r.field("vertices"), "must hold [x, y] number pairs (m)");
      s.vertices.emplace_back(p[0].get<double>(), p[1].get<double>());
    }
  }
  return s;
}

BodySettings read_body(ObjectReader& r) {
  BodySettings b;
  b.id = required_string(r, "id");
  auto shape = r.object("shape");
  if (!shape) throw invalid_field(r.field("shape"), "is required");
  b.shape = read_shape(*shape);
  shape->finish();
  b.is_static = read_bool(r, "static", false);
  b.mass = r.number("mass");
  if (auto v = r.number("density")) b.density = *v;
  b.position = read_vec2(r, "position", b.position);
  if (auto v = r.number("angle")) b.angle = *v;
  b.linear_velocity = read_vec2(r, "linear_velocity", b.linear_velocity);
  if (auto v = r.number("angular_velocity")) b.angular_velocity = *v;
  if (auto v = r.number("friction")) b.friction = *v;
  if (auto v = r.number("restitution")) b.restitution = *v;
  b.fixed_rotation = read_bool(r, "fixed_rotation", false);
  return b;
}

JointSettings read_joint(ObjectReader& r, const std::string& path) {
  JointSettings j;
  j.id = required_string(r, "id");
  const auto kind = r.choice("type", {"distance", "wheel", "weld", "mouse", "revolute"});
  if (!kind) throw invalid_field(r.field("type"), "is required");
  j.kind = static_cast<JointKind>(*kind);
  j.body_a = r.string("body_a").value_or("");
  j.body_b = required_string(r, "body_b");
  j.anchor_a = read_vec2(r, "anchor_a", j.anchor_a);
  j.anchor_b = read_vec2(r, "anchor_b", j.anchor_b);
  j.axis = read_vec2(r, "axis", j.axis);
  j.length = r.number("length");
  j.target = read_vec2(r, "target", j.anchor_b);
  if (auto v = r.number("max_force")) j.max_force = *v;
  if (auto v = r.number("motor_speed")) j.motor_speed = *v;
  if (auto v = r.number("max_motor_torque")) j.max_motor_torque = *v;
  if (auto v = r.number("motor_start_s")) j.motor_start_s = *v;
  j.collide_connected = read_bool(r, "collide_connected", false);
  j.tuning = read_designer_fields(r, path);
  j.typed = read_typed(r, path, j);
  return j;
}

OscillatorSettings read_oscillator(ObjectReader& r, const std::string& path) {
  OscillatorSettings o;
  o.id = required_string(r, "id");
  if (auto m = r.choice("method", {"explicit_euler", "semi_implicit_euler", "implicit_euler", "soft", "soft_exact"}))
    o.method = kAllMethods[*m];
  o.effective_mass = r.number("effective_mass");
  o.joint = r.string("joint").value_or("");
  if (auto v = r.number("initial_displacement")) o.initial_displacement = *v;
  if (auto v = r.number("initial_velocity")) o.initial_velocity = *v;
  o.tuning = read_designer_fields(r, path);
  return o;
}

ProbeSettings read_probe(ObjectReader& r) {
  ProbeSettings p;
  p.id = required_string(r, "id");
  const auto kind = r.choice("kind", {"displacement", "angle", "joint_length", "joint_angle", "joint_error", "oscillator"});
  if (!kind) throw invalid_field(r.field("kind"), "is required");
  p.kind = static_cast<ProbeKind>(*kind);
  p.body = r.string("body").value_or("");
  p.joint = r.string("joint").value_or("");
  p.oscillator = r.string("oscillator").value_or("");
  p.axis = read_vec2(r, "axis", p.axis);
  if (auto v = r.number("from_s")) p.from_s = *v;
  p.to_s = r.number("to_s");
  if (auto req = r.object("requested")) {
    p.requested_frequency_hz = req->number("frequency_hz");
    p.requested_damping_ratio = req->number("damping_ratio");
    req->finish();
  }
  return p;
}

}  // namespace

std::optional<MassModel> read_mass_model(ObjectReader& r) {
  auto i = r.choice("mass_model", {"effective", "box2d_reduced"});
  return i ? std::optional<MassModel>(static_cast<MassModel>(*i)) : std::nullopt;
}

namespace {

// "fps": [Hz], "substeps": [counts]: a preset's rates and an expectation's, in the world's own ranges.
void read_rate_lists(ObjectReader& r, std::vector<double>& fps, std::vector<int>& substeps) {
  if (auto v = read_number_list(r, "fps", scene::limits::kMaxRates, softtune::limits::kMinFps, scene::limits::kMaxSceneFps, "Hz")) fps = *v;
  if (auto v = read_integer_list(r, "substeps", scene::limits::kMaxRates, 1, scene::limits::kMaxSceneSubsteps)) substeps = *v;
}

Expectation read_expectation(ObjectReader& r) {
  Expectation e;
  e.probe = r.string("probe").value_or("");
  const auto m = r.choice("metric", {"frequency_error", "damping_ratio_error", "measured_frequency_hz", "measured_damping_ratio",
                                     "overshoot", "settle_frames", "max_abs_value", "max_constraint_error", "finite", "in_world",
                                     "settle_s"});
  if (!m) throw invalid_field(r.field("metric"), "is required");
  e.metric = static_cast<Metric>(*m);
  e.min = r.number("min");
  e.max = r.number("max");
  e.mass_model = read_mass_model(r);
  e.note = r.string("note").value_or("");
  read_rate_lists(r, e.at_fps, e.at_substeps);
  return e;
}

json vec2_json(const Eigen::Vector2d& v) { return json::array({number_or_null(v.x()), number_or_null(v.y())}); }

json series_json(const std::vector<double>& values) {
  json out = json::array();
  for (double v : values) out.push_back(number_or_null(v));
  return out;
}

json probe_json(const Scene& scene, const ProbeResult& p, std::size_t i) {
  const ResponseFit& m = p.measured;
  return {
      {"id", p.id},
      {"kind", probe_kind_name(scene.probes[i].kind)},
      {"requested", {{"frequency_hz", number_or_null(p.requested_frequency_hz)}, {"damping_ratio", number_or_null(p.requested_damping_ratio)}}},
      {"measured", {{"frequency_hz", number_or_null(m.frequency_hz)},
                    {"damping_ratio", number_or_null(m.damping_ratio)},
                    {"overshoot", number_or_null(m.overshoot)},
                    {"settle_frames", p.settle_frames ? json(*p.settle_frames) : json()},
                    {"settle_s", number_or_null(p.settle_s)},
                    {"equilibrium", number_or_null(m.equilibrium)},
                    {"fit_residual", number_or_null(m.residual)}}},
      {"error", {{"frequency", number_or_null(p.frequency_error)}, {"damping_ratio", number_or_null(p.damping_ratio_error)}}},
      {"predicted_frequency_hz", number_or_null(p.predicted_frequency_hz)},
      {"max_abs_value", number_or_null(p.max_abs_value)},
      {"diverged", p.diverged},
      {"window", {{"from_s", scene.probes[i].from_s}, {"to_s", number_or_null(scene.probes[i].to_s)}}},
      {"series", {{"time", series_json(p.time_s)}, {"value", series_json(p.value)}}},
  };
}

json snapshot_json(const Snapshot& s) {
  json bodies = json::array(), joints = json::array();
  for (const BodySnapshot& b : s.bodies) {
    json body = {{"id", b.id}, {"static", b.is_static}, {"probed", b.probed}, {"angle", number_or_null(b.angle)}};
    if (b.is_circle) {
      body["circle"] = {{"center", vec2_json(b.center)}, {"radius", number_or_null(b.radius)}};
    } else {
      json vertices = json::array();
      for (const auto& v : b.vertices) vertices.push_back(vec2_json(v));
      body["polygon"] = std::move(vertices);
    }
    bodies.push_back(std::move(body));
  }
  for (const JointSnapshot& j : s.joints) {
    joints.push_back({{"id", j.id}, {"type", j.kind}, {"anchor_a", vec2_json(j.anchor_a)}, {"anchor_b", vec2_json(j.anchor_b)},
                      {"rest_length", number_or_null(j.rest_length)}, {"current_length", number_or_null(j.current_length)}});
  }
  return {{"frame", s.frame}, {"time", number_or_null(s.time_s)}, {"bodies", std::move(bodies)}, {"joints", std::move(joints)}};
}


}  // namespace

Scene decode_scene(const json& doc) {
  ObjectReader r = read_object(doc, "");
  Scene s;
  s.name = required_string(r, "name");
  s.description = r.string("description").value_or("");
  if (auto m = read_mass_model(r)) s.mass_model = *m;
  auto world = r.object("world");
  if (!world) throw invalid_field("world", "is required");
  s.world = read_world(*world);
  world->finish();
  if (auto camera = r.object("camera")) {
    s.camera.center = read_vec2(*camera, "center", s.camera.center);
    if (auto v = camera->number("width_m")) s.camera.width_m = *v;
    s.camera.fit = read_bool(*camera, "fit", s.camera.fit);
    if (auto v = camera->string("follow")) s.camera.follow = *v;
    camera->finish();
  }
  read_object_list(r, "bodies", false, [&](ObjectReader& o, const std::string&) { s.bodies.push_back(read_body(o)); });
  read_object_list(r, "joints", false, [&](ObjectReader& o, const std::string& path) { s.joints.push_back(read_joint(o, path)); });
  read_object_list(r, "oscillators", false, [&](ObjectReader& o, const std::string& path) { s.oscillators.push_back(read_oscillator(o, path)); });
  read_object_list(r, "probes", false, [&](ObjectReader& o, const std::string&) { s.probes.push_back(read_probe(o)); });
  read_object_list(r, "expectations", false, [&](ObjectReader& o, const std::string&) { s.expectations.push_back(read_expectation(o)); });
  if (auto m = r.object("modal_tuning")) {
    s.modal_tuning = read_modal_tuning(*m);
    m->finish();
  }
  if (auto rates = r.object("rates")) {
    read_rate_lists(*rates, s.rates.fps, s.rates.substeps);
    rates->finish();
  }
  r.finish();
  if (auto e = validate_scene(s)) throw_field_error(*e);
  return s;
}

json encode_scene_result(const Scene& scene, const SceneResult& r) {
  if (r.error) throw_field_error(*r.error);
  json joints = json::array(), oscillators = json::array(), probes = json::array();
  for (std::size_t i = 0; i < r.joints.size(); ++i) joints.push_back(scene_joint_json(scene, r, i));
  for (const OscillatorRun& o : r.oscillators) {
    oscillators.push_back({{"id", o.id}, {"method", method_name(o.method)}, {"effective_mass", number_or_null(o.tuning.effective_mass)},
                           {"stiffness", number_or_null(o.tuning.standard_spring.stiffness)},
                           {"damping", number_or_null(o.tuning.standard_spring.damping)},
                           {"diverged_at_s", number_or_null(o.diverged_at_s)}});
  }
  for (std::size_t i = 0; i < r.probes.size(); ++i) probes.push_back(probe_json(scene, r.probes[i], i));
  json out = {
      {"name", scene.name},
      {"mass_model", mass_model_name(r.mass_model)},
      {"engine", scene_engine_json(r)},
      {"stages", stages_json(r.stages)},
      {"frames", r.frames},
      {"fps", scene.world.fps},
      {"h", number_or_null(r.h)},
      {"joints", std::move(joints)},
      {"oscillators", std::move(oscillators)},
      {"probes", std::move(probes)},
      {"max_constraint_error", number_or_null(r.max_constraint_error)},
      {"finite", r.finite},
      {"left_world", r.left_world},
      {"camera", {{"center", vec2_json(scene.camera.center)}, {"width_m", number_or_null(scene.camera.width_m)},
                  {"fit", scene.camera.fit}, {"follow", scene.camera.follow}}},
  };
  if (r.modal_tuning) out["modal_tuning"] = modal_tuning_json(scene, *r.modal_tuning, r);
  if (!r.snapshots.empty()) {
    json frames = json::array();
    for (const Snapshot& s : r.snapshots) frames.push_back(snapshot_json(s));
    out["snapshots"] = std::move(frames);
  }
  return out;
}

bool read_bool(ObjectReader& r, std::string_view key, bool fallback) {
  const json* v = r.raw(key);
  if (!v) return fallback;
  if (!v->is_boolean()) throw invalid_field(r.field(key), "must be true or false");
  return v->get<bool>();
}

void throw_field_error(const FieldError& e) { throw invalid_field(e.field, e.rule); }

}  // namespace softtune::codec
