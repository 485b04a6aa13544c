// The modes codec (server/codec/modes_codec.cpp): a scene's modal_tuning read strictly (paths in problems), a
// mode written with its poles and components, and a run's modal tuning with the measured figure taken from the
// target's probe fit.
#include "codec/modes_codec.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

namespace softtune::codec {
namespace {

using nlohmann::json;

scene::ModalTuningSettings read(const json& doc) {
  ObjectReader r = read_object(doc, "modal_tuning");
  scene::ModalTuningSettings m = read_modal_tuning(r);
  r.finish();
  return m;
}

std::string problem_field(const json& doc) {
  try {
    read(doc);
  } catch (const Problem& p) {
    return p.field;
  }
  return "(no problem)";
}

TEST(ModesCodec, ReadsModalTuning) {
  const auto m = read({{"mode", "exact"}, {"at_s", 1.5}, {"groups", {{{"id", "springs"}, {"joints", {"a", "b"}}}}},
                       {"targets", {{{"mode", "pitch"}, {"body", "chassis"}, {"frequency_hz", 2.0}, {"oscillation", "none"}}}}});
  EXPECT_EQ(m.mode, SoftMode::exact);
  EXPECT_EQ(*m.at_s, 1.5);
  ASSERT_EQ(m.groups.size(), 1u);
  EXPECT_EQ(m.groups[0].joints, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(m.targets.size(), 1u);
  EXPECT_EQ(m.targets[0].motion, "pitch");  // a target's "mode" is the motion, not standard | exact
  EXPECT_EQ(*m.targets[0].tuning.frequency_hz, 2.0);
  EXPECT_EQ(m.targets[0].tuning.mode, SoftMode::standard);
}

TEST(ModesCodec, RefusalsNameTheDottedField) {
  const json group = {{"id", "g"}, {"joints", {"a"}}};
  EXPECT_EQ(problem_field({{"groups", {group}}}), "modal_tuning.targets");
  EXPECT_EQ(problem_field({{"groups", {group}}, {"targets", {{{"body", "b"}, {"mode", "heave"}}}}}), "modal_tuning.targets.0.frequency_hz");
  EXPECT_EQ(problem_field({{"groups", {{{"id", "g"}, {"joints", {1}}}}}, {"targets", json::array()}}), "modal_tuning.groups.0.joints.0");
  EXPECT_EQ(problem_field({{"groups", {group}}, {"targets", {{{"body", "b"}, {"frequency_hz", 1}, {"oscillation", "some"}, {"speed", 1}}}}}),
            "modal_tuning.targets.0.speed");
  EXPECT_EQ(problem_field({{"groups", {group}}, {"targets", {{{"body", "b"}, {"frequency_hz", -1}, {"oscillation", "some"}}}}}),
            "modal_tuning.targets.0.frequency_hz");
}

TEST(ModesCodec, WritesModesWithoutNaN) {
  modes::Mode m;
  m.name = "chassis heave";
  m.undamped_frequency_hz = 1.3;
  m.continuous = modes::Pole{1.3, 0.2};
  m.components = {{0, modes::Dof::y, 1.0, 0.9}, {1, modes::Dof::angle, 0.1, 0.1}};
  modes::Mode free;
  free.name = "chassis surge";
  free.free = true;
  const json out = modes_json({free, m}, {"chassis", "wheel"});
  EXPECT_TRUE(out[0]["continuous"].is_null());
  EXPECT_TRUE(out[1]["discrete"].is_null());
  EXPECT_EQ(out[1]["components"][1]["body"], "wheel");
  EXPECT_EQ(out[1]["components"][1]["coordinate"], "angle");
  EXPECT_EQ(out[1]["components"][1]["motion"], "pitch");
}

TEST(ModesCodec, TargetIsMeasuredByItsProbe) {
  scene::ModalTuningResult modal;
  scene::ModalTargetResult t;
  t.mode = "chassis heave";
  t.probe = "travel";
  t.requested_frequency_hz = 3.0;
  t.requested_damping_ratio = 0.5;
  t.predicted = modes::Pole{3.0, 0.5};
  modal.targets = {t};
  scene::SceneResult run;
  scene::ProbeResult p;
  p.id = "travel";
  p.measured.frequency_hz = 3.03;
  p.measured.damping_ratio = 0.48;
  run.probes = {p};
  const json out = modal_tuning_json(scene::Scene{}, modal, run);
  EXPECT_NEAR(out["targets"][0]["error"]["frequency"].get<double>(), 0.01, 1e-12);
  EXPECT_NEAR(out["targets"][0]["error"]["damping_ratio"].get<double>(), -0.02, 1e-12);
  modal.targets[0].probe = "";
  EXPECT_TRUE(modal_tuning_json(scene::Scene{}, modal, run)["targets"][0]["measured"].is_null());
}

}  // namespace
}  // namespace softtune::codec
