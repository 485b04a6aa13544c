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

/// What a caller hands the pipeline: one draw model per frame and the camera for all of them (an
/// auto-fit camera is fitted once to the bounds of every frame, so the view does not jump).
struct FrameSet {
  Camera camera;
  std::vector<DrawFrame> frames;
};

/// The one camera for a run: `set.camera` if fixed, else fitted to the bounds of every frame.
Camera run_camera(const FrameSet& set, ImageSize size);

struct PreviewTimings {
  double wall_ms = 0.0;       ///< submit to finished
  double prepare_ms = 0.0;    ///< the caller's make_frames (simulation and draw model)
  double render_ms = 0.0;     ///< summed over frames: tessellation, raster and read-back
  double png_ms = 0.0;        ///< summed over frames: PNG encoding
  double filmstrip_ms = 0.0;  ///< the filmstrip PNG
  int workers = 0;            ///< render workers in the pool
};

/// A finished preview: PNG bytes of every frame and of the filmstrip.
struct Preview {
  std::string id;  ///< content hash of the canonical request and settings (64 hex digits)
  PreviewSettings settings;
  FilmstripLayout filmstrip;
  std::vector<std::string> frames_png;
  std::string filmstrip_png;
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
  /// Blocks until every frame is done; throws std::runtime_error when rendering failed.
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
};

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
  /// Throws std::invalid_argument for settings that break a cap.
  std::shared_ptr<PreviewJob> submit(std::string_view canonical_request, const PreviewSettings& settings,
                                     const std::function<FrameSet()>& make_frames);

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
