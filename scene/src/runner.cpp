#include "softtune/scene/runner.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "softtune/scene/box2d_scene.h"
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

bool body_finite(const b2Body* b) {
  const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity();
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(b->GetAngle()) && std::isfinite(v.x) &&
         std::isfinite(v.y) && std::isfinite(b->GetAngularVelocity());
}

Snapshot snapshot(const Scene& scene, Box2DScene& world, int frame) {
  Snapshot out;
  out.frame = frame;
  out.time_s = frame / scene.world.fps;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const b2Body* body = world.bodies()[i];
    BodySnapshot b;
    b.id = scene.bodies[i].id;
    b.is_static = scene.bodies[i].is_static;
    for (const ProbeSettings& p : scene.probes) b.probed = b.probed || p.body == b.id;
    b.center = {body->GetPosition().x, body->GetPosition().y};
    b.angle = body->GetAngle();
    b.mass_centre = {body->GetWorldCenter().x, body->GetWorldCenter().y};
    const b2Shape* shape = body->GetFixtureList()->GetShape();
    if (shape->GetType() == b2Shape::e_circle) {
      const auto* c = static_cast<const b2CircleShape*>(shape);
      const b2Vec2 p = body->GetWorldPoint(c->m_p);
      b.is_circle = true;
      b.center = {p.x, p.y};
      b.radius = c->m_radius;
    } else {
      const auto* poly = static_cast<const b2PolygonShape*>(shape);
      for (int k = 0; k < poly->m_count; ++k) {
        const b2Vec2 p = body->GetWorldPoint(poly->m_vertices[k]);
        b.vertices.emplace_back(p.x, p.y);
      }
    }
    out.bodies.push_back(std::move(b));
  }
  for (std::size_t i = 0; i < scene.joints.size(); ++i) {
    b2Joint* j = world.joints()[i];
    JointSnapshot s;
    s.id = scene.joints[i].id;
    s.kind = joint_kind_name(scene.joints[i].kind);
    s.anchor_a = {j->GetAnchorA().x, j->GetAnchorA().y};
    s.anchor_b = {j->GetAnchorB().x, j->GetAnchorB().y};
    if (j->GetType() == e_distanceJoint) s.rest_length = static_cast<b2DistanceJoint*>(j)->GetLength();
    s.current_length = (s.anchor_b - s.anchor_a).norm();
    out.joints.push_back(std::move(s));
  }
  for (b2Contact* c = world.world().GetContactList(); c; c = c->GetNext()) {
    if (!c->IsTouching() || !c->IsEnabled()) continue;
    b2WorldManifold m;
    c->GetWorldManifold(&m);
    for (int k = 0; k < c->GetManifold()->pointCount; ++k) {
      out.contacts.push_back({{m.points[k].x, m.points[k].y}, {m.normal.x, m.normal.y}});
    }
  }
  return out;
}

// What a probe reads, resolved once: the body or joint index behind its id.
struct ProbeTarget {
  const ProbeSettings* probe = nullptr;
  int body = -1, joint = -1;
  Eigen::Vector2d axis{0, 1};
};

// One probe's value now, from the world and its state at the start.
double probe_value(const Scene& scene, const ProbeTarget& t, Box2DScene& world, const std::vector<b2Vec2>& start_centers,
                   const std::vector<float>& start_angles) {
  if (t.body >= 0) {
    const b2Body* body = world.bodies()[t.body];
    if (t.probe->kind == ProbeKind::angle) return body->GetAngle() - start_angles[t.body];
    const b2Vec2 d = body->GetWorldCenter() - start_centers[t.body];
    return d.x * t.axis.x() + d.y * t.axis.y();
  }
  switch (t.probe->kind) {
    case ProbeKind::joint_length: return joint_length(scene.joints[t.joint], world.joints()[t.joint]);
    case ProbeKind::joint_angle: return joint_angle(world.joints()[t.joint]);
    default: return joint_error(scene.joints[t.joint], world.joints()[t.joint]);
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

// Steps the Box2D world frame by frame, sampling the probes at t = 0 and after every frame (into
// `samples`, indexed like scene.probes), and watching for NaN, bodies leaving the world and the largest
// constraint error; records snapshots when asked.
void step_world(const Scene& scene, const RunOptions& options, Box2DScene& world, std::vector<std::vector<double>>& samples,
                SceneResult& r) {
  r.stages.add(Stage::box2d_step);
  if (options.record_frames) r.stages.add(Stage::snapshots);
  std::vector<b2Vec2> centers;
  std::vector<float> angles;
  for (const b2Body* b : world.bodies()) {
    centers.push_back(b->GetWorldCenter());
    angles.push_back(b->GetAngle());
  }
  const std::vector<ProbeTarget> targets = resolve_probe_targets(scene);
  for (const ProbeTarget& t : targets) samples[t.probe - scene.probes.data()].reserve(r.frames + 1);
  std::vector<bool> left(scene.bodies.size(), false);
  const Eigen::Vector4d& bounds = scene.world.bounds;
  const int stride = std::max(1, options.frame_stride);
  std::size_t next_record = 0;  // into options.record_at
  for (int f = 0; f <= r.frames; ++f) {
    if (f > 0) world.step_frame(f - 1);
    for (const b2Body* b : world.bodies()) r.finite = r.finite && body_finite(b);
    if (!r.finite) break;  // a NaN never reaches a probe series
    for (const ProbeTarget& t : targets) samples[t.probe - scene.probes.data()].push_back(probe_value(scene, t, world, centers, angles));
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
      r.max_constraint_error = std::max(r.max_constraint_error, joint_error(scene.joints[j], world.joints()[j]));
    }
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      const b2Vec2 p = world.bodies()[b]->GetPosition();
      if (!left[b] && (p.x < bounds[0] || p.y < bounds[1] || p.x > bounds[2] || p.y > bounds[3])) {
        left[b] = true;
        r.left_world.push_back(scene.bodies[b].id);
      }
    }
    if (!options.record_frames) continue;
    if (options.record_at.empty()) {
      if (f % stride == 0) r.snapshots.push_back(snapshot(scene, world, f));
      continue;
    }
    for (; next_record < options.record_at.size() && options.record_at[next_record] <= f; ++next_record) {
      if (options.record_at[next_record] == f) r.snapshots.push_back(snapshot(scene, world, f));
    }
  }
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

  // The Box2D world exists only for scenes with bodies: the 1-D oscillator never creates one.
  std::unique_ptr<Box2DScene> world;
  if (!scene.bodies.empty()) {
    r.stages.add(Stage::box2d_world);
    world = std::make_unique<Box2DScene>(scene, r.mass_model);
    if (world->error()) {
      r.error = world->error();
      return r;
    }
    r.joints = world->tunings();
  }
  if (!scene.oscillators.empty() && !run_oscillators(scene, r)) return r;

  std::vector<std::vector<double>> samples(scene.probes.size());
  if (world) step_world(scene, options, *world, samples, r);
  fit_probes(scene, samples, r);
  return r;
}

}  // namespace softtune::scene
