#include "softtune/scene/runner.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "softtune/scene/box2d_backend.h"
#include "softtune/scene/engine_tuning.h"
#include "softtune/scene/probe_geometry.h"
#include "softtune/validation.h"

namespace softtune::scene {
namespace {

int find(const auto& items, const std::string& id) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

int find_joint_tuning(const std::vector<JointTuning>& t, const std::string& id) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i].joint == id) return static_cast<int>(i);
  }
  return -1;
}

// The talk's 1-D oscillator on one core integrator, sampled once per frame; stops at kDivergence.
std::optional<FieldError> run_oscillator(const Scene& scene, const OscillatorSettings& o, const std::vector<JointTuning>& joints,
                                         const std::string& path, OscillatorRun& out) {
  out.id = o.id;
  out.method = o.method;
  TuneRequest q;
  if (!o.joint.empty()) {
    const JointTuning& t = joints[find_joint_tuning(joints, o.joint)];
    q = *scene.joints[find(scene.joints, o.joint)].tuning;
    q.effective_mass = t.model_mass;
  } else {
    q = *o.tuning;
    q.effective_mass = o.effective_mass;
  }
  q.constraint.reset();
  q.fps = scene.world.fps;
  q.substeps = scene.world.substeps;
  if (auto e = validate_tune_request(q)) return FieldError{path + "." + e->field, e->rule};
  out.tuning = tune(q);
  out.requested_frequency_hz = requested_frequency_hz(q);
  out.requested_damping_ratio = requested_damping_ratio(q);
  const StepModel model = make_step_model(out.tuning.effective_mass, out.tuning.omega, out.tuning.damping_ratio, out.tuning.h);
  State s{o.initial_displacement, o.initial_velocity};
  const int frames = frame_count(scene.world);
  out.x.reserve(frames + 1);
  out.x.push_back(s.x);
  for (int f = 1; f <= frames; ++f) {
    for (int k = 0; k < scene.world.substeps; ++k) s = step(o.method, s, model);
    if (!std::isfinite(s.x) || std::abs(s.x) > kDivergence) {
      out.diverged_at_s = f / scene.world.fps;
      break;
    }
    out.x.push_back(s.x);
  }
  return std::nullopt;
}

bool body_finite(const BodyState& b) {
  return b.origin.allFinite() && b.centre.allFinite() && std::isfinite(b.angle) && b.velocity.allFinite() &&
         std::isfinite(b.angular_velocity);
}

// What a probe reads, resolved once: the body or joint index behind its id.
struct ProbeTarget {
  const ProbeSettings* probe = nullptr;
  int body = -1, joint = -1;
  Eigen::Vector2d axis{0, 1};
};

// One probe's value now, from the bodies' poses now and at the start.
double probe_value(const Scene& scene, const ProbeTarget& t, const std::vector<JointFrame>& frames,
                   std::span<const BodyState> now, std::span<const BodyState> start) {
  if (t.body >= 0) {
    if (t.probe->kind == ProbeKind::angle) return now[t.body].angle - start[t.body].angle;
    return (now[t.body].centre - start[t.body].centre).dot(t.axis);
  }
  const JointSettings& joint = scene.joints[t.joint];
  switch (t.probe->kind) {
    case ProbeKind::joint_length: return joint_length(joint, frames[t.joint], now);
    case ProbeKind::joint_angle: return joint_angle(frames[t.joint], now);
    default: return joint_error(joint, frames[t.joint], now);
  }
}

// The stages a scene will run, said before any of them starts.
void add_planned_stages(const Scene& scene, SceneResult& r) {
  r.stages.add(Stage::scene_setup);
  const bool tuned_joint = std::any_of(scene.joints.begin(), scene.joints.end(), [](const auto& j) { return j.tuning.has_value(); });
  if (tuned_joint || !scene.oscillators.empty()) {
    r.stages.add(Stage::designer_mapping);
    if (tuned_joint) r.stages.add(Stage::effective_mass);
    r.stages.add(Stage::softness);
  }
}

// Every 1-D oscillator of the scene on its core integrator; false (r.error set) when one is refused.
bool run_oscillators(const Scene& scene, SceneResult& r) {
  r.stages.add(Stage::core_integrator);
  r.oscillators.resize(scene.oscillators.size());
  for (std::size_t i = 0; i < scene.oscillators.size(); ++i) {
    if (auto e = run_oscillator(scene, scene.oscillators[i], r.joints, "oscillators." + std::to_string(i), r.oscillators[i])) {
      r.error = e;
      return false;
    }
  }
  return true;
}

// The Box2D probes' targets, resolved once; oscillator probes are read from their runs instead.
std::vector<ProbeTarget> resolve_probe_targets(const Scene& scene) {
  std::vector<ProbeTarget> targets;
  for (const ProbeSettings& probe : scene.probes) {
    if (probe.kind == ProbeKind::oscillator) continue;
    ProbeTarget t{&probe};
    if (probe.kind == ProbeKind::displacement || probe.kind == ProbeKind::angle) {
      t.body = find(scene.bodies, probe.body);
      t.axis = probe.axis.normalized();
    } else {
      t.joint = find(scene.joints, probe.joint);
    }
    targets.push_back(t);
  }
  return targets;
}

