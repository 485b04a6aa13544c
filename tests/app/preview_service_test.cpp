// PreviewService (server/app/preview_service.cpp): how many requests may wait for frames at once, and
// frames that span the whole run of every preset, with their manifest.
#include "app/preview_service.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <future>
#include <mutex>
#include <stdexcept>

#include "../presets_dir.h"
#include "codec/problem.h"
#include "softtune/render/camera_path.h"
#include "softtune/render/tessellate.h"

namespace softtune::codec {
namespace {

using namespace softtune::app;

using nlohmann::json;

// A renderer that holds every frame until the test opens the gate.
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  bool open = false;
  void release() {
    std::lock_guard lock(m);
    open = true;
    cv.notify_all();
  }
  void pass() {
    std::unique_lock lock(m);
    cv.wait(lock, [this] { return open; });
  }
};

class GatedRenderer final : public render::Renderer {
 public:
  explicit GatedRenderer(Gate& gate) : gate_(gate) {}
  void render(const render::DrawFrame&, const render::Camera&, render::ImageSize, std::span<std::uint8_t> rgba) override {
    gate_.pass();
    std::fill(rgba.begin(), rgba.end(), std::uint8_t{255});
  }

 private:
  Gate& gate_;
};

json oscillator(int response_frames) {
  return {{"response_frames", response_frames}, {"oscillation", "some"}, {"effective_mass", 1},
          {"frames", 2}, {"size", "32x18"}};
}

bool has_warning(const json& answer, const std::string& code) {
  for (const json& w : answer["warnings"]) {
    if (w["code"] == code) return true;
  }
  return false;
}

TEST(PreviewService, PastTheWaiterCapARequestIsAnsweredAtOnceAndStillRendered) {
  Gate gate;
  render::PipelineOptions options;
  options.make_renderer = [&gate] { return std::make_unique<GatedRenderer>(gate); };
  PreviewService service(options, 1);

  // The first request waits (its frames are held at the gate) ...
  auto first = std::async(std::launch::async, [&] { return service.start(oscillator(12), "", "/p"); });
  ASSERT_EQ(first.wait_for(std::chrono::milliseconds(200)), std::future_status::timeout);
  // ... so the second may not: it is answered at once with a progress URL and says why.
  auto declined = std::async(std::launch::async, [&] { return service.start(oscillator(13), "", "/p"); });
  if (declined.wait_for(std::chrono::seconds(5)) != std::future_status::ready) {
    ADD_FAILURE() << "the second request waited for its frames too";
    gate.release();
  }
  const json second = declined.get();
  EXPECT_EQ(second["status"], "rendering");
  EXPECT_TRUE(has_warning(second, "wait_declined")) << second.dump();

  gate.release();
  const json done = first.get();
  EXPECT_EQ(done["status"], "done");
  EXPECT_FALSE(has_warning(done, "wait_declined"));
  // The declined request's render went on; asking again waits for it or finds it done.
  const json again = service.start(oscillator(13), "", "/p");
  EXPECT_EQ(again["status"], "done");
  EXPECT_EQ(again["id"], second["id"]);
  EXPECT_FALSE(has_warning(again, "wait_declined"));
}

// Whether the frames fail while the request waits or before it looks, the answer is the same problem.
TEST(PreviewService, FailedFramesAreARenderFailedProblem) {
  struct Failing final : public render::Renderer {
    void render(const render::DrawFrame&, const render::Camera&, render::ImageSize, std::span<std::uint8_t>) override {
      throw std::runtime_error("injected GL fault");
    }
  };
  render::PipelineOptions options;
  options.make_renderer = [] { return std::make_unique<Failing>(); };
  PreviewService service(options);
  for (int attempt = 0; attempt < 100; ++attempt) {
    try {
      service.start(oscillator(12 + attempt), "", "/p");
      ADD_FAILURE() << "a failed preview was answered";
    } catch (const Problem& p) {
      EXPECT_EQ(p.status, 500);
      EXPECT_EQ(p.title, "Render failed");
      EXPECT_NE(p.detail.find("injected GL fault"), std::string::npos) << p.detail;
    }
  }
}

// Every preset in presets/ (the schema aside), with its world's fps and duration read from the file.
struct PresetRun {
  std::string name;
  double fps = 0.0, duration_s = 0.0;
};
std::vector<PresetRun> preset_runs() {
  std::vector<PresetRun> out;
  for (const auto& entry : std::filesystem::directory_iterator(test_support::kPresets)) {
    if (entry.path().extension() != ".json" || entry.path().stem() == "schema") continue;
    const json doc = json::parse(std::ifstream(entry.path()));
    out.push_back({entry.path().stem().string(), doc.at("world").at("fps").get<double>(),
                   doc.at("world").at("duration_s").get<double>()});
  }
  return out;
}

TEST(PreviewService, FramesSpanTheWholeRunOfEveryPresetAtAnyFrameCount) {
  // The old stride, rounded down, ended chain's 300 frames at 4.98 s of 8 s and bridge's 120 at 3.97 of 5.
  const std::vector<PresetRun> presets = preset_runs();
  ASSERT_GE(presets.size(), 10u);
  for (const PresetRun& p : presets) {
    const int run_frames = static_cast<int>(std::lround(p.duration_s * p.fps));
    const double run_end = run_frames / p.fps;
    for (const int frames : {2, 53, 120, 300}) {
      PreviewPlan plan = plan_preview({{"preset", p.name}, {"frames", frames}}, test_support::kPresets);
      const int expected = std::min(frames, run_frames + 1);
      ASSERT_EQ(plan.settings.frames, expected) << p.name;
      const render::FrameSet set = plan.make_frames();
      ASSERT_EQ(static_cast<int>(set.times_s.size()), expected) << p.name << " " << frames;
      EXPECT_DOUBLE_EQ(set.times_s.front(), 0.0) << p.name << " " << frames;
      EXPECT_NEAR(set.times_s.back(), run_end, 1e-12) << p.name << " " << frames << " frames";
      EXPECT_NEAR(set.run_end_s, run_end, 1e-12) << p.name;
      EXPECT_NEAR(plan.frame_dt_s, run_end / (expected - 1), 1e-12) << p.name;
      for (int k = 1; k < expected; ++k) {
        // Evenly spread, to the nearest game frame: never more than half a step from k run_end / (n - 1).
        EXPECT_LE(std::abs(set.times_s[k] - k * run_end / (expected - 1)), 0.5 / p.fps + 1e-12) << p.name << " frame " << k;
      }
      // The caption shows each frame's time and its number, counted from 0 like the files.
      char last[64];
      std::snprintf(last, sizeof last, "frame %d/%d", expected - 1, expected - 1);
      EXPECT_NE(set.frames.back().caption.find(last), std::string::npos) << set.frames.back().caption;
      char when[32];
      std::snprintf(when, sizeof when, "t = %.2f", run_end);
      EXPECT_NE(set.frames.back().caption.find(when), std::string::npos) << set.frames.back().caption;
    }
  }
}

TEST(PreviewService, AFrameCountPastTheRunIsClampedToEveryGameFrame) {
  // stiff runs 2 s at 60 fps: 121 game frames 0..120.
  PreviewPlan plan = plan_preview({{"preset", "stiff"}, {"frames", 500}}, test_support::kPresets);
  EXPECT_EQ(plan.settings.frames, 121);
  EXPECT_TRUE(has_warning({{"warnings", plan.warnings}}, "frames_clamped"));
  const render::FrameSet set = plan.make_frames();
  for (int k = 0; k < 121; ++k) EXPECT_NEAR(set.times_s[k], k / 60.0, 1e-12);
}

// Each preset's preview as the page asks for it, and with an A/B ghost that runs free and slow (the
// heavy_on_light ghost falls out of the picture); nothing for presets without a tuned joint.
std::optional<render::FrameSet> ghosted(const std::string& preset, bool ghost) {
  json request = {{"preset", preset}, {"frames", 40}};
  if (ghost) request["ghost"] = {{"response_frames", 40}, {"oscillation", "free"}};
  try {
    return plan_preview(request, test_support::kPresets).make_frames();
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    return std::nullopt;
  }
}

TEST(PreviewService, TheGhostNeverMovesTheCamerasFramingOfTheRealRun) {
  int ghosts = 0;
  for (const PresetRun& p : preset_runs()) {
    const auto with = ghosted(p.name, true);
    if (!with) continue;
    ++ghosts;
    const auto without = ghosted(p.name, false);
    ASSERT_TRUE(without);
    for (const render::ImageSize size : {render::ImageSize{640, 360}, render::ImageSize{360, 640}}) {
      // The ghost's legend line may grow the title band: the same band, the same framing.
      render::FrameSet same_legend = *without;
      for (std::size_t i = 0; i < same_legend.frames.size(); ++i) same_legend.frames[i].legend = with->frames[i].legend;
      const auto a = render::run_cameras(with->camera, with->follow, with->frames, size);
      const auto b = render::run_cameras(same_legend.camera, same_legend.follow, same_legend.frames, size);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].width_m, b[i].width_m) << p.name << " frame " << i;
        EXPECT_EQ(a[i].centre_m.x, b[i].centre_m.x) << p.name << " frame " << i;
        EXPECT_EQ(a[i].centre_m.y, b[i].centre_m.y) << p.name << " frame " << i;
      }
    }
  }
  EXPECT_GE(ghosts, 5);
}

