#include "codec/modes_codec.h"

#include "codec/joint_answer_codec.h"
#include "codec/json_writer.h"
#include "codec/list_reader.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "codec/tune_codec.h"

namespace softtune::codec {
namespace {

using nlohmann::json;
using namespace softtune::scene;

json pole_json(const std::optional<modes::Pole>& p) {
  if (!p) return nullptr;
  return {{"frequency_hz", number_or_null(p->frequency_hz)}, {"damping_ratio", number_or_null(p->damping_ratio)}};
}

std::string_view coordinate_name(modes::Dof d) {
  switch (d) {
    case modes::Dof::x: return "x";
    case modes::Dof::y: return "y";
    case modes::Dof::angle: return "angle";
  }
  return "";
}


const ProbeResult* find_probe(const SceneResult& run, const std::string& id) {
  for (const ProbeResult& p : run.probes) {
    if (p.id == id) return &p;
  }
  return nullptr;
}

}  // namespace

ModalTuningSettings read_modal_tuning(ObjectReader& r) {
  ModalTuningSettings m;
  if (auto mode = r.choice("mode", {"standard", "exact"})) m.mode = static_cast<SoftMode>(*mode);
  m.at_s = r.number("at_s");
  read_object_list(r, "groups", true, [&](ObjectReader& g, const std::string&) {
    JointGroupSettings group;
    group.id = g.string("id").value_or("");
    const json* joints = g.raw("joints");
    if (!joints || !joints->is_array()) throw invalid_field(g.field("joints"), "must be an array of joint ids");
    for (std::size_t k = 0; k < joints->size(); ++k) {
      if (!(*joints)[k].is_string()) throw invalid_field(g.field("joints") + "." + std::to_string(k), "must be a joint id");
      group.joints.push_back((*joints)[k].get<std::string>());
    }
    m.groups.push_back(std::move(group));
  });
  read_object_list(r, "targets", true, [&](ObjectReader& t, const std::string& path) {
    ModeTargetSettings target;
    target.probe = t.string("probe").value_or("");
    target.body = t.string("body").value_or("");
    target.motion = t.string("mode").value_or("");
    auto tuning = read_designer_fields(t, path, false);
    if (!tuning) throw invalid_field(path + ".frequency_hz", "give response_frames or frequency_hz, and oscillation or damping_ratio");
    target.tuning = *tuning;
    m.targets.push_back(std::move(target));
  });
  return m;
}

json modes_json(const std::vector<modes::Mode>& all, const std::vector<std::string>& body_ids) {
  json out = json::array();
  for (const modes::Mode& m : all) {
    json components = json::array();
    for (const modes::ShapeComponent& c : m.components) {
      components.push_back({{"body", body_ids[c.body]}, {"coordinate", coordinate_name(c.dof)}, {"motion", modes::dof_word(c.dof)},
                            {"amplitude", number_or_null(c.amplitude)}, {"share", number_or_null(c.share)}});
    }
    out.push_back({{"name", m.name}, {"free", m.free}, {"unstable", m.unstable},
                   {"undamped_frequency_hz", number_or_null(m.undamped_frequency_hz)},
                   {"continuous", pole_json(m.continuous)}, {"discrete", pole_json(m.discrete)},
                   {"components", std::move(components)}});
  }
  return out;
}

json modal_tuning_json(const Scene& scene, const ModalTuningResult& modal, const SceneResult& run) {
  json groups = json::array(), joints = json::array(), targets = json::array();
  for (const ModalGroupResult& g : modal.groups) {
    groups.push_back({{"id", g.id}, {"joints", g.joints}, {"stiffness", number_or_null(g.stiffness)}, {"damping", number_or_null(g.damping)}});
    for (const std::string& id : g.joints) {
      for (std::size_t i = 0; i < run.joints.size(); ++i) {
        const JointTuning& t = run.joints[i];
        if (t.joint != id) continue;
        const json answer = scene_joint_json(scene, run, i);
        // The joint's solved numbers, and each engine's values for them (joint_answer_codec.h: Box2D 2.4 the run's).
        const json tune = t.solved && t.solved->joint_export ? encode_tune_result(TuneRequest{}, *t.solved->joint_export)
                                                             : encode_tune_result(TuneRequest{}, t.result);
        joints.push_back({{"id", id}, {"group", g.id}, {"effective_mass", number_or_null(t.effective_mass)},
                          {"k", number_or_null(t.stiffness)}, {"c", number_or_null(t.damping)}, {"gamma", tune["gamma"]},
                          {"beta", tune["beta"]}, {"erp", tune["erp"]}, {"cfm", tune["cfm"]},
                          {"engines", answer["engines"]}, {"warnings", answer["warnings"]}});
      }
    }
  }
  for (const ModalTargetResult& t : modal.targets) {
    json measured = nullptr, error = nullptr;
    if (const ProbeResult* p = find_probe(run, t.probe); p && p->measured.frequency_hz && p->measured.damping_ratio) {
      measured = {{"frequency_hz", number_or_null(p->measured.frequency_hz)}, {"damping_ratio", number_or_null(p->measured.damping_ratio)}};
      error = {{"frequency", number_or_null(*p->measured.frequency_hz / t.requested_frequency_hz - 1.0)},
               {"damping_ratio", number_or_null(*p->measured.damping_ratio - t.requested_damping_ratio)}};
    }
    const json why = measured.is_null() ? target_measurement(run, t)["why"] : json();
    targets.push_back({{"mode", t.mode}, {"probe", t.probe.empty() ? json() : json(t.probe)}, {"unmeasured", why},
                       {"requested", {{"frequency_hz", number_or_null(t.requested_frequency_hz)}, {"damping_ratio", number_or_null(t.requested_damping_ratio)}}},
                       {"predicted", pole_json(t.predicted)}, {"continuous", pole_json(t.continuous)}, {"discrete", pole_json(t.discrete)},
                       {"measured", std::move(measured)}, {"error", std::move(error)}});
  }
  return {{"groups", std::move(groups)}, {"joints", std::move(joints)}, {"targets", std::move(targets)},
          {"residual", number_or_null(modal.residual)}, {"least_squares", modal.least_squares}, {"iterations", modal.iterations},
          {"rounds", modal.rounds}, {"start_stiffenings", modal.start_stiffenings},
          {"fell_back_to_standard", modal.fell_back_to_standard}, {"at_s", number_or_null(modal.at_s)}, {"settled", modal.settled}, {"modes", modes_json(modal.modes, modal.body_ids)}};
}

json linearisation_json(const std::string& name, const LinearisedScene& lin, const std::vector<modes::Mode>& all, const StageList& stages) {
  std::vector<std::string> ids;
  for (const auto& b : lin.model.bodies) ids.push_back(b.id);
  return {{"name", name}, {"stages", stages_json(stages)}, {"at_s", number_or_null(lin.at_s)}, {"settled", lin.settled},
          {"h", number_or_null(lin.h)}, {"bodies", lin.model.bodies.size()}, {"rows", lin.model.rows.size()},
          {"contact_points", lin.contact_points}, {"balance_residual", number_or_null(lin.balance_residual)},
          {"modes", modes_json(all, ids)}};
}

}  // namespace softtune::codec
