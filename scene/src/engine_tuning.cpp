#include "softtune/scene/engine_tuning.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "softtune/scene/box2d_backend.h"
#include "softtune/support/run_limit.h"

namespace softtune::scene {
namespace {

int index_of(const auto& items, const std::string& id) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

const ProbeResult* probe_named(const SceneResult& r, const std::string& id) {
  for (const ProbeResult& p : r.probes) {
    if (p.id == id) return &p;
  }
  return nullptr;
}

// A tuned joint's own-coordinate probe (its length or angle, compared with its own request), or -1.
int own_probe(const Scene& scene, const JointSettings& joint) {
  for (std::size_t p = 0; p < scene.probes.size(); ++p) {
    const ProbeSettings& probe = scene.probes[p];
    const bool own = probe.kind == ProbeKind::joint_length || probe.kind == ProbeKind::joint_angle;
    if (own && probe.joint == joint.id && probe.joint_request) return static_cast<int>(p);
  }
  return -1;
}

// The end of the window the targets are measured on: the latest of their probes' to_s (the run's end when one
// has none).
double targets_window(const Scene& scene, const std::vector<std::string>& probes) {
  double end = 0.0;
  for (const std::string& id : probes) {
    const int p = index_of(scene.probes, id);
    if (p < 0) continue;
    end = std::max(end, scene.probes[p].to_s.value_or(scene.world.duration_s));
  }
  return std::min(end, scene.world.duration_s);
}

// The solve's state: per unknown (ln k, c / c0), stacked.
struct Solve {
  const Scene* run_scene = nullptr;  // base, cut at the targets' window end
  RunOptions options;
  std::vector<EngineUnknown>* unknowns = nullptr;
  const std::vector<EngineTarget>* targets = nullptr;
  std::vector<double> damping_scale;  // c0 per unknown
  int runs = 0;
};

std::vector<std::optional<JointSpring>> springs_of(const Solve& s, const Eigen::VectorXd& x) {
  std::vector<std::optional<JointSpring>> springs(s.run_scene->joints.size());
  for (std::size_t u = 0; u < s.unknowns->size(); ++u) {
    const JointSpring spring{std::exp(x[2 * u]), std::max(0.0, x[2 * u + 1] * s.damping_scale[u])};
    for (int j : (*s.unknowns)[u].joints) springs[j] = spring;
  }
  return springs;
}

// One engine run with the springs of x: the residuals (f / f_req - 1, zeta - zeta_req per target), or empty
// when the run blew up or a target's fit failed; `error` when the engine refused the scene.
std::optional<Eigen::VectorXd> evaluate(Solve& s, const Eigen::VectorXd& x, std::optional<FieldError>& error) {
  support::check_run_limit();
  RunOptions o = s.options;
  o.springs = springs_of(s, x);
  const SceneResult r = run_scene(*s.run_scene, o);
  ++s.runs;
  if (r.error) {
    error = r.error;
    return std::nullopt;
  }
  if (!r.finite) return std::nullopt;
  Eigen::VectorXd res(2 * s.targets->size());
  for (std::size_t t = 0; t < s.targets->size(); ++t) {
    const EngineTarget& target = (*s.targets)[t];
    const ProbeResult* p = probe_named(r, target.probe);
    if (!p || !p->measured.frequency_hz || !p->measured.damping_ratio) return std::nullopt;
    res[2 * t] = *p->measured.frequency_hz / target.requested_frequency_hz - 1.0;
    res[2 * t + 1] = *p->measured.damping_ratio - target.requested_damping_ratio;
  }
  return res;
}

bool within_tolerance(const Eigen::VectorXd& r) {
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    if (std::abs(r[i]) > (i % 2 == 0 ? kEngineFrequencyTolerance : kEngineDampingTolerance)) return false;
  }
  return true;
}

// Which targets (rows / 2) each unknown answers for in a per-joint solve: its own joint's probe only.
bool answers_for(const EngineUnknown& u, const EngineTarget& t) { return t.request == u.id; }

// The finite-difference Jacobian at x (residual r0). Modal: one run per column (the groups couple through the
// bodies). Per joint: each joint's request is its own, so every joint is perturbed at once (two runs) and each
// column keeps only its own joint's rows. Empty when a perturbed run failed both ways.
std::optional<Eigen::MatrixXd> jacobian(Solve& s, bool modal, const Eigen::VectorXd& x, const Eigen::VectorXd& r0,
                                        std::optional<FieldError>& error) {
  const Eigen::Index n = x.size();
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(r0.size(), n);
  auto column = [&](const Eigen::VectorXd& dx) -> std::optional<Eigen::VectorXd> {
    for (double sign : {1.0, -1.0}) {
      if (auto r = evaluate(s, x + sign * dx, error)) return Eigen::VectorXd((*r - r0) / sign);
      if (error) return std::nullopt;
    }
    return std::nullopt;
  };
  const double step[2] = {kLnStiffnessStep, kDampingStep};
  if (modal) {
    for (Eigen::Index c = 0; c < n; ++c) {
      Eigen::VectorXd dx = Eigen::VectorXd::Zero(n);
      dx[c] = step[c % 2];
      auto d = column(dx);
      if (!d) return std::nullopt;
      J.col(c) = *d / step[c % 2];
    }
    return J;
  }
  for (int which = 0; which < 2; ++which) {
    Eigen::VectorXd dx = Eigen::VectorXd::Zero(n);
    for (Eigen::Index c = which; c < n; c += 2) dx[c] = step[which];
    auto d = column(dx);
    if (!d) return std::nullopt;
    for (std::size_t u = 0; u < s.unknowns->size(); ++u) {
      for (std::size_t t = 0; t < s.targets->size(); ++t) {
        if (!answers_for((*s.unknowns)[u], (*s.targets)[t])) continue;
        J(2 * t, 2 * u + which) = (*d)[2 * t] / step[which];
        J(2 * t + 1, 2 * u + which) = (*d)[2 * t + 1] / step[which];
      }
    }
  }
  return J;
}

// A per-joint Jacobian keeps each joint's columns on its own targets' rows only.
void keep_own_rows(const Solve& s, Eigen::MatrixXd& J) {
  for (std::size_t u = 0; u < s.unknowns->size(); ++u) {
    for (std::size_t t = 0; t < s.targets->size(); ++t) {
      if (!answers_for((*s.unknowns)[u], (*s.targets)[t])) J.block(2 * t, 2 * u, 2, 2).setZero();
    }
  }
}

// The Gauss-Newton step, cut to kMaxLnStiffnessStep / kMaxDampingStep (the whole step scaled, so it keeps
// its direction).
Eigen::VectorXd newton_step(const Eigen::MatrixXd& J, const Eigen::VectorXd& r) {
  Eigen::VectorXd dx = J.completeOrthogonalDecomposition().solve(-r);
  double scale = 1.0;
  for (Eigen::Index i = 0; i < dx.size(); ++i) {
    const double cap = i % 2 == 0 ? kMaxLnStiffnessStep : kMaxDampingStep;
    if (std::abs(dx[i]) > cap) scale = std::min(scale, cap / std::abs(dx[i]));
  }
  return dx * scale;
}

// The modal unknowns and targets: each group's Box2D 2.4 solve, each target with a measuring probe.
void modal_problem(const Scene& scene, const ModalTuningResult& modal, EngineTuningResult& out) {
  out.modal = true;
  for (const ModalGroupResult& g : modal.groups) {
    EngineUnknown u;
    u.id = g.id;
    for (const std::string& j : g.joints) u.joints.push_back(index_of(scene.joints, j));
    u.start = u.solved = {g.stiffness, g.damping};
    out.unknowns.push_back(std::move(u));
  }
  for (const ModalTargetResult& t : modal.targets) {
    if (t.probe.empty()) continue;  // a target no probe measures: nothing to run against
    EngineTarget e;
    e.probe = t.probe;
    e.request = t.mode;
    e.requested_frequency_hz = t.requested_frequency_hz;
    e.requested_damping_ratio = t.requested_damping_ratio;
    out.targets.push_back(std::move(e));
  }
}

// The per-joint unknowns and targets, from Box2D 2.4's run of the joints' own tunings (`box2d`).
void joint_problem(const Scene& scene, const SceneResult& box2d, EngineTuningResult& out) {
  for (std::size_t j = 0; j < scene.joints.size() && j < box2d.joints.size(); ++j) {
    const JointTuning& t = box2d.joints[j];
    const int p = own_probe(scene, scene.joints[j]);
    if (!t.tuned || p < 0) continue;
    const ProbeResult* pr = probe_named(box2d, scene.probes[p].id);
    const bool met = pr && pr->frequency_error && pr->damping_ratio_error &&
                     std::abs(*pr->frequency_error) <= kPerJointClaimFrequency &&
                     std::abs(*pr->damping_ratio_error) <= kPerJointClaimDamping;
    if (!met) {
      out.coupled_probes.push_back(scene.probes[p].id);
      continue;
    }
    EngineUnknown u;
    u.id = scene.joints[j].id;
    u.joints = {static_cast<int>(j)};
    u.start = u.solved = {t.stiffness, t.damping};
    out.unknowns.push_back(std::move(u));
    EngineTarget e;
    e.probe = scene.probes[p].id;
    e.request = scene.joints[j].id;
    e.requested_frequency_hz = t.requested_frequency_hz;
    e.requested_damping_ratio = t.requested_damping_ratio;
    out.targets.push_back(std::move(e));
  }
}

// Candidate probes of a per-joint solve (for the window): every tuned joint's own probe.
std::vector<std::string> joint_probe_ids(const Scene& scene) {
  std::vector<std::string> ids;
  for (const JointSettings& j : scene.joints) {
    const int p = own_probe(scene, j);
    if (j.tuning && p >= 0) ids.push_back(scene.probes[p].id);
  }
  return ids;
}

}  // namespace