TEST(PreviewService, TheLegendNamesEveryLineAtAReadableSize) {
  // At 640x360 every legend line (each tuned joint or target, and the ghost's) is placed whole, at no
  // less than 11 px, inside the title band.
  const render::ImageSize size{640, 360};
  for (const PresetRun& p : preset_runs()) {
    for (const bool ghost : {false, true}) {
      const auto set = ghosted(p.name, ghost);
      if (!set) continue;
      const render::DrawFrame& f = set->frames.back();
      const auto cameras = render::run_cameras(set->camera, set->follow, set->frames, size);
      const render::View v = render::make_view(cameras.back(), size);
      const std::vector<render::PlacedText> placed = render::layout_text_overlay(f, v);
      const int band = static_cast<int>(std::lround(render::caption_band(size, static_cast<int>(f.legend.size())) * size.height));
      for (const std::string& line : f.legend) {
        const auto it = std::find_if(placed.begin(), placed.end(), [&](const render::PlacedText& t) { return t.text == line; });
        ASSERT_NE(it, placed.end()) << p.name << (ghost ? " with ghost" : "") << ": \"" << line << "\" not drawn";
        EXPECT_GE(it->px, 11) << p.name << ": " << line;
        EXPECT_LE(it->box.bottom, band) << p.name << ": " << line;
        EXPECT_LE(it->box.right, size.width) << p.name << ": " << line;
      }
    }
  }
}

