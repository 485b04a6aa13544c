// Preview frames: the floor (raster only, PNG only, per frame) and the pipeline against it, in one run.
// Goal (issue 6): 120 frames at 640x360 cold (not cached) within 1.5x the floor and >= 250 frames/s
// with two workers; a cached repeat under 20 ms. Run with LP_NUM_THREADS=0/1/2 to compare llvmpipe
// thread settings (docs/benchmarks.md, "Preview frames"). Issue 22: a 120-frame 640x360 clip (WebP,
// GIF) against the 120 PNGs of the same run (BM_Clip), and the pipeline still within 1.2x of the floor.
// Issue 34: clips as fast as frames. BM_ClipWebpSettings encodes the 120 rendered frames of a preset with
// each candidate libwebp setting (the choice in clip.h's WebpClipOptions); BM_ClipStage renders a
// preset's 120 frames through the pipeline without a clip, with the WebP clip stage and with the GIF one,
// alternately in one run, and reports each clip's wall and CPU time against the frames alone and the
// WebP's size against the GIF's (aim: within 1.5x, no larger than the GIF).
#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <ctime>
#include <string>
#include <vector>

#include "softtune/render/clip.h"
#include "softtune/render/frame_pipeline.h"
#include "softtune/render/oscillator_frames.h"
#include "softtune/render/png.h"
#include "softtune/render/renderer.h"
#include "app/preview_service.h"

namespace {

using namespace softtune::render;
using Clock = std::chrono::steady_clock;

constexpr int kFrames = 120;
constexpr ImageSize kSize{640, 360};

const FrameSet& frames() {
  static const FrameSet set = [] {
    FrameSet s = oscillator_frames(OscillatorScene{}, kFrames);
    s.camera = run_camera(s, kSize);
    return s;
  }();
  return set;
}

std::vector<std::uint8_t> pixels() { return std::vector<std::uint8_t>(static_cast<std::size_t>(kSize.width) * kSize.height * 4); }

// Per-frame floor times in ms (wall and CPU), filled by the floor benchmarks that run first.
double g_raster_ms = 0.0, g_png_ms = 0.0, g_raster_cpu_ms = 0.0, g_png_cpu_ms = 0.0;

double ms_per_item(Clock::time_point t0, benchmark::State& state) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / static_cast<double>(state.iterations());
}

// CPU time in ms of the whole process (every worker thread) and of its raster processes, live (from
// /proc, 10 ms ticks) and exited (getrusage): on a shared machine wall time depends on the neighbours,
// CPU time much less.
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  double ms = ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
  rusage exited{};
  getrusage(RUSAGE_CHILDREN, &exited);
  ms += (exited.ru_utime.tv_sec + exited.ru_stime.tv_sec) * 1e3 + (exited.ru_utime.tv_usec + exited.ru_stime.tv_usec) * 1e-3;
  const double ms_per_tick = 1e3 / static_cast<double>(sysconf(_SC_CLK_TCK));
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream children(task.path() / "children");
    for (long pid; children >> pid;) {
      std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
      std::string line;
      std::getline(stat, line);
      std::istringstream fields(line.substr(line.rfind(')') + 2));  // after "pid (comm) "
      std::string skip;
      for (int i = 3; i < 14; ++i) fields >> skip;  // state ... cmajflt: fields 3 to 13
      long utime = 0, stime = 0;
      fields >> utime >> stime;
      ms += static_cast<double>(utime + stime) * ms_per_tick;
    }
  }
  return ms;
}

void raster(benchmark::State& state, int msaa) {
  auto r = make_osmesa_renderer({.msaa_samples = msaa});
  auto px = pixels();
  r->render(frames().frames[0], frames().camera, kSize, px);  // context and shader JIT outside the timing
  int i = 0;
  const auto t0 = Clock::now();
  const double c0 = cpu_ms();
  for (auto _ : state) {
    r->render(frames().frames[i++ % kFrames], frames().camera, kSize, px);
    benchmark::DoNotOptimize(px.data());
  }
  const double cpu = (cpu_ms() - c0) / static_cast<double>(state.iterations());
  const double ms = ms_per_item(t0, state);
  if (msaa == 0) g_raster_ms = ms, g_raster_cpu_ms = cpu;
  state.counters["ms_per_frame"] = ms;
  state.counters["cpu_ms_per_frame"] = cpu;
}
void BM_RasterOnly(benchmark::State& state) { raster(state, 0); }
void BM_RasterOnly_Msaa4(benchmark::State& state) { raster(state, 4); }

const std::vector<std::vector<std::uint8_t>>& rendered() {
  static const auto out = [] {
    std::vector<std::vector<std::uint8_t>> v;
    auto r = make_osmesa_renderer();
    for (const DrawFrame& f : frames().frames) {
      v.push_back(pixels());
      r->render(f, frames().camera, kSize, v.back());
    }
    return v;
  }();
  return out;
}

