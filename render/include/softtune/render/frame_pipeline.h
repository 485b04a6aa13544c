#pragma once
// The frame pipeline: a pool of render worker threads, PNG encoding on the same workers so one frame
// encodes while the next renders, results named by a content hash and kept in a byte-bounded LRU cache
// (support::LruCache), a filmstrip, and progress counters. No GL here: each worker makes a renderer on
// its first frame, which tessellates on the worker and has a softtune-raster process of its own (where
// the GL context lives, renderer.h) draw the triangles; a worker that waits release_renderer_after_ms
// without a frame destroys its renderer, and so ends that process.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/render/camera_path.h"
#include "softtune/render/clip.h"
#include "softtune/render/draw_model.h"
#include "softtune/render/filmstrip.h"
#include "softtune/render/png.h"
#include "softtune/render/renderer.h"
#include "softtune/support/lru_cache.h"

namespace softtune::render {

/// Caps on one preview request; above them the request is refused (validate_preview_settings).
namespace caps {
inline constexpr int kMaxWidth = 1920, kMaxHeight = 1080;  ///< px
inline constexpr int kMinSide = 16;                        ///< px, width and height
inline constexpr int kMaxFrames = 600;
inline constexpr int kDefaultFrames = 60;
inline constexpr ImageSize kDefaultSize{640, 360};
}  // namespace caps

struct PreviewSettings {
  int frames = caps::kDefaultFrames;
  ImageSize size = caps::kDefaultSize;
  int filmstrip_every = 0;  ///< frames between filmstrip tiles; 0 chooses about kFilmstripTargetTiles tiles
};

/// The first broken cap, naming the request field ("frames", "size", "filmstrip_every"), or nothing.
std::optional<FieldError> validate_preview_settings(const PreviewSettings& settings);

/// What a caller hands the pipeline: one draw model per frame and how the camera moves (camera_path.h:
/// a fixed camera; an auto-fit one fitted once to the action of every frame, so the view does not jump;
/// or, with `follow` boxes, one that follows them).
struct FrameSet {
  Camera camera;
  Follow follow;
  std::vector<DrawFrame> frames;
  /// s of each frame in the run (the manifest, a clip's frame timing); empty: 1/60 s apart.
  std::vector<double> times_s;
  /// s, where the run ends (the manifest's run_end_s); the last frame's time when frames span the run.
  double run_end_s = 0.0;
};

/// The first frame's camera of a run (run_cameras).
Camera run_camera(const FrameSet& set, ImageSize size);

struct PreviewTimings {
  double wall_ms = 0.0;       ///< submit to finished
  double prepare_ms = 0.0;    ///< the caller's make_frames (simulation and draw model)
  double render_ms = 0.0;     ///< summed over frames: tessellation, raster and read-back
  double png_ms = 0.0;        ///< summed over frames: PNG encoding
  double filmstrip_ms = 0.0;  ///< the filmstrip PNG
  double clip_ms = 0.0;       ///< summed over frames: the clip stage's encoding (0 without a clip)
  double clip_tail_ms = 0.0;  ///< the clip's encoding left after the last frame rendered, and its assembly
  int workers = 0;            ///< render workers in the pool
};

/// A finished preview: PNG bytes of every frame and of the filmstrip.
struct Preview {
  std::string id;  ///< content hash of the canonical request and settings (64 hex digits)
  PreviewSettings settings;
  FilmstripLayout filmstrip;
  std::vector<std::string> frames_png;
  std::string filmstrip_png;
  std::vector<double> frame_times_s;  ///< s, each frame's time in the run (FrameSet::times_s)
  double run_end_s = 0.0;             ///< s, FrameSet::run_end_s
  std::optional<ClipFormat> clip_format;  ///< the clip encoded while the frames rendered, if one was asked for
  std::string clip;                       ///< its bytes
  PreviewTimings timings;
  StageList stages;  ///< render, png_encode
  std::size_t bytes() const;
};

struct PreviewProgress {
  int done = 0;   ///< frames rendered and encoded
  int ready = 0;  ///< frames 0..ready-1 are encoded and can be served while the rest render (streaming)
  int total = 0;
  bool finished = false;
  bool failed = false;
};

struct JobState;

/// A preview being made (or found in the cache). Shared by everyone who asked for the same id.
class PreviewJob {
 public:
  explicit PreviewJob(std::shared_ptr<JobState> state) : state_(std::move(state)) {}
  const std::string& id() const;
  bool from_cache() const;
  PreviewProgress progress() const;
  /// Blocks until every frame is done; throws std::runtime_error when rendering failed, and
  /// support::RunStopped (a std::runtime_error) when its frames passed PipelineOptions::job_cpu_seconds.
  std::shared_ptr<const Preview> wait() const;
  /// Waits at most `timeout_ms`; true when finished.
  bool wait_for(int timeout_ms) const;
  /// PNG bytes of frame n as soon as that frame is encoded, while the others still render (a client
  /// shows the first frame at once); nullopt before then, for an unknown frame, or after a failure.
  std::optional<std::string> frame_png(int n) const;

