// The render pool: caps, content-hash naming, the cache, progress, failures, concurrency, and that no
// GL context exists until frames are asked for. Also built under ThreadSanitizer (docs/testing.md).
#include "softtune/render/frame_pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

#include "png_decode.h"
#include "softtune/render/palette.h"
#include "softtune/render/oscillator_frames.h"
#include "softtune/support/run_limit.h"

namespace softtune::render {
namespace {

PreviewSettings small(int frames) {
  PreviewSettings s;
  s.frames = frames;
  s.size = {160, 90};
  return s;
}

// A box sliding right by 0.1 m per frame.
FrameSet sliding_box(int frames) {
  FrameSet set;
  set.camera.auto_fit = false;
  set.camera.width_m = 8.0;
  for (int k = 0; k < frames; ++k) {
    const double x = -2.0 + 0.1 * k;
    DrawFrame f;
    f.polygons.push_back({{{x - 0.5, -0.5}, {x + 0.5, -0.5}, {x + 0.5, 0.5}, {x - 0.5, 0.5}}, Role::dynamic_body});
    set.frames.push_back(std::move(f));
  }
  return set;
}

// A renderer without GL: fills the image with a grey that encodes the box position; throws on a frame
// captioned "fail" while `failing` is set.
class FakeRenderer final : public Renderer {
 public:
  explicit FakeRenderer(std::atomic<bool>* failing) : failing_(failing) {}
  void render(const DrawFrame& frame, const Camera&, ImageSize, std::span<std::uint8_t> rgba) override {
    if (failing_ && failing_->load() && frame.caption == "fail") throw std::runtime_error("injected failure");
    const int v = frame.polygons.empty() ? 0 : static_cast<int>(std::lround(100 + 10 * frame.polygons[0].vertices_m[0].x));
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = (i % 4 == 3) ? 255 : static_cast<std::uint8_t>(v);
  }