// Steps the world frame by frame, sampling the probes at t = 0 and after every frame (into `samples`, indexed
// like scene.probes), and watching for NaN, bodies leaving the world and the largest constraint error; records
// snapshots when asked.
void step_world(const Scene& scene, const RunOptions& options, bool box2d, SceneWorld& world,
                std::vector<std::vector<double>>& samples, SceneResult& r) {
  r.stages.add(box2d ? Stage::box2d_step : Stage::engine_step);
  if (options.record_frames) r.stages.add(Stage::snapshots);
  const std::vector<JointFrame> frames = joint_frames(scene);
  std::vector<BodyState> start(scene.bodies.size()), now(scene.bodies.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) start[b] = world.body(b);
  const std::vector<ProbeTarget> targets = resolve_probe_targets(scene);
  for (const ProbeTarget& t : targets) samples[t.probe - scene.probes.data()].reserve(r.frames + 1);
  std::vector<bool> left(scene.bodies.size(), false);
  const Eigen::Vector4d& bounds = scene.world.bounds;
  const int stride = std::max(1, options.frame_stride);
  std::size_t next_record = 0;  // into options.record_at
  for (int f = 0; f <= r.frames; ++f) {
    if (f > 0) world.step_frame(f - 1);
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      now[b] = world.body(b);
      r.finite = r.finite && body_finite(now[b]);
    }
    if (!r.finite) break;  // a NaN never reaches a probe series
    for (const ProbeTarget& t : targets) samples[t.probe - scene.probes.data()].push_back(probe_value(scene, t, frames, now, start));
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
      r.max_constraint_error = std::max(r.max_constraint_error, joint_error(scene.joints[j], frames[j], now));
    }
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      const Eigen::Vector2d& p = now[b].origin;
      if (!left[b] && (p.x() < bounds[0] || p.y() < bounds[1] || p.x() > bounds[2] || p.y() > bounds[3])) {
        left[b] = true;
        r.left_world.push_back(scene.bodies[b].id);
      }
    }
    if (!options.record_frames) continue;
    if (options.record_at.empty()) {
      if (f % stride == 0) r.snapshots.push_back(snapshot(scene, frames, now, world.contacts(), f));
      continue;
    }
    for (; next_record < options.record_at.size() && options.record_at[next_record] <= f; ++next_record) {
      if (options.record_at[next_record] == f) r.snapshots.push_back(snapshot(scene, frames, now, world.contacts(), f));
    }
  }
}

// The engine's settings by its own names (choices by name).
engines::Parameters describe(const SceneBackend& backend, const engines::SettingValues& values) {
  engines::Parameters out;
  for (std::size_t i = 0; i < backend.settings.size() && i < values.size(); ++i) {
    const engines::SettingSpec& spec = backend.settings[i];
    if (spec.choices.empty()) {
      out.push_back({spec.name, values[i], spec.unit});
    } else {
      out.push_back({spec.name, 0.0, {}, spec.choices[static_cast<std::size_t>(values[i])]});
    }
  }
  return out;
}

// Builds the scene's world in the backend: every joint tuned on the bodies as they start (the same k, c in
// every engine), each soft joint given its spring (options.springs where set), and what to type for it.
std::unique_ptr<SceneWorld> build_world(const Scene& scene, const RunOptions& options, const SceneBackend& backend,
                                        SceneResult& r) {
  engines::SettingValues settings = options.engine_settings;
  if (settings.empty()) {
    for (const engines::SettingSpec& spec : backend.settings) settings.push_back(spec.default_value);
  }
  r.engine_settings = describe(backend, settings);
  if (auto e = tune_scene_joints(scene, r.mass_model, r.joints)) {
    r.error = e;
    return nullptr;
  }
  SceneBuild build{&scene, {}, settings, options.record_frames};
  r.joint_fields.resize(scene.joints.size());
  for (std::size_t i = 0; i < scene.joints.size(); ++i) {
    JointTuning& t = r.joints[i];
    std::optional<JointSpring> spring;
    if (t.soft()) spring = JointSpring{t.stiffness, t.damping};
    if (i < options.springs.size() && options.springs[i]) spring = options.springs[i];
    if (spring) {
      t.stiffness = spring->stiffness;
      t.damping = spring->damping;
      r.joint_fields[i] = backend.fields(scene, i, *spring, settings);
    }
    build.springs.push_back(spring);
  }
  std::optional<FieldError> refused;
  std::unique_ptr<SceneWorld> world = backend.build(build, refused);
  if (!world) r.error = refused.value_or(FieldError{"engine", std::string(backend.name) + " could not build the scene"});
  return world;
}