 private:
  std::shared_ptr<JobState> state_;
};

struct PipelineOptions {
  int workers = 2;                              ///< render threads, one renderer (one raster process) each
  std::size_t cache_bytes = std::size_t{256} << 20;
  PngOptions png;
  RendererOptions renderer;
  /// ms a worker waits without a frame before it destroys its renderer (and so ends its raster process
  /// and gives back its memory); the next frame makes a new one (about 60 ms). 0: never.
  int release_renderer_after_ms = 30'000;
  /// Makes a worker's renderer on its first frame; empty: the OSMesa backend with `renderer`.
  std::function<std::unique_ptr<Renderer>()> make_renderer;
  WebpClipOptions webp;  ///< the clip stage's WebP settings
  /// CPU time one preview's frames may take, s, summed over its frames: each worker thread's own time
  /// (tessellation, PNG, the clip stage) and its raster process's (Renderer::raster_cpu_seconds). Past
  /// it the job fails at its next frame and wait() throws support::RunStopped (Why::budget); 0: no limit.
  double job_cpu_seconds = 0.0;
};

/// Frames a clip stage holds as pixels while they wait for the encoder; past that a waiting frame is
/// decoded back from its PNG when its turn comes (a 1280x720 frame is 3.7 MB of pixels).
inline constexpr int kClipPendingFrames = 8;

class FramePipeline {
 public:
  explicit FramePipeline(PipelineOptions options = {});
  ~FramePipeline();  ///< finishes the frames already queued, then joins the workers
  FramePipeline(const FramePipeline&) = delete;
  FramePipeline& operator=(const FramePipeline&) = delete;

  /// The result's name: SHA-256 of the caller's canonical request text (scene + tuning) and the settings.
  static std::string preview_id(std::string_view canonical_request, const PreviewSettings& settings);

  /// The cached preview, the job already making it, or a new job. `make_frames` runs (on the calling
  /// thread) only for a new job and must return settings.frames frames; its exceptions propagate.
  /// Throws std::invalid_argument for settings that break a cap, or a clip over validate_clip's.
  /// With `clip`, a new job also encodes that clip as a stage of the pipeline: each frame goes to the
  /// encoder, in order, as soon as it and the frames before it are rendered, on whichever worker finds
  /// the encoder free (the others keep rendering), so the clip is done about when the frames are.
  std::shared_ptr<PreviewJob> submit(std::string_view canonical_request, const PreviewSettings& settings,
                                     const std::function<FrameSet()>& make_frames,
                                     std::optional<ClipFormat> clip = std::nullopt);

  /// A cached preview by id (GET of a frame), or nullptr.
  std::shared_ptr<const Preview> cached(const std::string& id);
  /// The job in flight or the cached result by id (progress), or nullptr.
  std::shared_ptr<PreviewJob> find(const std::string& id);

  support::LruStats cache_stats() const { return cache_.stats(); }
  int workers() const { return static_cast<int>(threads_.size()); }

 private:
  struct Task {
    std::shared_ptr<JobState> job;
    int index;
  };
  void worker_loop();
  void run_task(const Task& task, std::unique_ptr<Renderer>& renderer, std::vector<std::uint8_t>& pixels);
  void finish(JobState& job);
  void feed_clip(JobState& job, bool wait);
  static void charge_frame(JobState& job, double cpu_seconds);

  PipelineOptions options_;
  support::LruCache<std::string, Preview> cache_;  ///< by id, weighed by Preview::bytes()
  std::mutex jobs_mutex_;
  std::map<std::string, std::shared_ptr<JobState>> in_flight_;
  std::mutex queue_mutex_;
  std::condition_variable queue_cv_;
  std::deque<Task> queue_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace softtune::render