bool tunes_in_engine(const Scene& scene, const RunOptions& options) {
  if (!options.backend || options.backend == &kBox2DV24SceneBackend || !options.springs.empty()) return false;
  if (scene.bodies.empty()) return false;
  if (scene.modal_tuning) return true;
  return std::any_of(scene.joints.begin(), scene.joints.end(), [](const JointSettings& j) { return j.tuning.has_value(); });
}

std::optional<FieldError> engine_tune_scene(const Scene& scene, const RunOptions& options, Scene& base,
                                            std::vector<std::optional<JointSpring>>& springs,
                                            std::optional<ModalTuningResult>& modal, EngineTuningResult& out,
                                            StageList& stages) {
  out = {};
  out.engine = options.backend ? std::string(options.backend->name) : std::string(kBox2DV24SceneBackend.name);
  const MassModel mass_model = options.mass_model.value_or(scene.mass_model);
  base = scene;
  std::vector<std::string> window_probes;
  if (scene.modal_tuning) {
    ModalTuningResult solved;
    if (auto e = tune_modes(scene, mass_model, solved, base, stages)) return e;
    base.modal_tuning.reset();
    modal_problem(base, solved, out);
    for (const EngineTarget& t : out.targets) window_probes.push_back(t.probe);
    modal = std::move(solved);
  } else {
    window_probes = joint_probe_ids(scene);
  }
  if (window_probes.empty()) return std::nullopt;
  out.window_s = targets_window(base, window_probes);
  // The solve's runs: the scene up to the window's end, measuring only the probes it reads.
  Scene cut = base;
  cut.world.duration_s = out.window_s;
  cut.expectations.clear();
  std::erase_if(cut.probes, [&](const ProbeSettings& p) {
    return std::find(window_probes.begin(), window_probes.end(), p.id) == window_probes.end();
  });

  // Box2D 2.4's own run of its solve: what it measures, and (per joint) which requests it meets.
  RunOptions box2d_options;
  box2d_options.mass_model = mass_model;
  const SceneResult box2d = run_scene(cut, box2d_options);
  if (box2d.error) return box2d.error;
  if (!scene.modal_tuning) joint_problem(cut, box2d, out);
  for (EngineTarget& t : out.targets) {
    if (const ProbeResult* p = probe_named(box2d, t.probe)) {
      t.box2d_frequency_hz = p->measured.frequency_hz;
      t.box2d_damping_ratio = p->measured.damping_ratio;
    }
  }
  if (out.unknowns.empty() || out.targets.empty()) return std::nullopt;

  Solve s;
  s.run_scene = &cut;
  s.options = options;
  s.options.record_frames = false;
  s.options.record_at.clear();
  s.unknowns = &out.unknowns;
  s.targets = &out.targets;
  const Eigen::Index n = static_cast<Eigen::Index>(2 * out.unknowns.size());
  Eigen::VectorXd x(n);
  for (std::size_t u = 0; u < out.unknowns.size(); ++u) {
    const JointSpring& start = out.unknowns[u].start;
    // c0: the start's damping, or (zeta 0 asked) a tenth of critical damping at the first target's frequency.
    const double omega = 2.0 * std::numbers::pi * out.targets.front().requested_frequency_hz;
    s.damping_scale.push_back(start.damping > 0.0 ? start.damping : 0.2 * start.stiffness / omega);
    x[2 * u] = std::log(start.stiffness);
    x[2 * u + 1] = start.damping / s.damping_scale.back();
  }
  std::optional<FieldError> error;
  std::optional<Eigen::VectorXd> r = evaluate(s, x, error);
  if (error) return error;
  for (std::size_t t = 0; r && t < out.targets.size(); ++t) {  // what the engine does with Box2D's springs
    out.targets[t].start_frequency_hz = out.targets[t].requested_frequency_hz * (1.0 + (*r)[2 * t]);
    out.targets[t].start_damping_ratio = out.targets[t].requested_damping_ratio + (*r)[2 * t + 1];
  }
  // The Jacobian is measured once and then carried by Broyden's update along the accepted steps; it is measured
  // again only when a step on the carried one fails to lower the residual.
  std::optional<Eigen::MatrixXd> J;
  bool fresh = false;
  while (r && !within_tolerance(*r) && s.runs < kMaxEngineRuns) {
    if (!J) {
      if (s.runs + n + 1 > kMaxEngineRuns) break;
      J = jacobian(s, out.modal, x, *r, error);
      if (error) return error;
      if (!J) break;
      fresh = true;
    }
    const Eigen::VectorXd dx = newton_step(*J, *r);
    bool accepted = false;
    for (double alpha = 1.0; alpha >= 0.25 && s.runs < kMaxEngineRuns; alpha *= 0.5) {
      std::optional<Eigen::VectorXd> trial = evaluate(s, x + alpha * dx, error);
      if (error) return error;
      if (trial && trial->norm() < r->norm()) {
        const Eigen::VectorXd step = alpha * dx, change = *trial - *r;
        *J += (change - *J * step) * step.transpose() / step.squaredNorm();
        if (!out.modal) keep_own_rows(s, *J);
        x += step;
        r = trial;
        accepted = true;
        break;
      }
    }
    ++out.iterations;
    if (!accepted && fresh) break;
    fresh = false;
    if (!accepted) J.reset();
  }
  out.runs = s.runs;
  out.converged = r && within_tolerance(*r);
  springs = springs_of(s, x);
  for (std::size_t u = 0; u < out.unknowns.size(); ++u) {
    out.unknowns[u].solved = *springs[out.unknowns[u].joints.front()];
  }
  return std::nullopt;
}