void BM_PngOnly(benchmark::State& state) {
  const PngOptions o{static_cast<int>(state.range(0)), static_cast<PngFilter>(state.range(1))};
  const auto& v = rendered();
  std::size_t bytes = 0;
  int i = 0;
  const auto t0 = Clock::now();
  const double c0 = cpu_ms();
  for (auto _ : state) {
    const std::string png = encode_png(v[i++ % kFrames], kSize, o);
    bytes += png.size();
  }
  const double cpu = (cpu_ms() - c0) / static_cast<double>(state.iterations());
  const double ms = ms_per_item(t0, state);
  if (o.level == 1 && o.filter == PngFilter::up) g_png_ms = ms, g_png_cpu_ms = cpu;
  state.counters["ms_per_frame"] = ms;
  state.counters["cpu_ms_per_frame"] = cpu;
  state.counters["kB_per_frame"] = bytes / 1024.0 / static_cast<double>(state.iterations());
}

// A clip of the 120 frames as the service makes it (from their PNGs, decoding included) against
// encoding those 120 PNGs (BM_PngOnly's level 1, up filter: the service's default), same run.
void BM_Clip(benchmark::State& state) {
  const auto format = static_cast<ClipFormat>(state.range(0));
  std::vector<std::string> pngs;
  for (const auto& px : rendered()) pngs.push_back(encode_png(px, kSize));
  std::vector<double> times;
  for (int i = 0; i < kFrames; ++i) times.push_back(i / 60.0);
  std::size_t bytes = 0, png_bytes = 0;
  for (const std::string& p : pngs) png_bytes += p.size();
  const auto t0 = Clock::now();
  const double c0 = cpu_ms();
  for (auto _ : state) bytes = encode_clip(format, pngs, times).size();
  const double ms = ms_per_item(t0, state), cpu = (cpu_ms() - c0) / static_cast<double>(state.iterations());
  state.counters["ms_per_clip"] = ms;
  state.counters["cpu_ms_per_clip"] = cpu;
  state.counters["pngs_ms"] = kFrames * g_png_ms;
  state.counters["ratio_to_pngs"] = g_png_ms > 0.0 ? ms / (kFrames * g_png_ms) : 0.0;
  state.counters["cpu_ratio_to_pngs"] = g_png_cpu_ms > 0.0 ? cpu / (kFrames * g_png_cpu_ms) : 0.0;
  state.counters["clip_kB"] = bytes / 1024.0;
  state.counters["pngs_kB"] = png_bytes / 1024.0;
}

// Wall: the pipeline's time per frame against the serial floor (raster + PNG per frame).
// CPU: the pipeline's CPU per frame (all threads) against the floor's CPU: its overhead, whatever the
// machine's load; 2000 / cpu_ms_per_frame is the rate two idle cores would reach.
void report(benchmark::State& state, double ms_per_frame, double process_cpu_ms) {
  const double floor = g_raster_ms + g_png_ms, floor_cpu = g_raster_cpu_ms + g_png_cpu_ms;
  const double cpu = process_cpu_ms / (static_cast<double>(state.iterations()) * kFrames);
  state.counters["ms_per_frame"] = ms_per_frame;
  state.counters["frames_per_s"] = 1000.0 / ms_per_frame;
  state.counters["floor_ms"] = floor;
  state.counters["ratio_to_floor"] = floor > 0.0 ? ms_per_frame / floor : 0.0;
  state.counters["cpu_ms_per_frame"] = cpu;
  state.counters["cpu_ratio_to_floor"] = floor_cpu > 0.0 ? cpu / floor_cpu : 0.0;
  state.counters["fps_on_2_idle_cores"] = 2000.0 / cpu;
}

// Warm pool (contexts exist), every request new: the service's usual cold render.
void BM_Pipeline120(benchmark::State& state) {
  PipelineOptions o;
  o.workers = static_cast<int>(state.range(0));
  FramePipeline p(o);
  PreviewSettings s{kFrames, kSize, 0};
  p.submit("warm-up", s, [] { return frames(); })->wait();
  int n = 0;
  const auto t0 = Clock::now();
  const double c0 = cpu_ms();
  for (auto _ : state) {
    benchmark::DoNotOptimize(p.submit("run " + std::to_string(n++), s, [] { return frames(); })->wait());
  }
  report(state, ms_per_item(t0, state) / kFrames, cpu_ms() - c0);
}

// A new pool per request: includes creating the GL contexts.
void BM_Pipeline120_NewPool(benchmark::State& state) {
  PreviewSettings s{kFrames, kSize, 0};
  const auto t0 = Clock::now();
  const double c0 = cpu_ms();
  for (auto _ : state) {
    FramePipeline p;
    benchmark::DoNotOptimize(p.submit("cold", s, [] { return frames(); })->wait());
  }
  report(state, ms_per_item(t0, state) / kFrames, cpu_ms() - c0);
}