TEST(PreviewService, TheAnswerCarriesTheFramesManifest) {
  struct Blank final : public render::Renderer {
    void render(const render::DrawFrame&, const render::Camera&, render::ImageSize, std::span<std::uint8_t> rgba) override {
      std::fill(rgba.begin(), rgba.end(), std::uint8_t{255});
    }
  };
  render::PipelineOptions options;
  options.make_renderer = [] { return std::make_unique<Blank>(); };
  PreviewService service(options);
  const json answer = service.start({{"preset", "chain"}, {"frames", 7}, {"size", "32x18"}}, test_support::kPresets, "/p");
  const json& m = answer.at("manifest");
  EXPECT_EQ(m["frame_count"], 7);
  EXPECT_DOUBLE_EQ(m["run_end_s"].get<double>(), 8.0);
  ASSERT_EQ(m["frames"].size(), 7u);
  for (int k = 0; k < 7; ++k) {
    EXPECT_EQ(m["frames"][k]["index"], k);
    EXPECT_EQ(m["frames"][k]["file"], answer["frames"][k]);
    // chain: 480 steps in 7 frames, every 80 steps, 4/3 s apart.
    EXPECT_NEAR(m["frames"][k]["time_s"].get<double>(), k * 80 / 60.0, 1e-12);
  }
  EXPECT_NEAR(m["frame_dt_s"].get<double>(), 4.0 / 3.0, 1e-12);
  // A status poll of the finished preview gives the same manifest.
  EXPECT_EQ(service.status(answer["id"], "/p")->at("manifest"), m);
}

// The preview's engine (issue 32): the frames come from the picked engine's run (its stages, not Box2D's), the
// cache key tells engines apart, and a scene the engine cannot represent is its 422 naming the feature.
TEST(PreviewService, FramesComeFromThePickedEnginesRun) {
  const json request = {{"preset", "vehicle_per_spring"}, {"frames", 6}};
  PreviewPlan box2d = plan_preview(request, test_support::kPresets);
  json in_ode = request;
  in_ode["engine"] = "ode";
  PreviewPlan ode = plan_preview(in_ode, test_support::kPresets);
  EXPECT_EQ(box2d.engine["name"], "box2d_v2_4");
  EXPECT_EQ(ode.engine["name"], "ode");
  EXPECT_NE(box2d.canonical, ode.canonical);
  const render::FrameSet a = box2d.make_frames(), b = ode.make_frames();
  ASSERT_EQ(a.frames.size(), b.frames.size());
  using softtune::Stage;
  EXPECT_TRUE(box2d.prepare_stages->contains(Stage::box2d_step));
  EXPECT_TRUE(ode.prepare_stages->contains(Stage::engine_step));
  EXPECT_FALSE(ode.prepare_stages->contains(Stage::box2d_step));

  json mouse = {{"preset", "mouse"}, {"frames", 4}, {"engine", "bullet"}};
  try {
    plan_preview(mouse, test_support::kPresets).make_frames();
    ADD_FAILURE() << "bullet drew the capped mouse";
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "joints.0.max_force");
    EXPECT_NE(p.detail.find("bullet"), std::string::npos) << p.detail;
  }
}

}  // namespace
}  // namespace softtune::codec