SceneResult run_scene_tuned_in_engine(const Scene& scene, const RunOptions& options) {
  Scene base;
  std::vector<std::optional<JointSpring>> springs;
  std::optional<ModalTuningResult> modal;
  EngineTuningResult tuning;
  StageList stages;
  stages.add(Stage::validate);
  if (auto e = engine_tune_scene(scene, options, base, springs, modal, tuning, stages)) {
    SceneResult r;
    r.error = e;
    r.engine = std::string(options.backend->name);
    r.engine_version = std::string(options.backend->version);
    r.stages = stages;
    return r;
  }
  RunOptions confirm = options;
  confirm.springs = springs;
  confirm.springs.resize(base.joints.size());  // never empty: the confirming run is not tuned again
  SceneResult run = run_scene(base, confirm);
  if (!run.stages.items.empty()) run.stages.items.erase(run.stages.items.begin());  // its own validate: ran above
  stages.append(run.stages);
  run.stages = stages;
  if (modal) {
    for (std::size_t g = 0; g < modal->groups.size() && g < tuning.unknowns.size(); ++g) {
      modal->groups[g].stiffness = tuning.unknowns[g].solved.stiffness;
      modal->groups[g].damping = tuning.unknowns[g].solved.damping;
    }
    mark_solved_joints(base, *modal, run.joints);
    run.modal_tuning = std::move(modal);
  }
  confirm_engine_tuning(run, tuning);
  run.engine_tuning = std::move(tuning);
  return run;
}

void confirm_engine_tuning(const SceneResult& run, EngineTuningResult& out) {
  for (EngineTarget& t : out.targets) {
    const ProbeResult* p = probe_named(run, t.probe);
    if (!p) continue;
    t.measured_frequency_hz = p->measured.frequency_hz;
    t.measured_damping_ratio = p->measured.damping_ratio;
    if (t.measured_frequency_hz) t.frequency_error = *t.measured_frequency_hz / t.requested_frequency_hz - 1.0;
    if (t.measured_damping_ratio) t.damping_ratio_error = *t.measured_damping_ratio - t.requested_damping_ratio;
  }
}

}  // namespace softtune::scene
