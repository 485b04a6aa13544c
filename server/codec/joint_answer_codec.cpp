#include "codec/joint_answer_codec.h"

#include <cmath>
#include <cstdio>

#include "codec/json_writer.h"
#include "codec/problem.h"
#include "codec/tune_codec.h"

namespace softtune::codec {
namespace {

using nlohmann::json;
using namespace softtune::scene;

// Errors beyond these read as a miss, not as the asked motion (issue 30: 3 % in frequency, 0.03 in zeta).
constexpr double kMissFrequency = 0.03, kMissDamping = 0.03;

const ModalTargetResult* first_target(const SceneResult& run) {
  return run.modal_tuning && !run.modal_tuning->targets.empty() ? &run.modal_tuning->targets.front() : nullptr;
}

const ProbeResult* probe_of(const SceneResult& run, const std::string& id) {
  for (const ProbeResult& p : run.probes) {
    if (p.id == id) return &p;
  }
  return nullptr;
}

// The Box2D 2.4 model names its values on b2DistanceJointDef unless told the joint (wheel, mouse); a weld's
// spring is the same math on b2WeldJointDef, and a mouse joint's maxForce is the scene's.
void name_box2d_values(const JointSettings& j, json& values) {
  if (!values.is_object()) return;
  const std::string def(box2d_joint_def(j.kind));
  json out = json::object();
  for (auto& [name, v] : values.items()) {
    const std::size_t colons = name.find("::");
    const std::string field = colons == std::string::npos ? name : name.substr(colons + 2);
    out[def + "::" + field] = field == "maxForce" ? json(j.max_force) : v;
  }
  values = std::move(out);
}

json box2d_run_values(const JointSettings& j, const JointTuning& t) {
  const std::string def(box2d_joint_def(j.kind));
  json v = {{def + "::stiffness", number_or_null(t.stiffness)}, {def + "::damping", number_or_null(t.damping)}};
  if (j.kind == JointKind::mouse) v[def + "::maxForce"] = number_or_null(j.max_force);
  return v;
}

}  // namespace

json target_measurement(const SceneResult& run, const ModalTargetResult& target) {
  json out = {{"mode", target.mode}, {"probe", target.probe.empty() ? json() : json(target.probe)}};
  const ProbeResult* p = target.probe.empty() ? nullptr : probe_of(run, target.probe);
  if (p && p->measured.frequency_hz && p->measured.damping_ratio) {
    out["frequency_hz"] = number_or_null(p->measured.frequency_hz);
    out["damping_ratio"] = number_or_null(p->measured.damping_ratio);
    return out;
  }
  out["frequency_hz"] = nullptr;
  out["damping_ratio"] = nullptr;
  out["why"] = target.probe.empty() ? "no probe of the scene measures this mode (add a displacement or angle probe on its body)"
               : !p                 ? "its probe did not run"
                                    : "its probe's window shows no second-order motion to fit (the mode is not excited there)";
  return out;
}

namespace {

json warning(const char* code, const std::string& message) { return {{"code", code}, {"message", message}}; }

// A solved joint's warnings speak of what was asked: the target's mode, measured in the run.
json solved_warnings(const SceneResult& run, const json& engines) {
  json out = json::array();
  for (const ModalTargetResult& target : run.modal_tuning->targets) {
    const json m = target_measurement(run, target);
    char line[300];
    if (m["frequency_hz"].is_null()) {
      std::snprintf(line, sizeof line, "%s (asked %.4g Hz, damping ratio %.3g) is not measured: %s", target.mode.c_str(),
                    target.requested_frequency_hz, target.requested_damping_ratio, m["why"].get<std::string>().c_str());
      out.push_back(warning("mode_not_measured", line));
      continue;
    }
    const double f = m["frequency_hz"].get<double>(), zeta = m["damping_ratio"].get<double>();
    const double df = f / target.requested_frequency_hz - 1.0, dz = zeta - target.requested_damping_ratio;
    if (std::abs(df) > kMissFrequency || std::abs(dz) > kMissDamping) {
      std::snprintf(line, sizeof line, "%s measures %.4g Hz, damping ratio %.3g in Box2D 2.4 against the asked %.4g Hz, %.3g (%+.1f %%, %+.3f)",
                    target.mode.c_str(), f, zeta, target.requested_frequency_hz, target.requested_damping_ratio, 100.0 * df, dz);
      out.push_back(warning("mode_off_request", line));
    }
  }
  // The engines' own warnings stay (what each engine cannot do with these values); the solve's per-joint
  // request is nothing the designer asked, so the core's warnings about it do not.
  for (auto& [name, e] : engines.items()) {
    if (!e.is_object() || !e.contains("warnings")) continue;
    for (const json& w : e["warnings"]) {
      json copy = w;
      copy["engine"] = name;
      out.push_back(std::move(copy));
    }
  }
  return out;
}

json solved_engines(const Scene& scene, const SceneResult& run, const JointTuning& t, std::size_t i) {
  const JointSettings& j = scene.joints[i];
  const SolvedJoint& solved = *t.solved;
  json engines = solved.joint_export ? encode_tune_result(TuneRequest{}, *solved.joint_export)["engines"] : json::object();
  const ModalTargetResult* target = first_target(run);
  const json measured = target ? target_measurement(run, *target) : json();
  const json per_joint = solved.joint_export
                             ? json{{"frequency_hz", number_or_null(solved.joint_export->frequency_hz)},
                                    {"damping_ratio", number_or_null(solved.joint_export->damping_ratio)}}
                             : json();
  for (auto& [name, e] : engines.items()) {
    if (!e.is_object() || !e.contains("parameters")) continue;
    if (name == "box2d_v2_4") continue;
    e["basis"] = "per_joint_model";
    e["compared_to"] = per_joint;
    e["note"] = "per-joint model: these values make this engine's joint alone do what Box2D 2.4's joint does with the "
                "solved k, c on its own effective mass; the scene (and its mode) ran in Box2D 2.4 only";
  }
  json& b = engines["box2d_v2_4"];
  if (!b.is_object()) b = json::object();
  // Box2D 2.4 is the engine the scene ran: what to type is what ran, and what it achieves is the mode measured.
  b["basis"] = "scene_run";
  b["parameters"] = box2d_run_values(j, t);
  b["exact"] = b["parameters"];
  json achieved = {{"frequency_hz", measured.is_object() ? measured["frequency_hz"] : json()},
                   {"damping_ratio", measured.is_object() ? measured["damping_ratio"] : json()},
                   {"spectral_radius", b.contains("predicted") && b["predicted"].is_object() ? b["predicted"]["spectral_radius"] : json()},
                   {"stable", true}};
  b["predicted"] = achieved;
  b["exact_predicted"] = achieved;
  b["measured"] = measured;
  b["compared_to"] = target ? json{{"frequency_hz", number_or_null(target->requested_frequency_hz)},
                                   {"damping_ratio", number_or_null(target->requested_damping_ratio)}}
                            : json();
  b["note"] = "the values the scene ran in Box2D 2.4, measured on " + (target ? target->mode : std::string("the mode"));
  return engines;
}

json requested_of_target(const ModalTargetResult& t, int index) {
  const double f = t.requested_frequency_hz, zeta = t.requested_damping_ratio;
  return {{"frequency_hz", number_or_null(f)}, {"damping_ratio", number_or_null(zeta)},
          {"damped_frequency_hz", number_or_null(f * std::sqrt(std::max(0.0, 1.0 - zeta * zeta)))},
          {"mode", t.mode}, {"target", index}};
}

// The tune-shaped answer of a solved joint: its solved numbers, requested = the target, achieved = measured.
json solved_answer(const Scene& scene, const SceneResult& run, const JointTuning& t, std::size_t i, const json& warnings) {
  const ModalTargetResult* target = first_target(run);
  json a = t.solved->joint_export ? encode_tune_result(TuneRequest{}, *t.solved->joint_export) : json::object();
  a["mode"] = "solved";
  a["k"] = number_or_null(t.stiffness);
  a["c"] = number_or_null(t.damping);
  a["effective_mass"] = number_or_null(t.model_mass);
  if (target) {
    a["requested"] = requested_of_target(*target, 0);
    const json m = target_measurement(run, *target);
    a["achieved"] = {{"frequency_hz", m["frequency_hz"]}, {"damping_ratio", m["damping_ratio"]}, {"measured", m}};
  }
  a.erase("engines");    // the joint's own `engines` beside it (the page joins them): said once
  a.erase("stability");  // the integrators' verdicts on the per-joint equivalent: nothing the designer asked
  a["warnings"] = warnings;
  a["joint"] = scene.joints[i].id;
  a["solved_by"] = {{"group", t.solved->group}};
  return a;
}

json box2d_settings_json(const JointSettings& j, const JointTuning& t) {
  if (!t.tuned || t.request.engine_settings.empty()) return nullptr;
  const char* joints[] = {"distance", "wheel", "mouse"};
  for (const auto& v : t.request.engine_settings) {
    if (v.size() != 3) continue;
    json s = {{"joint", joints[static_cast<int>(v[0])]}, {"velocityIterations", static_cast<int>(v[1])}};
    if (j.kind == JointKind::mouse) s["rotationShare"] = number_or_null(v[2]);
    return {{"box2d_v2_4", std::move(s)}};
  }
  return nullptr;
}

}  // namespace

json scene_joint_engines_json(const Scene& scene, const SceneResult& run, const JointTuning& t) {
  std::size_t i = 0;
  while (i < scene.joints.size() && scene.joints[i].id != t.joint) ++i;
  if (i == scene.joints.size() || !t.tuned) return json::object();
  json engines = t.solved && run.modal_tuning ? solved_engines(scene, run, t, i) : encode_tune_result(t.request, t.result)["engines"];
  json& b = engines["box2d_v2_4"];
  if (b.is_object()) {
    for (const char* key : {"parameters", "exact"}) name_box2d_values(scene.joints[i], b[key]);
    // The model knows distance, wheel and mouse joints; a weld's spring is the same row on its own def.
    if (scene.joints[i].kind == JointKind::weld && b["settings"].is_object()) b["settings"]["joint"] = "weld";
  }
  return engines;
}

json scene_joint_json(const Scene& scene, const SceneResult& run, std::size_t i) {
  const JointTuning& t = run.joints[i];
  const JointSettings& js = scene.joints[i];
  json j = {{"id", t.joint}, {"type", joint_kind_name(js.kind)}, {"tuned", t.tuned}, {"typed", t.typed},
            {"angular", t.angular}, {"effective_mass", number_or_null(t.effective_mass)},
            {"box2d_reduced_mass", number_or_null(t.box2d_reduced_mass)}};
  // What to type into the engine that ran, under its own field names (SceneBackend::fields): the values the
  // page's Copy copies for a scene joint, in every engine alike.
  if (i < run.joint_fields.size() && !run.joint_fields[i].empty()) {
    j["parameters"] = {{"engine", run.engine}, {"values", engine_values_json(run.joint_fields[i])}};
  }
  if (t.typed) {
    j["mass_model"] = mass_model_name(t.mass_model);
    j["model_mass"] = number_or_null(t.model_mass);
    j["stiffness"] = number_or_null(t.stiffness);
    j["damping"] = number_or_null(t.damping);
    j["as_typed"] = box2d_run_values(js, t);
    return j;
  }
  if (!t.tuned) return j;
  j["mass_model"] = mass_model_name(t.mass_model);
  j["model_mass"] = number_or_null(t.model_mass);
  j["stiffness"] = number_or_null(t.stiffness);
  j["damping"] = number_or_null(t.damping);
  j["engine_settings"] = box2d_settings_json(js, t);
  const json engines = scene_joint_engines_json(scene, run, t);
  j["engines"] = engines;
  if (t.solved && run.modal_tuning) {
    const ModalTargetResult* target = first_target(run);
    json targets = json::array();
    for (const ModalTargetResult& x : run.modal_tuning->targets) targets.push_back(x.mode);
    j["requested"] = target ? requested_of_target(*target, 0) : json();
    j["solved_by"] = {{"group", t.solved->group}, {"targets", std::move(targets)}};
    j["measured"] = target ? target_measurement(run, *target) : json();
    j["predicted_frequency_hz"] = target && target->predicted ? number_or_null(target->predicted->frequency_hz) : json();
    j["achieved_frequency_hz"] = j["measured"].is_object() ? j["measured"]["frequency_hz"] : json();
    j["fell_back_to_standard"] = run.modal_tuning->fell_back_to_standard;
    j["warnings"] = solved_warnings(run, engines);
    j["answer"] = solved_answer(scene, run, t, i, j["warnings"]);
    return j;
  }
  j["requested"] = {{"frequency_hz", number_or_null(t.requested_frequency_hz)}, {"damping_ratio", number_or_null(t.requested_damping_ratio)}};
  j["predicted_frequency_hz"] = number_or_null(t.predicted_frequency_hz);
  j["achieved_frequency_hz"] = number_or_null(t.result.achieved_frequency_hz);
  j["fell_back_to_standard"] = t.fell_back_to_standard;
  j["warnings"] = warnings_json(t.result.warnings);
  return j;
}

std::optional<TypedSpring> read_typed(ObjectReader& r, const std::string& path, JointSettings& joint) {
  const json* v = r.raw("typed");
  if (!v) return std::nullopt;
  const std::string field = path + ".typed";
  const std::string def(box2d_joint_def(joint.kind));
  const std::string names = def + "::stiffness and " + def + "::damping" +
                            (joint.kind == JointKind::mouse ? " (and optionally " + def + "::maxForce)" : "");
  if (!v->is_object()) throw invalid_field(field, "must be an object of the values typed into Box2D 2.4: " + names);
  if (joint.kind == JointKind::revolute) throw invalid_field(field, "a revolute joint is a rigid pin: it has no spring to type");
  TypedSpring out;
  bool stiffness = false, damping = false;
  for (auto& [name, value] : v->items()) {
    const std::string at = field + "." + name;
    const bool known = name == def + "::stiffness" || name == def + "::damping" || (joint.kind == JointKind::mouse && name == def + "::maxForce");
    if (!known) throw invalid_field(at, "is not a value of this " + std::string(joint_kind_name(joint.kind)) + " joint's " + def + ": type " + names);
    if (!value.is_number()) throw invalid_field(at, "must be a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) throw invalid_field(at, "must be a finite number");
    if (name == def + "::stiffness") out.stiffness = x, stiffness = true;
    else if (name == def + "::damping") out.damping = x, damping = true;
    else joint.max_force = x;
  }
  if (!stiffness) throw invalid_field(field + "." + def + "::stiffness", "is required");
  if (!damping) throw invalid_field(field + "." + def + "::damping", "is required");
  return out;
}

}  // namespace softtune::codec