// Each probe's series fitted (Prony) and set against what was asked of it and what was predicted.
void fit_probes(const Scene& scene, std::vector<std::vector<double>>& samples, SceneResult& r) {
  r.stages.add(Stage::response_fit);
  for (std::size_t p = 0; p < scene.probes.size(); ++p) {
    const ProbeSettings& probe = scene.probes[p];
    std::optional<double> f_req = probe.requested_frequency_hz, zeta_req = probe.requested_damping_ratio;
    std::optional<double> predicted;
    bool diverged = false;
    if (probe.kind == ProbeKind::oscillator) {
      const OscillatorRun& o = r.oscillators[find(scene.oscillators, probe.oscillator)];
      samples[p] = o.x;
      diverged = o.diverged_at_s.has_value();
      if (!f_req) f_req = o.requested_frequency_hz;
      if (!zeta_req) zeta_req = o.requested_damping_ratio;
    } else if (!probe.joint.empty() && probe.kind != ProbeKind::joint_error && probe.joint_request) {  // a rigid row has no request
      const JointTuning& t = r.joints[find_joint_tuning(r.joints, probe.joint)];
      if (t.tuned) {
        if (!f_req) f_req = t.requested_frequency_hz;
        if (!zeta_req) zeta_req = t.requested_damping_ratio;
        predicted = t.predicted_frequency_hz;
      }
    }
    ProbeResult pr = measure_probe(probe, std::move(samples[p]), scene.world.fps);
    pr.requested_frequency_hz = f_req;
    pr.requested_damping_ratio = zeta_req;
    pr.predicted_frequency_hz = predicted;
    pr.diverged = diverged;
    if (f_req && pr.measured.frequency_hz) pr.frequency_error = *pr.measured.frequency_hz / *f_req - 1.0;
    if (zeta_req && pr.measured.damping_ratio) pr.damping_ratio_error = *pr.measured.damping_ratio - *zeta_req;
    r.probes.push_back(std::move(pr));
  }
}

}  // namespace

ProbeResult measure_probe(const ProbeSettings& probe, std::vector<double> value, double fps) {
  ProbeResult r;
  r.id = probe.id;
  for (std::size_t i = 0; i < value.size(); ++i) r.time_s.push_back(i / fps);
  const int last = static_cast<int>(value.size()) - 1;
  const int begin = std::min(last, static_cast<int>(std::ceil(probe.from_s * fps - 1e-9)));
  const int end = probe.to_s ? std::min(last, static_cast<int>(std::floor(*probe.to_s * fps + 1e-9))) : last;
  if (begin >= 0 && end >= begin) {
    const std::vector<double> window(value.begin() + begin, value.begin() + end + 1);
    for (double v : window) r.max_abs_value = std::max(r.max_abs_value, std::abs(v));
    r.measured = fit_response(window, 1.0 / fps);
    r.settle_frames = r.measured.settle_samples;
    if (r.settle_frames) r.settle_s = *r.settle_frames / fps;
  }
  r.value = std::move(value);
  return r;
}

SceneResult run_scene(const Scene& scene, const RunOptions& options) {
  SceneResult r;
  r.mass_model = options.mass_model.value_or(scene.mass_model);
  r.stages.add(Stage::validate);
  if (auto e = validate_scene(scene)) {
    r.error = e;
    return r;
  }
  // In an engine other than Box2D 2.4, modal targets and tuned joints are solved by that engine's own runs.
  if (tunes_in_engine(scene, options)) return run_scene_tuned_in_engine(scene, options);
  // Modes first (modal_tuning.h): the run is then of the scene with the solved springs in its joints.
  if (scene.modal_tuning) {
    Scene tuned;
    ModalTuningResult modal;
    if (auto e = tune_modes(scene, r.mass_model, modal, tuned, r.stages)) {
      r.error = e;
      return r;
    }
    SceneResult run = run_scene(tuned, options);
    run.stages.items.erase(run.stages.items.begin());  // its own validate: ran above
    r.stages.append(run.stages);
    run.stages = r.stages;
    mark_solved_joints(tuned, modal, run.joints);
    run.modal_tuning = std::move(modal);
    return run;
  }
  add_planned_stages(scene, r);
  r.frames = frame_count(scene.world);
  r.h = step_size(scene.world.fps, scene.world.substeps);

  // The engine's world exists only for scenes with bodies: the 1-D oscillator never creates one.
  const SceneBackend& backend = options.backend ? *options.backend : kBox2DV24SceneBackend;
  const bool box2d = &backend == &kBox2DV24SceneBackend;
  r.engine = backend.name;
  r.engine_version = backend.version;
  std::unique_ptr<SceneWorld> world;
  if (!scene.bodies.empty()) {
    r.stages.add(box2d ? Stage::box2d_world : Stage::engine_world);
    if (!(world = build_world(scene, options, backend, r))) return r;
  }
  if (!scene.oscillators.empty() && !run_oscillators(scene, r)) return r;

  std::vector<std::vector<double>> samples(scene.probes.size());
  if (world) step_world(scene, options, box2d, *world, samples, r);
  fit_probes(scene, samples, r);
  return r;
}

}  // namespace softtune::scene
