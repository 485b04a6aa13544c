// scene_frames (server/app/scene_frames.cpp): every joint of every preset drawn by its kind, probe trails,
// and the camera of the run keeping the bodies and anchors in view below the title band.
#include "app/scene_frames.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/preset_store.h"
#include "codec/scene_codec.h"
#include "softtune/render/camera_path.h"
#include "softtune/render/frame_schedule.h"
#include "softtune/render/tessellate.h"
#include "softtune/engines/scene_backends.h"
#include "softtune/scene/runner.h"
#include "../presets_dir.h"

namespace softtune::app {
namespace {

using nlohmann::json;

using test_support::kPresets;

struct PresetRun {
  json doc;
  scene::Scene scene;
  std::vector<scene::Snapshot> snapshots;
};

// The preset's snapshots as a 60-frame preview takes them (preview_service.cpp, plan_scene).
PresetRun run(const std::string& name) {
  PresetRun r;
  r.doc = load_preset(kPresets, name);
  r.scene = codec::decode_scene(r.doc);
  scene::RunOptions options;
  options.record_frames = true;
  options.record_at = render::spread_frames(scene::frame_count(r.scene.world), 60);
  r.snapshots = scene::run_scene(r.scene, options).snapshots;
  return r;
}

std::vector<std::string> scene_presets() {
  std::vector<std::string> out;
  for (const std::string& name : list_presets(kPresets)) {
    if (!load_preset(kPresets, name).value("bodies", json::array()).empty()) out.push_back(name);
  }
  return out;
}

// What the preset's JSON asks for, counted from the document itself (not from the decoded scene).
struct Counts {
  int coils = 0, rods = 0, links = 0, targets = 0, pins = 0, welds = 0;
};

Counts asked(const json& doc) {
  Counts c;
  for (const json& j : doc.value("joints", json::array())) {
    const std::string type = j.at("type");
    const bool tuned = j.contains("response_frames") || j.contains("frequency_hz");
    if (type == "wheel" || (type == "distance" && tuned)) ++c.coils;
    if (type == "distance" && !tuned) ++c.rods;
    if (type == "mouse") ++c.links, ++c.targets;
    if (type == "weld" || type == "revolute") ++c.pins;
    if (type == "weld") ++c.welds;
  }
  return c;
}

Counts drawn(const render::DrawFrame& f) {
  Counts c;
  for (const render::SpringShape& s : f.springs) {
    c.coils += s.style == render::SpringStyle::coil;
    c.rods += s.style == render::SpringStyle::rod;
    c.links += s.style == render::SpringStyle::link;
  }
  c.targets = static_cast<int>(f.targets.size());
  c.pins = static_cast<int>(f.pins.size());
  for (const render::PinShape& p : f.pins) c.welds += p.weld;
  return c;
}

TEST(SceneFrames, EveryJointOfEveryPresetIsDrawnByItsKind) {
  const auto names = scene_presets();
  ASSERT_GE(names.size(), 5u);
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const PresetRun r = run(name);
    ASSERT_FALSE(r.snapshots.empty());
    const Counts want = asked(r.doc);
    for (int i : {0, static_cast<int>(r.snapshots.size()) - 1}) {
      const Counts got = drawn(scene_frame(r.scene, r.snapshots, i));
      EXPECT_EQ(got.coils, want.coils);
      EXPECT_EQ(got.rods, want.rods);
      EXPECT_EQ(got.links, want.links);
      EXPECT_EQ(got.targets, want.targets);
      EXPECT_EQ(got.pins, want.pins);
      EXPECT_EQ(got.welds, want.welds);
    }
  }
}

TEST(SceneFrames, WheelSpringRunsFromTheChassisMountToTheWheelCentre) {
  const PresetRun r = run("vehicle");
  const render::DrawFrame f = scene_frame(r.scene, r.snapshots, 0);
  ASSERT_EQ(f.springs.size(), 2u);
  // vehicle.json: chassis centre 0.6 m above the wheels on a vertical axis: a 0.6 m spring at rest, ending at
  // the wheel centre (0.405 m: where Box2D's contact leaves a 0.4 m wheel on the road, docs/scenes.md).
  const double wheel_y = r.doc["bodies"][2]["position"][1].get<double>();
  for (const render::SpringShape& s : f.springs) {
    EXPECT_NEAR(s.rest_length_m, 0.6, 1e-6);
    EXPECT_NEAR(s.b_m.y, wheel_y, 1e-6);
    EXPECT_NEAR(s.a_m.y - s.b_m.y, 0.6, 1e-6);
    EXPECT_NEAR(s.a_m.x, s.b_m.x, 1e-6);
  }
  // Later the chassis has sat down on its springs: compressed below the rest length (gravity on 120 kg).
  const render::DrawFrame later = scene_frame(r.scene, r.snapshots, 15);
  for (const render::SpringShape& s : later.springs) EXPECT_LT(*s.current_length_m, s.rest_length_m);
}

TEST(SceneFrames, MouseTargetIsTheJointsTargetAndTheLinkEndsOnTheCrate) {
  const PresetRun r = run("mouse");
  const render::DrawFrame f = scene_frame(r.scene, r.snapshots, 0);
  ASSERT_EQ(f.targets.size(), 1u);
  EXPECT_NEAR(f.targets[0].at_m.x, r.scene.joints[0].target.x(), 1e-6);
  EXPECT_NEAR(f.targets[0].at_m.y, r.scene.joints[0].target.y(), 1e-6);
  ASSERT_EQ(f.springs.size(), 1u);
  EXPECT_NEAR(f.springs[0].a_m.x, r.scene.joints[0].target.x(), 1e-6);
  EXPECT_NEAR(f.springs[0].b_m.x, r.scene.joints[0].anchor_b.x(), 1e-6);
}

TEST(SceneFrames, ProbedPointsLeaveATrailOfTheLastHalfSecond) {
  const PresetRun r = run("mouse");
  const int last = static_cast<int>(r.snapshots.size()) - 1;
  const render::DrawFrame first = scene_frame(r.scene, r.snapshots, 0);
  const render::DrawFrame f = scene_frame(r.scene, r.snapshots, last);
  EXPECT_TRUE(first.trails.empty());  // one point is no path yet
  ASSERT_EQ(f.trails.size(), trailed_points(r.scene).size());
  // Every snapshot of the last half second (the frames fall on game frames, so their gaps differ by a step).
  int within = 0;
  for (const scene::Snapshot& s : r.snapshots) within += r.snapshots[last].time_s - s.time_s <= kTrailSeconds + 1e-9;
  EXPECT_GE(within, 8);  // 0.5 s at about 0.05 s a frame
  for (const render::Trail& t : f.trails) EXPECT_EQ(static_cast<int>(t.points_m.size()), within);
}

// The Bar: on every preset and every frame, each moving body's box and every joint point lies inside the
// view below the title band; with camera.follow, the followed body and what is joined to it does.
TEST(SceneFrames, CameraKeepsBodiesAndAnchorsInViewBelowTheBand) {
  for (const std::string& name : scene_presets()) {
    SCOPED_TRACE(name);
    const PresetRun r = run(name);
    const render::FrameSet set = scene_frames(r.scene, r.snapshots);
    for (render::ImageSize size : {render::ImageSize{640, 360}, render::ImageSize{360, 640}}) {
      const auto cameras = render::run_cameras(set.camera, set.follow, set.frames, size);
      ASSERT_EQ(cameras.size(), set.frames.size());
      for (std::size_t i = 0; i < set.frames.size(); ++i) {
        const render::Bounds view = render::visible_below_band(cameras[i], size);
        const auto inside = [&](render::Vec2 p) {
          return p.x >= view.lo.x - 1e-9 && p.x <= view.hi.x + 1e-9 && p.y >= view.lo.y - 1e-9 && p.y <= view.hi.y + 1e-9;
        };
        if (!r.scene.camera.follow.empty()) {
          const render::Bounds b = set.follow.bounds_m[i];
          EXPECT_TRUE(inside(b.lo) && inside(b.hi)) << "frame " << i;
          continue;
        }
        const render::DrawFrame& f = set.frames[i];
        for (const render::PolygonShape& p : f.polygons) {
          if (p.role == render::Role::static_body) continue;
          for (render::Vec2 v : p.vertices_m) EXPECT_TRUE(inside(v)) << "frame " << i;
        }
        for (const render::CircleShape& c : f.circles) {
          EXPECT_TRUE(inside({c.centre_m.x - c.radius_m, c.centre_m.y - c.radius_m}) &&
                      inside({c.centre_m.x + c.radius_m, c.centre_m.y + c.radius_m}))
              << "frame " << i;
        }
        for (const render::PinShape& p : f.pins) EXPECT_TRUE(inside(p.at_m)) << "frame " << i;
        for (const render::AnchorDot& a : f.anchors) EXPECT_TRUE(inside(a.at_m)) << "frame " << i;
        for (const render::TargetShape& t : f.targets) EXPECT_TRUE(inside(t.at_m)) << "frame " << i;
      }
    }
  }
}

// The stiff preset (20 Hz at 60 fps, omega h = 2.1): explicit and semi-implicit Euler leave the frame
// (semi-implicit Euler is stable only for omega h < 2), the core soft spring does not; each is drawn beside
// the Box2D spring until then, and after it its divergence trail and "left the view at t = T s (frame K)".
TEST(SceneFrames, StiffPresetDrawsTheOscillatorsUntilTheyBlowUp) {
  PresetRun r = run("stiff");
  scene::RunOptions options;
  options.record_frames = true;
  const scene::SceneResult result = scene::run_scene(r.scene, options);
  const double rest = *r.scene.joints[0].length;
  ASSERT_EQ(result.oscillators.size(), 3u);
  std::vector<int> left;
  for (const scene::OscillatorRun& o : result.oscillators) left.push_back(left_frame_at(o, kOscillatorLimit * rest));
  EXPECT_GT(left[0], 0);   // explicit Euler
  EXPECT_GT(left[1], 0);   // semi-implicit Euler
  EXPECT_EQ(left[2], -1);  // soft: calm
  const render::FrameSet set = scene_frames(r.scene, result.snapshots, &result);
  const auto labels_with = [](const render::DrawFrame& f, const std::string& text) {
    int n = 0;
    for (const render::Label& l : f.labels) n += l.text.find(text) != std::string::npos;
    return n;
  };
  // Frame 0: the Box2D spring and all three copies, each a block and a spring.
  EXPECT_EQ(set.frames[0].springs.size(), 4u);
  EXPECT_EQ(labels_with(set.frames[0], "blew up"), 0);
  const int late = std::max(left[0], left[1]);
  const render::DrawFrame& f = set.frames[late];
  EXPECT_EQ(f.springs.size(), 2u);  // Box2D and the core soft spring
  // Every game frame is a preview frame here, so each left at the frame of its game frame, at that time.
  for (int k : {0, 1}) {
    char label[64];
    std::snprintf(label, sizeof label, "left the view\nat t = %.2f s (frame %d)", left[k] / 60.0, left[k]);
    EXPECT_EQ(labels_with(f, label), 1) << label;
  }
  // Its divergence: a trail of its last steps, the last one out past the limit.
  int divergent = 0;
  for (const render::Trail& t : f.trails) {
    if (!t.divergent) continue;
    ++divergent;
    EXPECT_EQ(static_cast<int>(t.points_m.size()), std::min(kDivergenceTrailFrames, left[divergent - 1]) + 1);
  }
  EXPECT_EQ(divergent, 2);
  // Until a copy leaves, its block sits at rest + x along the joint: it stays within the limit.
  for (const render::SpringShape& s : set.frames[left[0] - 1].springs) {
    EXPECT_LE(std::abs(*s.current_length_m - rest), kOscillatorLimit * rest + 1e-9);
  }
}

// The Bar: the caption, settings and legend land inside the title band, across the image, at both
// aspect ratios and at the smallest and largest sizes; the legend names every tuned joint.
TEST(SceneFrames, TextLandsInsideTheTitleBand) {
  for (const std::string& name : scene_presets()) {
    SCOPED_TRACE(name);
    PresetRun r = run(name);
    scene::RunOptions options;
    options.record_frames = true;
    options.record_at = render::spread_frames(scene::frame_count(r.scene.world), 60);
    const scene::SceneResult result = scene::run_scene(r.scene, options);
    const render::FrameSet set = scene_frames(r.scene, result.snapshots, &result);
    // Every tuned joint a probe measures has its line; the others are grouped, so no more lines than joints.
    // A modally tuned scene has a line per target and per group instead of its grouped joints' lines.
    const std::vector<std::string>& legend = set.frames.front().legend;
    int tuned = 0;
    for (const scene::JointSettings& j : r.scene.joints) tuned += j.tuning.has_value();
    const auto& modal = r.scene.modal_tuning;
    EXPECT_LE(static_cast<int>(legend.size()), tuned + (modal ? static_cast<int>(modal->targets.size()) : 0));
    EXPECT_EQ(legend.empty(), tuned == 0);
    for (std::size_t p = 0; p < result.probes.size(); ++p) {
      const std::string& joint = r.scene.probes[p].joint;
      if (joint.empty() || !result.probes[p].measured.frequency_hz || !result.probes[p].measured.damping_ratio) continue;
      bool tuned_joint = false;
      for (const scene::JointSettings& j : r.scene.joints) tuned_joint = tuned_joint || (j.id == joint && j.tuning);
      for (const scene::JointGroupSettings& g : modal ? modal->groups : std::vector<scene::JointGroupSettings>{}) {
        tuned_joint = tuned_joint && std::find(g.joints.begin(), g.joints.end(), joint) == g.joints.end();
      }
      if (!tuned_joint) continue;
      const auto has = [&](const std::string& line) { return line.rfind(joint + ": asked", 0) == 0; };
      EXPECT_TRUE(std::any_of(legend.begin(), legend.end(), has)) << joint;
    }
    for (render::ImageSize size : {render::ImageSize{640, 360}, render::ImageSize{360, 640},
                                   render::ImageSize{1920, 1080}, render::ImageSize{160, 90}}) {
      const auto cameras = render::run_cameras(set.camera, set.follow, set.frames, size);
      // The band grows for a long legend (caption_band) rather than shrink the text below 11 px.
      const double band = render::caption_band(size, static_cast<int>(legend.size())) * size.height;
      for (std::size_t i : {std::size_t{0}, set.frames.size() - 1}) {
        const auto texts = render::layout_text_overlay(set.frames[i], render::make_view(cameras[i], size));
        // The smallest size keeps the whole lines that fit (a long scene name leaves no room for the settings).
        ASSERT_GE(texts.size(), size.width >= 360 ? 2u : 1u);
        for (const render::PlacedText& t : texts) {
          if (!t.in_band) continue;
          EXPECT_GE(t.box.left, 0) << t.text;
          EXPECT_GE(t.box.top, 0) << t.text;
          EXPECT_LE(t.box.right, size.width) << t.text << " at " << size.width << "x" << size.height;
          EXPECT_LE(t.box.bottom, band) << t.text << " at " << size.width << "x" << size.height;
        }
      }
    }
  }
}

// Frames from another engine's run name it first in their settings line; Box2D 2.4's keep theirs unchanged.
TEST(SceneFrames, AnotherEnginesFramesNameIt) {
  const scene::Scene s = codec::decode_scene(load_preset(kPresets, "buddhas"));
  for (const char* name : {"box2d_v2_4", "ode"}) {
    scene::RunOptions options;
    options.record_frames = true;
    options.record_at = {0, 30};
    options.backend = engines::find_scene_backend(name);
    ASSERT_TRUE(options.backend) << name;
    const scene::SceneResult result = scene::run_scene(s, options);
    ASSERT_FALSE(result.error) << result.error->field;
    const render::FrameSet set = scene_frames(s, result.snapshots, &result, default_layers(s));
    ASSERT_EQ(set.frames.size(), 2u);
    const bool named = set.frames[1].settings.rfind(std::string(name) + " \u00b7 ", 0) == 0;
    EXPECT_EQ(named, std::string(name) != "box2d_v2_4") << set.frames[1].settings;
  }
}

}  // namespace
}  // namespace softtune::app