void BM_CachedRepeat(benchmark::State& state) {
  FramePipeline p;
  PreviewSettings s{kFrames, kSize, 0};
  p.submit("repeat", s, [] { return frames(); })->wait();
  const auto t0 = Clock::now();
  for (auto _ : state) {
    benchmark::DoNotOptimize(p.submit("repeat", s, [] { return frames(); })->wait());
  }
  state.counters["ms_per_request"] = ms_per_item(t0, state);
}

void BM_ContextCreation(benchmark::State& state) {
  auto px = pixels();
  DrawFrame empty;
  for (auto _ : state) {
    auto r = make_osmesa_renderer();
    r->render(empty, frames().camera, kSize, px);  // the first frame creates the context
  }
}

// 120 frames of a preset at 640x360, as the service draws them (plan_preview's make_frames), camera fixed
// per frame (run_cameras), so a bench can render them outside the pipeline.
struct PresetFrames {
  FrameSet set;
  std::vector<Camera> cameras;
};
const PresetFrames& preset_frames(int which) {
  static const char* kNames[] = {"vehicle", "bridge", "chain"};
  static std::map<int, PresetFrames> made;
  auto it = made.find(which);
  if (it != made.end()) return it->second;
  PresetFrames f;
  f.set = softtune::app::plan_preview({{"preset", kNames[which]}, {"frames", kFrames}}, SOFTTUNE_PRESETS_DIR).make_frames();
  f.cameras = run_cameras(f.set.camera, f.set.follow, f.set.frames, kSize);
  return made.emplace(which, std::move(f)).first->second;
}

const std::vector<std::vector<std::uint8_t>>& preset_pixels(int which) {
  static std::map<int, std::vector<std::vector<std::uint8_t>>> made;
  auto it = made.find(which);
  if (it != made.end()) return it->second;
  const PresetFrames& f = preset_frames(which);
  std::vector<std::vector<std::uint8_t>> v;
  auto r = make_osmesa_renderer();
  for (std::size_t i = 0; i < f.set.frames.size(); ++i) {
    v.push_back(pixels());
    r->render(f.set.frames[i], f.cameras[i], kSize, v.back());
  }
  return made.emplace(which, std::move(v)).first->second;
}

// One libwebp setting on a preset's 120 rendered frames (pixels in hand, no PNG decoding), against the
// GIF encoder on the same pixels: args preset (0 vehicle, 1 bridge, 2 chain), method, lossless, quality,
// near_lossless, kmax, diff (0: WebPAnimEncoder's sub-frames, 1: our own differencing over WebPMux,
// 2: that on frames mapped to the GIF's palette).
void BM_ClipWebpSettings(benchmark::State& state) {
  const auto& v = preset_pixels(static_cast<int>(state.range(0)));
  WebpClipOptions o;
  o.method = static_cast<int>(state.range(1));
  o.lossless = state.range(2) != 0;
  o.quality = static_cast<float>(state.range(3));
  o.near_lossless = static_cast<int>(state.range(4));
  o.kmax = static_cast<int>(state.range(5));
  o.kmin = o.kmax > 1 ? o.kmax / 2 : 0;
  o.differencing = state.range(6) != 0;
  o.palette = state.range(6) == 2;
  const std::vector<double>& times = preset_frames(static_cast<int>(state.range(0))).set.times_s;
  const auto encode = [&](ClipFormat format) {
    auto e = make_clip_encoder(format, kSize, times, o);
    for (const auto& px : v) e->add(px);
    return e->finish().size();
  };
  std::size_t bytes = 0;
  const auto t0 = Clock::now();
  const double c0 = cpu_ms();
  for (auto _ : state) bytes = encode(ClipFormat::webp);
  const double ms = ms_per_item(t0, state), cpu = (cpu_ms() - c0) / static_cast<double>(state.iterations());
  const auto g0 = Clock::now();
  const double gc0 = cpu_ms();
  const std::size_t gif_bytes = encode(ClipFormat::gif);
  const double gif_cpu = cpu_ms() - gc0;
  state.counters["ms_per_frame"] = ms / kFrames;
  state.counters["cpu_ms_per_frame"] = cpu / kFrames;
  state.counters["clip_kB"] = bytes / 1024.0;
  state.counters["gif_kB"] = gif_bytes / 1024.0;
  state.counters["gif_cpu_ms_per_frame"] = gif_cpu / kFrames;
  state.counters["gif_ms_per_frame"] = std::chrono::duration<double, std::milli>(Clock::now() - g0).count() / kFrames;
}

