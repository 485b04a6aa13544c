#include "softtune/scene/modal_tuning.h"

#include <cmath>
#include <numbers>
#include <set>

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

std::optional<FieldError> tune_modes(const Scene& scene, MassModel mass_model, ModalTuningResult& out, Scene& tuned,
                                     StageList& stages) {
  const ModalTuningSettings& settings = *scene.modal_tuning;
  out = ModalTuningResult{};
  tuned = scene;
  tuned.modal_tuning.reset();
  std::vector<SpringConstants> solved;
  for (int round = 0; round < kModalRounds; ++round) {
    if (round == 0) {
      stages.add(Stage::settle);
      stages.add(Stage::linearise);
    }
    LinearisedScene lin;
    if (auto e = linearise_scene(tuned, mass_model, LinearisationOptions{settings.at_s}, lin)) return e;

    modes::ModalTuneRequest q;
    q.discrete = settings.mode == SoftMode::exact;
    q.h = lin.h;
    for (std::size_t g = 0; g < settings.groups.size(); ++g) {
      modes::SpringGroup group;
      for (const std::string& id : settings.groups[g].joints) {
        const int j = find_id(scene.joints, id);
        for (int row : spring_rows(lin, j)) group.rows.push_back(row);
      }
      const int first = find_id(scene.joints, settings.groups[g].joints.front());
      group.start = round == 0 ? SpringConstants{lin.joints[first].stiffness, lin.joints[first].damping} : solved[g];
      q.groups.push_back(group);
    }
    for (std::size_t t = 0; t < settings.targets.size(); ++t) {
      const ModeTargetSettings& target = settings.targets[t];
      modes::ModeTarget mt;
      if (!target_coordinate(scene, target, lin, mt.body, mt.dof)) {
        return FieldError{"modal_tuning.targets." + std::to_string(t) + ".probe", "must measure a dynamic body"};
      }
      const TuneRequest request = target_request(scene, target);
      mt.frequency_hz = requested_frequency_hz(request);
      mt.damping_ratio = requested_damping_ratio(request);
      q.targets.push_back(mt);
    }
    if (round == 0) {
      stages.add(Stage::modes);
      stages.add(Stage::modal_solve);
    }
    modes::ReducedSystem system = modes::reduce(lin.model);
    const modes::ModalTuneResult r = modes::solve_modal_tune(lin.model, system, q);
    if (r.error) return FieldError{"modal_tuning." + r.error->field, r.error->rule};
    solved = r.groups;

    // The solved springs as each joint's equivalent standard request on its own model mass.
    for (std::size_t g = 0; g < settings.groups.size(); ++g) {
      for (const std::string& id : settings.groups[g].joints) {
        const int j = find_id(scene.joints, id);
        const double m = lin.joints[j].model_mass, k = solved[g].stiffness, c = solved[g].damping;
        TuneRequest& jt = *tuned.joints[j].tuning;
        jt.response_frames.reset();
        jt.oscillation.reset();
        jt.mode = SoftMode::standard;
        jt.frequency_hz = std::sqrt(k / m) / (2.0 * std::numbers::pi);
        jt.damping_ratio = c / (2.0 * std::sqrt(k * m));
      }
    }

    out = ModalTuningResult{};
    out.residual = r.residual;
    out.least_squares = r.least_squares;
    out.iterations = r.iterations;
    out.at_s = lin.at_s;
    out.settled = lin.settled;
    out.modes = r.modes;
    for (const auto& b : lin.model.bodies) out.body_ids.push_back(b.id);
    for (std::size_t g = 0; g < settings.groups.size(); ++g) {
      out.groups.push_back({settings.groups[g].id, settings.groups[g].joints, solved[g].stiffness, solved[g].damping});
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
  }
  for (const ModalTargetResult& t : out.targets) {
    const int p = find_id(tuned.probes, t.probe);
    if (p < 0) continue;
    tuned.probes[p].requested_frequency_hz = t.requested_frequency_hz;
    tuned.probes[p].requested_damping_ratio = t.requested_damping_ratio;
  }
  return std::nullopt;
}

}  // namespace softtune::scene
