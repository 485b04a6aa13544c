#include "app/scene_legend.h"

#include <algorithm>
#include <cstdio>
#include <set>

namespace softtune::app {

namespace {

const scene::ProbeResult* measured_probe(const scene::Scene& scene, const scene::SceneResult& result, const std::string& id) {
  for (std::size_t i = 0; i < result.probes.size() && i < scene.probes.size(); ++i) {
    if (scene.probes[i].id == id && result.probes[i].measured.frequency_hz && result.probes[i].measured.damping_ratio)
      return &result.probes[i];
  }
  return nullptr;
}

// The joints a modal tuning solves (their per-joint request is the solve's, not the designer's).
std::set<std::string> grouped_joints(const scene::Scene& scene) {
  std::set<std::string> out;
  if (!scene.modal_tuning) return out;
  for (const scene::JointGroupSettings& g : scene.modal_tuning->groups) out.insert(g.joints.begin(), g.joints.end());
  return out;
}

bool angular_joint(const scene::SceneResult& result, const std::string& id) {
  for (const scene::JointTuning& t : result.joints) {
    if (t.joint == id) return t.angular;
  }
  return false;
}

// "chassis heave: asked 3.00 Hz ζ 0.50 → measured 3.02, ζ 0.48", then "suspension (2 joints): solved k ..., c ...".
void modal_lines(const scene::Scene& scene, const scene::SceneResult& result, std::vector<std::string>& out) {
  const scene::ModalTuningResult& modal = *result.modal_tuning;
  for (const scene::ModalTargetResult& t : modal.targets) {
    char line[200];
    const int n = std::snprintf(line, sizeof line, "%s: asked %.2f Hz \u03b6 %.2f", t.mode.c_str(), t.requested_frequency_hz,
                                t.requested_damping_ratio);
    const scene::ProbeResult* probe = measured_probe(scene, result, t.probe);
    if (probe) {
      std::snprintf(line + n, sizeof line - n, " \u2192 measured %.2f, \u03b6 %.2f", *probe->measured.frequency_hz,
                    *probe->measured.damping_ratio);
    } else {
      std::snprintf(line + n, sizeof line - n, " (not measured)");
    }
    out.push_back(line);
  }
  for (const scene::ModalGroupResult& g : modal.groups) {
    const bool angular = !g.joints.empty() && angular_joint(result, g.joints.front());
    char line[200];
    std::snprintf(line, sizeof line, "%s (%zu joint%s): solved k %.5g %s, c %.5g %s", g.id.c_str(), g.joints.size(),
                  g.joints.size() == 1 ? "" : "s", g.stiffness, angular ? "N m/rad" : "N/m", g.damping,
                  angular ? "N m s/rad" : "N s/m");
    out.push_back(line);
  }
}

}  // namespace

std::vector<std::string> scene_legend(const scene::Scene& scene, const scene::SceneResult& result) {
  std::vector<std::string> out;
  if (result.modal_tuning) modal_lines(scene, result, out);
  const std::set<std::string> grouped = result.modal_tuning ? grouped_joints(scene) : std::set<std::string>{};
  // Joints no probe measures are grouped by what was asked ("hanger_0 … hanger_9 (10): asked ..."), so a
  // bridge's ten hangers take one line and the measured ones stay readable.
  struct Group {
    std::string ask, first, last;
    int count = 0;
  };
  std::vector<Group> unmeasured;
  for (const scene::JointTuning& t : result.joints) {
    if (!t.soft() || grouped.contains(t.joint)) continue;
    const scene::ProbeResult* probe = nullptr;
    for (std::size_t i = 0; i < result.probes.size() && i < scene.probes.size(); ++i) {
      if (scene.probes[i].joint == t.joint && result.probes[i].measured.frequency_hz && !probe) probe = &result.probes[i];
    }
    char ask[96], line[200];
    if (t.typed) {  // the values as typed: nothing was asked, so the line says what they are
      std::snprintf(ask, sizeof ask, "as typed k %.5g, c %.5g", t.stiffness, t.damping);
    } else {
      std::snprintf(ask, sizeof ask, "asked %.2f %s \u03b6 %.2f", t.requested_frequency_hz, t.angular ? "Hz (rot)" : "Hz",
                    t.requested_damping_ratio);
    }
    if (probe && probe->measured.damping_ratio) {
      std::snprintf(line, sizeof line, "%s: %s \u2192 measured %.2f, \u03b6 %.2f", t.joint.c_str(), ask,
                    *probe->measured.frequency_hz, *probe->measured.damping_ratio);
      out.push_back(line);
      continue;
    }
    auto g = std::find_if(unmeasured.begin(), unmeasured.end(), [&](const Group& x) { return x.ask == ask; });
    if (g == unmeasured.end()) g = unmeasured.insert(unmeasured.end(), Group{ask, t.joint, t.joint, 0});
    g->last = t.joint;
    ++g->count;
  }
  for (const Group& g : unmeasured) {
    const std::string who = g.count == 1 ? g.first : g.first + " \u2026 " + g.last + " (" + std::to_string(g.count) + ")";
    out.push_back(who + ": " + g.ask + " (not measured)");
  }
  return out;
}

std::string scene_settings(const scene::Scene& scene) {
  const std::set<std::string> grouped = grouped_joints(scene);
  std::string modes;
  auto add = [&modes](SoftMode mode) {
    const std::string m = mode == SoftMode::exact ? "exact" : "standard";
    if (modes.find(m) == std::string::npos) modes += (modes.empty() ? "" : "+") + m;
  };
  // A modal tuning's mode is its solve's (exact: the step lands on the mode); its joints' own is only the first guess.
  if (scene.modal_tuning) add(scene.modal_tuning->mode);
  for (const scene::JointSettings& j : scene.joints) {
    if (j.tuning && !grouped.contains(j.id)) add(j.tuning->mode);
  }
  char line[160];
  const int substeps = scene.world.substeps;
  std::snprintf(line, sizeof line, "%s%s%g fps \u00d7 %d substep%s", modes.c_str(), modes.empty() ? "" : " \u00b7 ",
                scene.world.fps, substeps, substeps == 1 ? "" : "s");
  return line;
}

}  // namespace softtune::app
