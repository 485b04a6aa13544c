#include "softtune/scene/modal_tuning.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "softtune/discrete_analysis.h"
#include "softtune/scene/limits.h"
#include "softtune/validation.h"

namespace softtune::scene {
namespace {

std::string at(const std::string& list, std::size_t i) { return "modal_tuning." + list + "." + std::to_string(i); }

int find_id(const auto& items, const std::string& id) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

std::optional<modes::Dof> motion_dof(const std::string& motion) {
  for (modes::Dof d : {modes::Dof::x, modes::Dof::y, modes::Dof::angle}) {
    if (motion == modes::dof_word(d)) return d;
  }
  return std::nullopt;
}

// The designer request of a target, completed as the runner completes a joint's (fps, substeps; the mass is a
// placeholder: a mode has no single mass).
TuneRequest target_request(const Scene& s, const ModeTargetSettings& t) {
  TuneRequest q = t.tuning;
  q.fps = s.world.fps;
  q.substeps = s.world.substeps;
  q.effective_mass = 1.0;
  q.constraint.reset();
  return q;
}

std::optional<FieldError> check_target(const Scene& s, const ModeTargetSettings& t, const std::string& path) {
  if (t.probe.empty() && t.body.empty()) return FieldError{path + ".body", "give body with mode (heave | pitch | surge), or a probe"};
  if (!t.probe.empty()) {
    const int p = find_id(s.probes, t.probe);
    if (p < 0) return FieldError{path + ".probe", "must name a probe of this scene"};
    const ProbeSettings& probe = s.probes[p];
    // Alone, the probe names the mode too: it must read a body coordinate.
    if (t.body.empty() && probe.kind != ProbeKind::displacement && probe.kind != ProbeKind::angle)
      return FieldError{path + ".probe", "must be a displacement or angle probe (a body coordinate a mode moves), or give body and mode"};
    if (t.body.empty() && !t.motion.empty()) return FieldError{path + ".body", "is required with mode"};
  }
  if (!t.body.empty()) {
    const int b = find_id(s.bodies, t.body);
    if (b < 0) return FieldError{path + ".body", "must name a body of this scene"};
    if (s.bodies[b].is_static) return FieldError{path + ".body", "must be a dynamic body (a static one has no modes)"};
    if (!motion_dof(t.motion)) return FieldError{path + ".mode", "must be heave, pitch or surge"};
  }
  if (auto e = validate_tune_request(target_request(s, t))) return FieldError{path + "." + e->field, e->rule};
  return std::nullopt;
}

}  // namespace

std::optional<FieldError> validate_modal_tuning(const Scene& s) {
  if (!s.modal_tuning) return std::nullopt;
  const ModalTuningSettings& m = *s.modal_tuning;
  if (auto e = check_linearisable(s, m.at_s, "modal_tuning.at_s")) return e;
  if (m.groups.empty() || m.groups.size() > limits::kMaxJointGroups)
    return FieldError{"modal_tuning.groups", "must hold 1 to " + std::to_string(limits::kMaxJointGroups) + " groups"};
  if (m.targets.empty() || m.targets.size() > limits::kMaxModeTargets)
    return FieldError{"modal_tuning.targets", "must hold 1 to " + std::to_string(limits::kMaxModeTargets) + " targets"};
  std::set<std::string> ids, grouped;
  for (std::size_t g = 0; g < m.groups.size(); ++g) {
    const JointGroupSettings& group = m.groups[g];
    if (group.id.empty() || group.id.size() > limits::kMaxIdLength || !ids.insert(group.id).second)
      return FieldError{at("groups", g) + ".id", "must be 1 to " + std::to_string(limits::kMaxIdLength) + " characters, unique among groups"};
    if (group.joints.empty() || group.joints.size() > limits::kMaxJoints)
      return FieldError{at("groups", g) + ".joints", "must name 1 to " + std::to_string(limits::kMaxJoints) + " joints"};
    for (std::size_t k = 0; k < group.joints.size(); ++k) {
      const std::string path = at("groups", g) + ".joints." + std::to_string(k);
      const int j = find_id(s.joints, group.joints[k]);
      if (j < 0) return FieldError{path, "must name a joint of this scene"};
      if (!s.joints[j].tuning) return FieldError{path, "must name a tuned joint (its own tuning is the solve's first guess)"};
      if (!grouped.insert(group.joints[k]).second) return FieldError{path, "is already in a group: a joint has one tuning"};
    }
  }
  for (std::size_t t = 0; t < m.targets.size(); ++t) {
    if (auto e = check_target(s, m.targets[t], at("targets", t))) return e;
  }
  return std::nullopt;
}

bool target_coordinate(const Scene& s, const ModeTargetSettings& t, const LinearisedScene& lin, int& body, modes::Dof& dof) {
  int scene_body = -1;
  if (t.body.empty()) {
    const ProbeSettings& p = s.probes[find_id(s.probes, t.probe)];
    scene_body = find_id(s.bodies, p.body);
    // A displacement probe measures the coordinate its axis is closest to.
    dof = p.kind == ProbeKind::angle ? modes::Dof::angle : (std::abs(p.axis.y()) >= std::abs(p.axis.x()) ? modes::Dof::y : modes::Dof::x);
  } else {
    scene_body = find_id(s.bodies, t.body);
    dof = *motion_dof(t.motion);
  }
  body = scene_body >= 0 ? lin.model_body[scene_body] : -1;
  return body >= 0;
}

std::string measuring_probe(const Scene& s, const ModeTargetSettings& t) {
  if (!t.probe.empty()) return t.probe;
  const modes::Dof dof = *motion_dof(t.motion);
  for (const ProbeSettings& p : s.probes) {
    if (p.body != t.body) continue;
    if (dof == modes::Dof::angle && p.kind == ProbeKind::angle) return p.id;
    if (dof != modes::Dof::angle && p.kind == ProbeKind::displacement) {
      const Eigen::Vector2d axis = p.axis.normalized();
      if (std::abs(dof == modes::Dof::y ? axis.y() : axis.x()) > 0.9) return p.id;
    }
  }
  return "";
}

namespace {

// A joint request for a designer's TuneRequest as the runner completes it (fps, substeps; a unit mass stands in).
TuneRequest joint_request(const Scene& s, TuneRequest q) {
  q.fps = s.world.fps;
  q.substeps = s.world.substeps;
  q.effective_mass = 1.0;
  q.constraint.reset();
  return q;
}

FieldError unresolvable(const modes::ModalTuneRequest& q, const LinearisedScene& lin) {
  char line[300];
  std::snprintf(line, sizeof line,
                "cannot be handed to the joints: the springs that place this mode have no designer request on a joint's "
                "own mass within the tune contract (their implicit Euler poles sit at z ~ 0 at h = %.4g s); ask for a "
                "slower or less damped motion",
                lin.h);
  return FieldError{q.targets.size() == 1 ? "modal_tuning.targets.0.frequency_hz" : "modal_tuning.targets", line};
}

// Each grouped joint takes its group's k, c as the equivalent standard request on its own model mass (or, for
// c < 0, the equivalent exact one), which the runner (and the next linearisation) turns back into that k, c.
// Returns false when a joint's equivalent request is out of the tune contract's range (k, c whose implicit
// Euler poles sit at z ~ 0: a pole the step cannot resolve).
bool set_group_springs(const Scene& scene, const LinearisedScene& lin, const std::vector<SpringConstants>& springs, Scene& tuned) {
  const ModalTuningSettings& settings = *scene.modal_tuning;
  for (std::size_t g = 0; g < settings.groups.size(); ++g) {
    for (const std::string& id : settings.groups[g].joints) {
      const int j = find_id(scene.joints, id);
      const double m = lin.joints[j].model_mass, k = springs[g].stiffness, c = springs[g].damping;
      tuned.joints[j].solved_spring = springs[g];
      TuneRequest& jt = *tuned.joints[j].tuning;
      jt.response_frames.reset();
      jt.oscillation.reset();
      if (c >= 0.0) {
        jt.mode = SoftMode::standard;
        jt.frequency_hz = std::sqrt(k / m) / (2.0 * std::numbers::pi);
        jt.damping_ratio = c / (2.0 * std::sqrt(k * m));
        if (validate_tune_request(joint_request(scene, jt))) return false;
        continue;
      }
      // c < 0 (exact mode, a fast request): no standard request gives it, but the exact request of the poles
      // implicit Euler has with (m, k, c) does (joint_tuning.h implicit_euler_request).
      const TuneRequest poles = implicit_euler_request(m, k, c, scene.world);
      jt.mode = SoftMode::exact;
      jt.frequency_hz = poles.frequency_hz;
      jt.damping_ratio = poles.damping_ratio;
      if (validate_tune_request(joint_request(scene, jt))) return false;
    }
  }
  return true;
}

// Exact mode cannot give zeta = 0 (like one joint: c' + h k' = 0, no finite gamma): implicit Euler damps every
// positive c, and a negative c would have to cancel it exactly. Such a solve matches the continuous poles (c = 0).
bool undamped_target(const Scene& scene) {
  for (const ModeTargetSettings& t : scene.modal_tuning->targets) {
    if (requested_damping_ratio(target_request(scene, t)) == 0.0) return true;
  }
  return false;
}

// The solve's request on one linearisation, from the groups' springs `start`.
modes::ModalTuneRequest solve_request(const Scene& scene, const LinearisedScene& lin, const std::vector<SpringConstants>& start,
                                      std::optional<FieldError>& error) {
  const ModalTuningSettings& settings = *scene.modal_tuning;
  modes::ModalTuneRequest q;
  q.discrete = settings.mode == SoftMode::exact && !undamped_target(scene);
  q.h = lin.h;
  for (std::size_t g = 0; g < settings.groups.size(); ++g) {
    modes::SpringGroup group;
    for (const std::string& id : settings.groups[g].joints) {
      for (int row : spring_rows(lin, find_id(scene.joints, id))) group.rows.push_back(row);
    }
    group.start = start[g];
    q.groups.push_back(group);
  }
  for (std::size_t t = 0; t < settings.targets.size(); ++t) {
    const ModeTargetSettings& target = settings.targets[t];
    modes::ModeTarget mt;
    if (!target_coordinate(scene, target, lin, mt.body, mt.dof)) {
      error = FieldError{"modal_tuning.targets." + std::to_string(t) + ".probe", "must measure a dynamic body"};
      return q;
    }
    const TuneRequest request = target_request(scene, target);
    mt.frequency_hz = requested_frequency_hz(request);
    mt.damping_ratio = requested_damping_ratio(request);
    q.targets.push_back(mt);
  }
  return q;
}

// The refusal of a target whose mode left with the rest state of the springs it needs: at those springs the
// body comes to rest held (on the ground, on its contacts), which no spring of the group moves any more.
FieldError held_at_rest(const Scene& scene, const LinearisedScene& lin, const modes::ModalTuneRequest& q,
                        const std::vector<SpringConstants>& springs, const modes::ModalTuneResult& r) {
  const std::string path = "modal_tuning." + r.error->field;
  const std::size_t t = static_cast<std::size_t>(r.refused_target);
  const int body = q.targets[t].body;
  int contacts = 0;
  for (const modes::Row& row : lin.model.rows) contacts += row.joint < 0 && (row.body_a == body || row.body_b == body);
  char line[400];
  std::snprintf(line, sizeof line,
                "cannot be reached: the springs that give %.4g Hz, damping ratio %.3g (k = %.4g, c = %.4g per joint of "
                "group '%s') let the scene rest with %s %s, so no mode moves it in %s (the request is softer than "
                "the scene's travel allows)",
                q.targets[t].frequency_hz, q.targets[t].damping_ratio, springs.front().stiffness, springs.front().damping,
                scene.modal_tuning->groups.front().id.c_str(), lin.model.bodies[body].id.c_str(),
                contacts ? "on its contacts" : "held by its rigid rows", std::string(modes::dof_word(q.targets[t].dof)).c_str());
  return FieldError{path, line};
}

// Whether stiffer group springs can lift the target's body: it hangs on a grouped joint, directly or through
// other joints (a box of the vehicle's stack does not: its contacts hold it whatever the suspension does).
bool carried_by_groups(const Scene& scene, const std::string& body) {
  std::set<std::string> reached{body};
  for (bool grew = true; grew;) {
    grew = false;
    for (const JointSettings& j : scene.joints) {
      if (reached.contains(j.body_a) != reached.contains(j.body_b)) grew = reached.insert(j.body_a).second | reached.insert(j.body_b).second;
    }
  }
  for (const JointGroupSettings& g : scene.modal_tuning->groups) {
    for (const std::string& id : g.joints) {
      const JointSettings& j = scene.joints[find_id(scene.joints, id)];
      if (reached.contains(j.body_a) || reached.contains(j.body_b)) return true;
    }
  }
  return false;
}

// A group whose solved k falls below this fraction of the round's first guess no longer holds the mode.
constexpr double kVanishingStiffness = 1e-6;

// An exact solve near Nyquist can stall far from the request (the discrete poles bend as omega h grows); the
// continuous solve of the same request is smooth there and lands close, so the exact one starts again from it.
modes::ModalTuneResult solve_from_continuous(const modes::LinearModel& model, modes::ReducedSystem& system,
                                             modes::ModalTuneRequest q, modes::ModalTuneResult first) {
  if (first.refusal != modes::Refusal::unreached || !q.discrete) return first;
  modes::ModalTuneRequest continuous = q;
  continuous.discrete = false;
  const modes::ModalTuneResult guess = modes::solve_modal_tune(model, system, continuous);
  if (guess.error) return first;
  for (std::size_t g = 0; g < q.groups.size(); ++g) q.groups[g].start = guess.groups[g];
  modes::ModalTuneResult second = modes::solve_modal_tune(model, system, q);
  return second.error && second.residual >= first.residual ? first : second;
}

// The floor of a target whose closest springs vanish: the mode keeps its frequency without the tuned joints
// (a deck on its pins), so no k of theirs makes it slower.
std::optional<FieldError> below_floor(const Scene& scene, const modes::ModalTuneRequest& q, const std::vector<SpringConstants>& start,
                                      const modes::ModalTuneResult& r) {
  for (std::size_t g = 0; g < r.groups.size(); ++g) {
    if (!(r.groups[g].stiffness < kVanishingStiffness * start[g].stiffness)) continue;
    const std::size_t t = static_cast<std::size_t>(std::max(0, r.refused_target));
    const std::optional<modes::Pole>& p = r.targets[t].predicted;
    char line[400];
    std::snprintf(line, sizeof line,
                  "cannot be reached: even with the k of group '%s' near 0 (%.3g) the mode stays at %.4g Hz: what holds "
                  "it without the tuned joints (pins, gravity, other springs) is faster than the %.4g Hz asked",
                  scene.modal_tuning->groups[g].id.c_str(), r.groups[g].stiffness, p ? p->frequency_hz : 0.0, q.targets[t].frequency_hz);
    return FieldError{"modal_tuning.targets." + std::to_string(t), line};
  }
  return std::nullopt;
}

// The body and coordinate a body probe reads ("chassis", y), or false for a joint probe.
bool probe_coordinate(const ProbeSettings& p, std::string& body, modes::Dof& dof) {
  if (p.kind != ProbeKind::displacement && p.kind != ProbeKind::angle) return false;
  body = p.body;
  const Eigen::Vector2d axis = p.axis.normalized();
  dof = p.kind == ProbeKind::angle ? modes::Dof::angle : (std::abs(axis.y()) >= std::abs(axis.x()) ? modes::Dof::y : modes::Dof::x);
  return true;
}

// The body and coordinate a target names (body + motion, or its probe's).
bool named_coordinate(const Scene& s, const ModeTargetSettings& t, std::string& body, modes::Dof& dof) {
  if (!t.body.empty()) {
    body = t.body;
    dof = *motion_dof(t.motion);
    return true;
  }
  const int p = find_id(s.probes, t.probe);
  return p >= 0 && probe_coordinate(s.probes[p], body, dof);
}

// What each probe is compared with once the groups are solved: a target's probe, and a body probe on a target's
// body and coordinate, with that target's request; any other probe of a grouped joint with nothing (a joint's
// travel mixes the modes: the car's rear travel moves with its heave and its pitch) -- never the solve's
// per-joint equivalent request.
void set_probe_requests(const Scene& scene, const ModalTuningResult& out, Scene& tuned) {
  std::set<std::string> grouped;
  for (const JointGroupSettings& g : scene.modal_tuning->groups) grouped.insert(g.joints.begin(), g.joints.end());
  const auto& targets = scene.modal_tuning->targets;
  for (ProbeSettings& p : tuned.probes) {
    int match = -1;
    for (std::size_t t = 0; t < out.targets.size() && match < 0; ++t) {
      if (out.targets[t].probe == p.id) match = static_cast<int>(t);
    }
    const bool own = p.requested_frequency_hz || p.requested_damping_ratio;  // the scene states its own
    if (own && match < 0) continue;
    std::string body;
    modes::Dof dof{};
    const bool body_probe = probe_coordinate(p, body, dof);
    for (std::size_t t = 0; t < targets.size() && t < out.targets.size() && match < 0; ++t) {
      std::string tb;
      modes::Dof td{};
      if (body_probe && named_coordinate(scene, targets[t], tb, td) && tb == body && td == dof) match = static_cast<int>(t);
    }
    if (match < 0 && !p.joint.empty() && grouped.contains(p.joint)) p.joint_request = false;
    if (match < 0) continue;
    p.joint_request = false;
    p.requested_frequency_hz = out.targets[match].requested_frequency_hz;
    p.requested_damping_ratio = out.targets[match].requested_damping_ratio;
  }
}

bool settled_springs(const std::vector<SpringConstants>& a, const std::vector<SpringConstants>& b) {
  for (std::size_t g = 0; g < a.size(); ++g) {
    if (std::abs(std::log(a[g].stiffness / b[g].stiffness)) > kModalRoundTolerance) return false;
    if (std::abs(std::log(a[g].damping / b[g].damping)) > kModalRoundTolerance) return false;
  }
  return true;
}

}  // namespace

std::optional<FieldError> tune_modes(const Scene& scene, MassModel mass_model, ModalTuningResult& out, Scene& tuned,
                                     StageList& stages) {
  const ModalTuningSettings& settings = *scene.modal_tuning;
  out = ModalTuningResult{};
  tuned = scene;
  tuned.modal_tuning.reset();
  stages.add(Stage::settle);
  stages.add(Stage::linearise);
  std::vector<SpringConstants> springs;  // the groups' k, c the next linearisation settles with
  bool solved_once = false;
  int stiffenings = 0;
  for (int round = 0; round < kMaxModalRounds;) {
    LinearisedScene lin;
    if (auto e = linearise_scene(tuned, mass_model, LinearisationOptions{settings.at_s}, lin)) return e;
    if (springs.empty()) {
      for (const JointGroupSettings& g : settings.groups) {
        const JointTuning& first = lin.joints[find_id(scene.joints, g.joints.front())];
        springs.push_back({first.stiffness, first.damping});
      }
    }
    std::optional<FieldError> error;
    const modes::ModalTuneRequest q = solve_request(scene, lin, springs, error);
    if (error) return error;
    if (!stages.contains(Stage::modal_solve)) {
      stages.add(Stage::modes);
      stages.add(Stage::modal_solve);
    }
    modes::ReducedSystem system = modes::reduce(lin.model);
    const modes::ModalTuneResult r = solve_from_continuous(lin.model, system, q, modes::solve_modal_tune(lin.model, system, q));
    const bool missing = r.refusal == modes::Refusal::no_mode || r.refusal == modes::Refusal::not_moved;
    const bool liftable = missing && carried_by_groups(scene, lin.model.bodies[q.targets[r.refused_target].body].id);
    if (liftable && !solved_once && stiffenings < kMaxStartStiffenings) {
      // The first guess sags the body onto something (a car whose per-spring tuning cannot carry it rests on
      // the road): start again from stiffer springs, the same damping ratio, until the mode is there.
      for (SpringConstants& g : springs) {
        g.stiffness *= kStartStiffening;
        g.damping *= std::sqrt(kStartStiffening);
      }
      set_group_springs(scene, lin, springs, tuned);
      ++stiffenings;
      continue;
    }
    if (missing && solved_once) return held_at_rest(scene, lin, q, springs, r);
    // Out of reach about this rest state may be in reach about the one the closest springs give (a deck that
    // sags more hangs slower): settle there and solve again, while rounds remain and the springs are usable.
    const bool usable = std::all_of(r.groups.begin(), r.groups.end(), [](const SpringConstants& g) {
      return std::isfinite(g.stiffness) && g.stiffness > 0.0 && std::isfinite(g.damping);
    });
    if (r.refusal == modes::Refusal::unreached) {
      if (auto e = below_floor(scene, q, springs, r)) return e;
    }
    if (r.refusal == modes::Refusal::unreached && usable && round + 1 < kMaxModalRounds &&
        !(solved_once && settled_springs(springs, r.groups))) {
      springs = r.groups;
      solved_once = true;
      if (!set_group_springs(scene, lin, springs, tuned)) return unresolvable(q, lin);
      ++round;
      continue;
    }
    if (r.error) return FieldError{"modal_tuning." + r.error->field, r.error->rule};
    const bool settled = solved_once && settled_springs(springs, r.groups);
    springs = r.groups;
    solved_once = true;
    if (!set_group_springs(scene, lin, springs, tuned)) return unresolvable(q, lin);
    ++round;

    out = ModalTuningResult{};
    out.residual = r.residual;
    out.least_squares = r.least_squares;
    out.iterations = r.iterations;
    out.rounds = round;
    out.start_stiffenings = stiffenings;
    out.fell_back_to_standard = settings.mode == SoftMode::exact && !q.discrete;
    out.at_s = lin.at_s;
    out.settled = lin.settled;
    out.modes = r.modes;
    for (const auto& b : lin.model.bodies) out.body_ids.push_back(b.id);
    for (std::size_t g = 0; g < settings.groups.size(); ++g) {
      out.groups.push_back({settings.groups[g].id, settings.groups[g].joints, springs[g].stiffness, springs[g].damping});
    }
    for (std::size_t t = 0; t < settings.targets.size(); ++t) {
      ModalTargetResult tr;
      const modes::TargetOutcome& o = r.targets[t];
      tr.mode = r.modes[o.mode].name;
      tr.probe = measuring_probe(scene, settings.targets[t]);
      tr.requested_frequency_hz = q.targets[t].frequency_hz;
      tr.requested_damping_ratio = q.targets[t].damping_ratio;
      tr.predicted = o.predicted;
      tr.continuous = r.modes[o.mode].continuous;
      tr.discrete = r.modes[o.mode].discrete;
      out.targets.push_back(tr);
    }
    if (settled && round >= kMinModalRounds) break;
  }
  set_probe_requests(scene, out, tuned);
  return std::nullopt;
}

void mark_solved_joints(const Scene& scene, const ModalTuningResult& modal, std::vector<JointTuning>& joints) {
  for (const ModalGroupResult& g : modal.groups) {
    for (const std::string& id : g.joints) {
      for (JointTuning& t : joints) {
        if (t.joint != id || !t.tuned) continue;
        SolvedJoint solved{g.id, std::nullopt};
        TuneRequest q = implicit_euler_request(t.model_mass, t.stiffness, t.damping, scene.world);
        q.engine_settings = t.request.engine_settings;
        if (!validate_tune_request(q)) solved.joint_export = tune(q);
        t.solved = std::move(solved);
      }
    }
  }
}

}  // namespace softtune::scene