 private:
  std::atomic<bool>* failing_;
};

PipelineOptions fake_options(std::atomic<bool>* failing = nullptr) {
  PipelineOptions o;
  o.make_renderer = [failing] { return std::make_unique<FakeRenderer>(failing); };
  return o;
}

TEST(PreviewSettings, CapsNameTheField) {
  EXPECT_FALSE(validate_preview_settings({}));
  EXPECT_FALSE(validate_preview_settings({caps::kMaxFrames, {caps::kMaxWidth, caps::kMaxHeight}, 0}));
  EXPECT_EQ(validate_preview_settings({0, {640, 360}, 0})->field, "frames");
  EXPECT_EQ(validate_preview_settings({caps::kMaxFrames + 1, {640, 360}, 0})->field, "frames");
  EXPECT_EQ(validate_preview_settings({60, {caps::kMaxWidth + 1, 360}, 0})->field, "size");
  EXPECT_EQ(validate_preview_settings({60, {640, caps::kMaxHeight + 1}, 0})->field, "size");
  EXPECT_EQ(validate_preview_settings({60, {caps::kMinSide - 1, 360}, 0})->field, "size");
  EXPECT_EQ(validate_preview_settings({60, {640, 360}, 61})->field, "filmstrip_every");
  EXPECT_EQ(validate_preview_settings({60, {640, 360}, -1})->field, "filmstrip_every");
  const auto e = validate_preview_settings({601, {640, 360}, 0});
  EXPECT_NE(e->rule.find("600"), std::string::npos);
}

TEST(FramePipeline, RefusesSettingsAboveTheCapsBeforeMakingFrames) {
  FramePipeline p(fake_options());
  bool called = false;
  EXPECT_THROW(p.submit("x", {601, {640, 360}, 0}, [&] { called = true; return FrameSet{}; }), std::invalid_argument);
  EXPECT_THROW(p.submit("x", {60, {3840, 2160}, 0}, [&] { called = true; return FrameSet{}; }), std::invalid_argument);
  EXPECT_FALSE(called);
}

TEST(FramePipeline, NoGlContextUnlessFramesAreRequested) {
  const int before = gl_contexts_created();
  {
    FramePipeline p;  // the OSMesa backend, workers running
    // A caller that simulates and looks up previews but asks for no frames.
    const FrameSet set = oscillator_frames(OscillatorScene{}, 30);
    EXPECT_EQ(set.frames.size(), 30u);
    EXPECT_FALSE(p.cached(FramePipeline::preview_id("oscillator", small(30))));
    EXPECT_FALSE(p.find("no-such-id"));
    EXPECT_THROW(p.submit("x", small(0), [] { return FrameSet{}; }), std::invalid_argument);
  }
  EXPECT_EQ(gl_contexts_created(), before);

  // Frames requested: at most one context per worker, and a cached repeat creates none.
  FramePipeline p;
  p.submit("box", small(8), [] { return sliding_box(8); })->wait();
  const int after_first = gl_contexts_created();
  EXPECT_GE(after_first, before + 1);
  EXPECT_LE(after_first, before + p.workers());
  EXPECT_TRUE(p.submit("box", small(8), [] { return sliding_box(8); })->from_cache());
  EXPECT_EQ(gl_contexts_created(), after_first);
}

// An idle worker gives its renderer (with the OSMesa backend: its raster process) back, and the next
// frame makes a new one.
TEST(FramePipeline, IdleWorkersReleaseTheirRenderers) {
  std::atomic<int> made{0}, live{0};
  struct Counted final : public Renderer {
    explicit Counted(std::atomic<int>& live) : live_(live) { ++live_; }
    ~Counted() override { --live_; }
    void render(const DrawFrame&, const Camera&, ImageSize, std::span<std::uint8_t> rgba) override {
      std::fill(rgba.begin(), rgba.end(), std::uint8_t{255});
    }
    std::atomic<int>& live_;
  };
  PipelineOptions o;
  o.workers = 1;
  o.release_renderer_after_ms = 50;
  o.make_renderer = [&] {
    ++made;
    return std::make_unique<Counted>(live);
  };
  FramePipeline p(o);
  p.submit("a", small(3), [] { return sliding_box(3); })->wait();
  EXPECT_EQ(made.load(), 1);
  for (int i = 0; i < 500 && live.load() > 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(live.load(), 0);
  p.submit("b", small(3), [] { return sliding_box(3); })->wait();
  EXPECT_EQ(made.load(), 2);
  // While frames keep coming, the renderer is kept.
  p.submit("c", small(3), [] { return sliding_box(3); })->wait();
  EXPECT_EQ(made.load(), 2);
}

TEST(FramePipeline, FramesDifferWhileTheSceneMovesAndRepeatExactly) {
  FramePipeline a, b;  // separate caches: the repeat really renders again
  const auto pa = a.submit("box", small(6), [] { return sliding_box(6); })->wait();
  const auto pb = b.submit("box", small(6), [] { return sliding_box(6); })->wait();
  ASSERT_EQ(pa->frames_png.size(), 6u);
  EXPECT_EQ(pa->id, pb->id);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(pa->frames_png[k], pb->frames_png[k]) << "frame " << k;
    if (k > 0) {
      EXPECT_NE(pa->frames_png[k], pa->frames_png[k - 1]) << "frame " << k;
    }
  }
  EXPECT_EQ(pa->filmstrip_png, pb->filmstrip_png);
  // The box is at its projected position in every frame.
  const View v = make_view(sliding_box(1).camera, {160, 90});
  for (int k = 0; k < 6; ++k) {
    const test::Decoded d = test::decode_png(pa->frames_png[k]);
    const std::uint8_t* p = d.at(static_cast<int>(v.px(-2.0 + 0.1 * k)), static_cast<int>(v.py(0.0)));
    EXPECT_EQ(p[0], role_colours(Role::dynamic_body).fill.r) << "frame " << k;
    EXPECT_EQ(p[2], role_colours(Role::dynamic_body).fill.b) << "frame " << k;
  }
  EXPECT_TRUE(pa->stages.contains(Stage::render));
  EXPECT_TRUE(pa->stages.contains(Stage::png_encode));
}

TEST(FramePipeline, IdDependsOnRequestAndSettings) {
  const std::string base = FramePipeline::preview_id("req", small(10));
  EXPECT_EQ(base.size(), 64u);
  EXPECT_EQ(base, FramePipeline::preview_id("req", small(10)));
  EXPECT_NE(base, FramePipeline::preview_id("req2", small(10)));
  EXPECT_NE(base, FramePipeline::preview_id("req", small(11)));
  PreviewSettings other = small(10);
  other.size = {161, 90};
  EXPECT_NE(base, FramePipeline::preview_id("req", other));
  other = small(10);
  other.filmstrip_every = 2;
  EXPECT_NE(base, FramePipeline::preview_id("req", other));
}

TEST(FramePipeline, CacheServesRepeatsWithoutMakingFrames) {
  FramePipeline p(fake_options());
  std::atomic<int> made{0};
  auto make = [&] { ++made; return sliding_box(5); };
  const auto first = p.submit("r", small(5), make);
  EXPECT_FALSE(first->from_cache());
  const auto preview = first->wait();
  const auto again = p.submit("r", small(5), make);
  EXPECT_TRUE(again->from_cache());
  EXPECT_EQ(again->wait(), preview);
  EXPECT_EQ(made.load(), 1);
  EXPECT_EQ(p.cached(preview->id), preview);
  EXPECT_EQ(p.find(preview->id)->wait(), preview);
  const support::LruStats s = p.cache_stats();
  EXPECT_EQ(s.entries, 1u);
  EXPECT_EQ(s.bytes, preview->bytes());
}

TEST(FramePipeline, CacheIsBoundedByBytes) {
  PipelineOptions o = fake_options();
  FramePipeline probe(fake_options());
  const std::size_t one = probe.submit("r0", small(5), [] { return sliding_box(5); })->wait()->bytes();
  o.cache_bytes = one * 2 + one / 2;  // room for two
  FramePipeline p(o);
  for (int i = 0; i < 4; ++i) p.submit("r" + std::to_string(i), small(5), [] { return sliding_box(5); })->wait();
  const support::LruStats s = p.cache_stats();
  EXPECT_EQ(s.entries, 2u);
  EXPECT_LE(s.bytes, o.cache_bytes);
  EXPECT_EQ(s.evictions, 2u);
  EXPECT_FALSE(p.cached(FramePipeline::preview_id("r0", small(5))));
  EXPECT_TRUE(p.cached(FramePipeline::preview_id("r3", small(5))));
}

TEST(FramePipeline, ProgressReachesTheTotal) {
  FramePipeline p;
  const auto job = p.submit("box", small(20), [] { return sliding_box(20); });
  int last = 0;
  while (!job->wait_for(1)) {
    const PreviewProgress pr = job->progress();
    EXPECT_GE(pr.done, last);
    EXPECT_LE(pr.done, 20);
    EXPECT_EQ(pr.total, 20);
    last = pr.done;
  }
  const PreviewProgress done = job->progress();
  EXPECT_TRUE(done.finished);
  EXPECT_FALSE(done.failed);
  EXPECT_EQ(done.done, 20);
}

// Frames stream: frame 0 is served while later frames are still held in the renderer, and the bytes
// served early are the bytes of the finished preview.
class GatedRenderer final : public Renderer {
 public:
  explicit GatedRenderer(std::atomic<bool>* open) : open_(open) {}
  void render(const DrawFrame& frame, const Camera&, ImageSize, std::span<std::uint8_t> rgba) override {
    while (frame.caption == "hold" && !open_->load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::fill(rgba.begin(), rgba.end(), static_cast<std::uint8_t>(frame.caption == "hold" ? 200 : 50));
  }

 private:
  std::atomic<bool>* open_;
};

TEST(FramePipeline, AnEncodedFrameIsServedBeforeTheOthersFinish) {
  std::atomic<bool> open{false};
  PipelineOptions o;
  o.make_renderer = [&open] { return std::make_unique<GatedRenderer>(&open); };
  FramePipeline p(o);
  const auto job = p.submit("gated", small(6), [] {
    FrameSet set = sliding_box(6);
    for (std::size_t k = 1; k < set.frames.size(); ++k) set.frames[k].caption = "hold";
    return set;
  });
  while (job->progress().ready < 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const PreviewProgress early = job->progress();
  EXPECT_FALSE(early.finished);
  EXPECT_EQ(early.ready, 1);
  const auto first = job->frame_png(0);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(test::decode_png(*first).rgba.at(0), 50);
  EXPECT_FALSE(job->frame_png(1).has_value()) << "frame 1 is still held";
  EXPECT_FALSE(job->frame_png(6).has_value());
  open = true;
  const auto preview = job->wait();
  EXPECT_EQ(job->progress().ready, 6);
  EXPECT_EQ(*first, preview->frames_png[0]);
  EXPECT_EQ(job->frame_png(1), preview->frames_png[1]);
}

// A frame once served stays served while the job finishes: finish() moves the frames into the preview
// before it encodes the filmstrip and marks the job finished, and a reader in that window once read the
// moved-from frames (a null dereference that took the server down under the page's polling).
TEST(FramePipeline, AFrameStaysServedWhileTheJobFinishes) {
  FramePipeline p(fake_options());
  PreviewSettings large = small(24);
  large.size = {1920, 1080};  // a filmstrip of that size takes long enough to encode for the reads to land in it
  // The window is a few ms per job: several jobs make a miss unlikely (one job hit it in about one run of three).
  for (int round = 0; round < 6; ++round) {
    const auto job = p.submit("finishing " + std::to_string(round), large, [] { return sliding_box(24); });
    while (job->progress().ready < 1) std::this_thread::yield();
    const std::optional<std::string> first = job->frame_png(0);
    ASSERT_TRUE(first.has_value());
    int reads = 0;
    while (!job->progress().finished) {
      const std::optional<std::string> again = job->frame_png(0);
      ASSERT_TRUE(again.has_value()) << "after " << reads << " reads";
      ASSERT_EQ(*again, *first);
      ++reads;
    }
    EXPECT_GT(reads, 0);
    EXPECT_EQ(job->frame_png(0), first);
    EXPECT_EQ(job->frame_png(23), job->wait()->frames_png[23]);
  }
}

// A renderer that takes a while per frame, so a job's tail is still rendering when the next job comes.
class SlowRenderer final : public Renderer {
 public:
  void render(const DrawFrame&, const Camera&, ImageSize, std::span<std::uint8_t> rgba) override {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    std::fill(rgba.begin(), rgba.end(), std::uint8_t{128});
  }
};

// The newest job renders first: its frame 0 is ready while the job it replaced still has most of its frames
// to render, and that job still finishes, every frame.
TEST(FramePipeline, TheNewestJobsFirstFrameDoesNotWaitForAnOlderJobsTail) {
  PipelineOptions o;
  o.make_renderer = [] { return std::make_unique<SlowRenderer>(); };
  FramePipeline p(o);
  const auto older = p.submit("older", small(200), [] { return sliding_box(200); });
  while (older->progress().ready < 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const auto newer = p.submit("newer", small(20), [] { return sliding_box(20); });
  while (newer->progress().ready < 1) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_LT(older->progress().done, 100) << "the new first frame waited for the older job";
  EXPECT_EQ(newer->wait()->frames_png.size(), 20u);
  EXPECT_EQ(older->wait()->frames_png.size(), 200u);
}

TEST(FramePipeline, AFailedFrameFailsTheJobAndIsNotCached) {
  std::atomic<bool> failing{true};
  FramePipeline p(fake_options(&failing));
  auto make = [] {
    FrameSet set = sliding_box(8);
    set.frames[3].caption = "fail";
    return set;
  };
  const auto job = p.submit("r", small(8), make);
  try {
    job->wait();
    ADD_FAILURE() << "a failed frame must fail the job";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("frame 3"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(job->progress().failed);
  EXPECT_FALSE(p.cached(job->id()));
  failing = false;
  std::atomic<int> made{0};
  EXPECT_FALSE(p.submit("r", small(8), [&] { ++made; return make(); })->wait()->frames_png.empty());
  EXPECT_EQ(made.load(), 1);  // rendered again, not served from a cache
}

TEST(FramePipeline, MakeFramesErrorsReachTheCaller) {
  FramePipeline p(fake_options());
  EXPECT_THROW(p.submit("r", small(8), [] { return sliding_box(7); }), std::logic_error);
  EXPECT_THROW(p.submit("r", small(8), []() -> FrameSet { throw std::runtime_error("bad scene"); }),
               std::runtime_error);
  EXPECT_NO_THROW(p.submit("r", small(8), [] { return sliding_box(8); })->wait());
}

TEST(FramePipeline, ConcurrentIdenticalRequestsShareOneRender) {
  FramePipeline p;
  std::atomic<int> made{0};
  std::vector<std::shared_ptr<const Preview>> results(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      results[t] = p.submit("same", small(12), [&] { ++made; return sliding_box(12); })->wait();
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(made.load(), 1);
  for (const auto& r : results) EXPECT_EQ(r->frames_png, results[0]->frames_png);
}

TEST(FramePipeline, DifferentRequestsInParallel) {
  FramePipeline p;
  std::vector<std::shared_ptr<PreviewJob>> jobs;
  for (int i = 0; i < 3; ++i) {
    jobs.push_back(p.submit("box" + std::to_string(i), small(10 + i), [i] { return sliding_box(10 + i); }));
  }
  for (int i = 0; i < 3; ++i) EXPECT_EQ(jobs[i]->wait()->frames_png.size(), static_cast<std::size_t>(10 + i));
}

}  // namespace
}  // namespace softtune::render

namespace softtune::render {
namespace {

// The clip stage: frames handed to the encoder in order as they render, on 1 to 3 workers, with more
// frames than the stage holds as pixels (so some are decoded back from their PNGs), gives the very clip
// that encoding the finished PNGs gives (clip_test.cpp decodes that one back frame by frame).
TEST(FramePipeline, TheClipStageEncodesTheFramesInOrderWhileTheyRender) {
  for (const ClipFormat format : {ClipFormat::webp, ClipFormat::gif}) {
    for (const int workers : {1, 2, 3}) {
      PipelineOptions o = fake_options();
      o.workers = workers;
      FramePipeline p(o);
      const int n = 3 * kClipPendingFrames;
      FrameSet frames = sliding_box(n);
      for (int k = 0; k < n; ++k) frames.times_s.push_back(0.1 * k);
      const auto preview = p.submit("clip", small(n), [&] { return frames; }, format)->wait();
      ASSERT_EQ(preview->clip_format, format);
      EXPECT_EQ(preview->clip, encode_clip(format, preview->frames_png, preview->frame_times_s))
          << clip_format_name(format) << ", " << workers << " workers";
      EXPECT_GT(preview->timings.clip_ms, 0.0);
    }
  }
}

TEST(FramePipeline, AClipOverItsCapIsRefusedBeforeAnyFrameIsMade) {
  FramePipeline p(fake_options());
  bool called = false;
  EXPECT_THROW(p.submit("big", {121, {1280, 720}, 0}, [&] { called = true; return FrameSet{}; }, ClipFormat::webp),
               std::invalid_argument);
  EXPECT_FALSE(called);
  // Without a clip the same preview is allowed.
  EXPECT_NO_THROW(p.submit("small", {2, {1280, 720}, 0}, [] { return sliding_box(2); }, std::nullopt)->wait());
}

}  // namespace
}  // namespace softtune::render

namespace softtune::render {

// A preview's frames are held to PipelineOptions::job_cpu_seconds, summed over the workers' threads and
// their raster processes: 600 full-HD frames (seconds of work with the real OSMesa backend) under a limit
// of 0.3 s stop within a frame or two per worker of it, fail with RunStopped (the service's 422), and
// leave nothing cached; the next job renders normally.
TEST(FramePipeline, AJobStopsAtItsCpuLimit) {
  PreviewSettings full_hd;
  full_hd.frames = caps::kMaxFrames;
  full_hd.size = {caps::kMaxWidth, caps::kMaxHeight};
  // One full-HD frame's time here (render and PNG, wall: at least its CPU), from a short job of the same
  // frames on a pipeline without a limit once its raster processes run. The limit is 0.3 s, or six frames
  // where a frame is slower (a TSan build draws one in about 0.1 s): a job stops within about one frame per
  // worker of its limit, however slow the build.
  PreviewSettings four = full_hd;
  four.frames = 4;
  double frame_s = 0.0;
  {
    FramePipeline probe(PipelineOptions{});
    probe.submit("warm", four, [] { return sliding_box(4); })->wait();  // the raster processes start here
    const PreviewTimings t = probe.submit("four", four, [] { return sliding_box(4); })->wait()->timings;
    frame_s = (t.render_ms + t.png_ms) * 1e-3 / 4;
  }
  const double limit = std::max(0.3, 6.0 * frame_s);
  PipelineOptions o;
  o.job_cpu_seconds = limit;
  FramePipeline p(o);
  PreviewSettings one = full_hd;
  one.frames = 1;
  p.submit("warm", one, [] { return sliding_box(1); })->wait();  // this pipeline's raster processes start
  const auto t0 = std::chrono::steady_clock::now();
  const auto job = p.submit("full-hd", full_hd, [] { return sliding_box(caps::kMaxFrames); });
  double spent = 0.0;
  try {
    job->wait();
    ADD_FAILURE() << "600 full-HD frames must pass a " << limit << " s limit";
  } catch (const support::RunStopped& e) {
    EXPECT_EQ(e.why, support::RunStopped::Why::budget);
    EXPECT_DOUBLE_EQ(e.limit_seconds, limit);
    spent = e.cpu_seconds;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_GT(spent, limit);
  EXPECT_LT(spent, limit + 2 * p.workers() * frame_s + 0.1)
      << "stopped at " << spent << " s of CPU, limit " << limit << " s, one frame " << frame_s << " s";
  EXPECT_LT(spent, caps::kMaxFrames * frame_s / 4) << "the whole job would take about " << caps::kMaxFrames * frame_s << " s";
  EXPECT_TRUE(job->progress().failed);
  EXPECT_FALSE(p.cached(job->id()));
  std::printf("full-HD preview stopped at %.3f s of CPU (limit %.2f s) after %.2f s wall; one frame %.4f s of "
              "render and PNG time, all 600 frames about %.1f s of it\n", spent, limit, wall, frame_s, caps::kMaxFrames * frame_s);
  // A job within the limit is untouched.
  EXPECT_EQ(p.submit("small", small(8), [] { return sliding_box(8); })->wait()->frames_png.size(), 8u);
}

}  // namespace softtune::render
