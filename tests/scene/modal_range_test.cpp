// The modal solve over every request the page can send (web/index.html: response_frames 1..120 frames at
// basis 60 fps, oscillation free | some | none, the page's standard | exact, at 30, 60, 120 and 144 fps): the
// vehicle's chassis heave and the bridge deck's fundamental are found and reached for each one, exactly as
// the page asks (app::apply_scene_tuning on the preset), the predicted pole on the request. The only refusals
// allowed are the truly unreachable ones, each checked against its own physics: a frequency beyond what the step
// represents in exact mode (omega_d h >= 0.99 pi, exact_max_omega), and a heave so soft that the static sag
// g / omega^2 is more than 0.9 of the body's clearance (the chassis then rests on the road: no spring moves it).
// The preset's own exact "some" is swept at every frame count, the other combinations at every fourth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "app/preset_store.h"
#include "app/scene_tuning.h"
#include "codec/scene_codec.h"
#include "softtune/designer.h"
#include "softtune/exact_softness.h"
#include "softtune/scene/modal_tuning.h"
#include "../presets_dir.h"
#include "softtune/support/sanitizer_build.h"

namespace softtune::scene {
namespace {

constexpr double kRangeBasisFps = 60.0;  // the page's default basis; its slider counts 1..120 frames
constexpr int kRangeMaxFrames = 120;

struct RangeCase {
  std::string preset;
  double clearance_m;  // how far the targeted body can sag before it rests on something (from the preset)
  // Requests the solve still refuses although the physics above does not forbid them: known gaps, reported
  // (docs/scenes.md, "Tuning the modes"), listed here so that nothing else may join them unnoticed.
  double gap_below_hz = 0.0;  // every request slower than this
  std::vector<std::tuple<double, int, std::string>> gap_points = {};  // exact mode: (fps, frames, oscillation)
};

// One request as the page sends it for a preset: the sliders' tuning on every tuned joint and on the target.
std::optional<FieldError> tune_as_page(const RangeCase& c, double fps, int frames, const std::string& oscillation,
                                       const std::string& mode, ModalTuningResult& out) {
  nlohmann::json doc = app::load_preset(test_support::kPresets, c.preset);
  app::apply_scene_tuning(doc, {{"fps", fps}, {"substeps", 1}, {"response_frames", frames}, {"basis_fps", kRangeBasisFps},
                                {"oscillation", oscillation}, {"mode", mode}});
  const Scene scene = codec::decode_scene(doc);
  Scene tuned;
  StageList stages;
  return tune_modes(scene, MassModel::effective, out, tuned, stages);
}

// Refusals the physics forces: the step cannot represent the pole, or the sag leaves no travel.
bool truly_unreachable(const RangeCase& c, double fps, double f_hz, double zeta, bool exact, const FieldError& e) {
  const double omega = 2.0 * std::numbers::pi * f_hz;
  if (exact && omega >= exact_max_omega(zeta, 1.0 / fps)) return e.field.ends_with(".frequency_hz");
  const double sag = 10.0 / (omega * omega);
  return sag > 0.9 * c.clearance_m && e.rule.find("let the scene rest with") != std::string::npos;
}

// Under ASan/UBSan and TSan (sanitizer_build.h) the solve runs 20-50 times slower: the bridge deck's full
// sweep (35 s in Release) overran ctest's 900 s there, so the sanitizer builds sweep every 8th request.
constexpr int kRangeStrideScale = SOFTTUNE_SANITIZED_BUILD ? 24 : 1;  // 141 s under ASan at 8

void sweep(const RangeCase& c) {
  int refused = 0, unreachable = 0, gaps = 0;
  for (const std::string mode : {"exact", "standard"}) {
    for (double fps : {30.0, 60.0, 120.0, 144.0}) {
      for (const std::string oscillation : {"free", "some", "none"}) {
        const double zeta = damping_ratio_of(oscillation == "free" ? Oscillation::free : oscillation == "some" ? Oscillation::some : Oscillation::none);
        // Every frame count for the preset's own exact "some"; every fourth (and the slowest) for the others.
        const int stride = kRangeStrideScale * (mode == "exact" && oscillation == "some" ? 1 : 4);
        for (int frames = 1; frames <= kRangeMaxFrames; frames = frames == kRangeMaxFrames ? frames + 1 : std::min(frames + stride, kRangeMaxFrames)) {
          const double f = kRangeBasisFps / frames;
          ModalTuningResult r;
          const auto e = tune_as_page(c, fps, frames, oscillation, mode, r);
          if (!e) {
            ASSERT_EQ(r.targets.size(), 1u);
            ASSERT_TRUE(r.targets[0].predicted);
            EXPECT_NEAR(r.targets[0].predicted->frequency_hz / f, 1.0, 1e-6) << c.preset << " " << mode << " " << fps << " " << frames << " " << oscillation;
            EXPECT_NEAR(r.targets[0].predicted->damping_ratio, zeta, 1e-6) << c.preset << " " << mode << " " << fps << " " << frames << " " << oscillation;
            continue;
          }
          ++refused;
          const bool allowed = truly_unreachable(c, fps, f, zeta, mode == "exact", *e);
          unreachable += allowed;
          const bool gap = f < c.gap_below_hz || (mode == "exact" && std::find(c.gap_points.begin(), c.gap_points.end(),
                                                                               std::make_tuple(fps, frames, oscillation)) != c.gap_points.end());
          gaps += gap && !allowed;
          if (gap) continue;
          EXPECT_TRUE(allowed) << c.preset << " " << mode << " fps " << fps << " frames " << frames << " (" << f << " Hz) "
                               << oscillation << ": " << e->field << ": " << e->rule;
        }
      }
    }
  }
  std::printf("%s: %d refused, %d of them truly unreachable, %d known gaps\n", c.preset.c_str(), refused, unreachable, gaps);
}

// The chassis box's bottom is 0.75 m above the road at the springs' rest length (vehicle.json). Two exact
// requests next to what the step represents still stall: 60 Hz critically damped at 30 fps (omega h = 12.6, the
// poles at z ~ 3e-6) and 30 Hz at 60 fps (omega_d h = 0.87 pi).
TEST(ModalRange, VehicleHeaveOverThePageRange) {
  sweep({"vehicle", 0.75, 0.0, {{30.0, 1, "none"}, {60.0, 2, "some"}}});
}

// Nothing under the deck: no sag limit. Slower than 1.65 Hz (37 frames and more at basis 60) the solve drives
// the hangers' k towards 0 and the deck hangs on its pins alone, whose own fundamental (0.96-2.2 Hz, depending on
// the rest state each round reaches) it cannot get under reliably: a known gap, refused naming the target.
// The same critically damped 60 Hz at 30 fps as the vehicle's has no per-joint request within the tune contract.
TEST(ModalRange, BridgeDeckFundamentalOverThePageRange) { sweep({"bridge_deck", 100.0, 1.65, {{30.0, 1, "none"}}}); }

}  // namespace
}  // namespace softtune::scene