// A preset's 120 frames through the pipeline (2 workers, warm): frames alone, with the WebP clip stage,
// with the GIF clip stage, each iteration all three, so the ratios share the machine's load.
void BM_ClipStage(benchmark::State& state) {
  const PresetFrames& f = preset_frames(static_cast<int>(state.range(0)));
  PipelineOptions o;
  o.workers = 2;
  FramePipeline p(o);
  PreviewSettings s{kFrames, kSize, 0};
  p.submit("warm-up", s, [&] { return f.set; })->wait();
  double ms[3] = {0, 0, 0}, cpu[3] = {0, 0, 0}, render_ms[3] = {0, 0, 0}, clip_ms[3] = {0, 0, 0};
  std::size_t bytes[3] = {0, 0, 0};
  int n = 0;
  for (auto _ : state) {
    for (int k = 0; k < 3; ++k) {
      const std::optional<ClipFormat> clip = k == 0 ? std::nullopt : std::optional(k == 1 ? ClipFormat::webp : ClipFormat::gif);
      const auto t0 = Clock::now();
      const double c0 = cpu_ms();
      const auto preview = p.submit("stage " + std::to_string(n++), s, [&] { return f.set; }, clip)->wait();
      cpu[k] += cpu_ms() - c0;
      ms[k] += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
      bytes[k] = preview->clip.size();
      render_ms[k] += preview->timings.render_ms;
      clip_ms[k] += preview->timings.clip_ms;
    }
  }
  const double it = static_cast<double>(state.iterations());
  state.counters["frames_ms"] = ms[0] / it;
  state.counters["webp_ms"] = ms[1] / it;
  state.counters["gif_ms"] = ms[2] / it;
  state.counters["webp_x_frames"] = ms[1] / ms[0];
  state.counters["gif_x_frames"] = ms[2] / ms[0];
  state.counters["webp_cpu_x_frames"] = cpu[1] / cpu[0];
  state.counters["gif_cpu_x_frames"] = cpu[2] / cpu[0];
  state.counters["webp_kB"] = bytes[1] / 1024.0;
  state.counters["gif_kB"] = bytes[2] / 1024.0;
  // Summed over frames and workers (PreviewTimings): where the time goes.
  state.counters["frames_render_ms"] = render_ms[0] / it;
  state.counters["webp_render_ms"] = render_ms[1] / it;
  state.counters["webp_encode_ms"] = clip_ms[1] / it;
  state.counters["gif_encode_ms"] = clip_ms[2] / it;
  state.counters["webp_x_gif_size"] = bytes[2] > 0 ? static_cast<double>(bytes[1]) / bytes[2] : 0.0;
}

BENCHMARK(BM_RasterOnly)->Iterations(600)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RasterOnly_Msaa4)->Iterations(240)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PngOnly)
    ->ArgNames({"level", "filter"})
    ->Args({1, static_cast<int>(PngFilter::up)})
    ->Args({1, static_cast<int>(PngFilter::none)})
    ->Args({1, static_cast<int>(PngFilter::sub)})
    ->Args({1, static_cast<int>(PngFilter::paeth)})
    ->Args({1, static_cast<int>(PngFilter::all)})
    ->Args({3, static_cast<int>(PngFilter::up)})
    ->Args({6, static_cast<int>(PngFilter::up)})
    ->Args({6, static_cast<int>(PngFilter::all)})
    ->Iterations(240)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Clip)->ArgName("webp0_gif1")->Arg(0)->Arg(1)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ClipWebpSettings)
    ->ArgNames({"preset", "method", "lossless", "quality", "near_lossless", "kmax", "diff"})
    ->Args({0, 1, 1, 20, 100, 9, 0})  // the previous default (kmax 9 is libwebp's default for lossless)
    ->Args({0, 0, 1, 0, 100, 0, 1})
    ->Args({0, 1, 1, 0, 100, 0, 1})
    ->Args({0, 0, 0, 75, 100, 0, 1})
    ->Args({0, 0, 1, 0, 100, 0, 2})
    ->Args({0, 1, 1, 0, 100, 0, 2})
    ->Args({0, 1, 1, 25, 100, 0, 2})
    ->Args({1, 1, 1, 20, 100, 9, 0})
    ->Args({1, 0, 1, 0, 100, 0, 2})
    ->Args({1, 1, 1, 0, 100, 0, 2})
    ->Args({1, 1, 1, 25, 100, 0, 2})
    ->Args({2, 1, 1, 20, 100, 9, 0})
    ->Args({2, 0, 1, 0, 100, 0, 2})
    ->Args({2, 1, 1, 0, 100, 0, 2})
    ->Args({2, 1, 1, 25, 100, 0, 2})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ClipStage)->ArgName("preset")->Arg(0)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Pipeline120)->ArgName("workers")->Arg(1)->Arg(2)->Iterations(8)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Pipeline120_NewPool)->Iterations(4)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CachedRepeat)->Iterations(2000)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ContextCreation)->Iterations(10)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
