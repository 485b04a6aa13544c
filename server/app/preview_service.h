#pragma once
// Preview frames for a request: {"preset": NAME} or {"scene": {...}} (a Box2D scene, drawn from its
// snapshots), or tune fields (the 1-D oscillator with its analytic ghost), plus "frames", "size",
// "filmstrip_every", "mass_model", "engine" and "engine_settings" (a scene's engine, simulate_app.h), "animation" ("webp" or "gif": a clip encoded while the frames render)
// and "wait". One long-lived frame pipeline serves every request; its
// workers start their raster processes (softtune-raster, which hold the GL contexts) only when the first
// frame is asked for, and end them when idle (render::PipelineOptions::release_renderer_after_ms).

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "softtune/render/clip.h"
#include "softtune/render/frame_pipeline.h"

namespace softtune::app {

/// What to render: the canonical request text (its hash names the result), the settings, and the
/// function that simulates and builds the draw model (run only when the result is not cached).
struct PreviewPlan {
  std::string canonical;
  render::PreviewSettings settings;
  std::function<render::FrameSet()> make_frames;
  bool wait = true;               ///< answer when done (true) or at once with a progress URL (false)
  std::optional<render::ClipFormat> clip;  ///< "animation": encode this clip while the frames render
  double frame_dt_s = 0.0;        ///< s of scene time between frames on average, so a client plays them in real time
  double run_end_s = 0.0;         ///< s, the run's end: the last frame's time (a run that stopped early ends sooner)
  nlohmann::json warnings = nlohmann::json::array();
  nlohmann::json engine;          ///< a scene preview: the engine it runs in {name, version, settings}; null otherwise
  std::shared_ptr<StageList> prepare_stages = std::make_shared<StageList>();  ///< filled by make_frames
};

/// Reads a preview request; throws Problem (422) naming the field.
PreviewPlan plan_preview(const nlohmann::json& request, const std::string& presets_dir);

/// Requests that may wait ("wait": true) for frames still rendering at one time. The render pool
/// draws one preview at a time on all its workers, so a further waiter would only hold one of the
/// server's worker threads, and enough of them starve health and tune: 16 waiting previews on 8
/// threads kept health from answering for 4 s. Past this cap a request is answered at once, as with
/// "wait": false, with a `wait_declined` warning; its render goes on.
inline constexpr int kMaxPreviewWaiters = 2;

/// Bytes of clips kept (LRU), beside the frame pipeline's own cache.
inline constexpr std::size_t kClipCacheBytes = std::size_t{64} << 20;

class PreviewService {
 public:
  explicit PreviewService(render::PipelineOptions options = {}, int max_waiters = kMaxPreviewWaiters);

  /// Starts (or finds) a preview; `url_prefix` is where its frames are served ("/api/v1/preview").
  nlohmann::json start(const nlohmann::json& request, const std::string& presets_dir, const std::string& url_prefix);
  /// Progress of a job in flight, or the finished answer; nullopt for an unknown id.
  std::optional<nlohmann::json> status(const std::string& id, const std::string& url_prefix);
  /// PNG bytes of frame n, or of the filmstrip; nullopt when the id or frame is unknown.
  std::optional<std::string> frame_png(const std::string& id, int n);
  std::optional<std::string> filmstrip_png(const std::string& id);
  /// The finished preview as an animated WebP or GIF (render/clip.h), made on first ask and kept in a
  /// byte-bounded cache of its own; nullopt when the id is unknown. One clip encodes at a time, so clips
  /// never take more than one core; a preview above render::caps::kMaxClipPixels is a 422 naming `frames`.
  std::optional<std::string> clip(const std::string& id, render::ClipFormat format);

  support::LruStats cache_stats() const { return pipeline_.cache_stats(); }
  support::LruStats clip_cache_stats() const { return clips_.stats(); }

 private:
  nlohmann::json answer(const render::PreviewJob& job, const std::string& url_prefix) const;

  render::FramePipeline pipeline_;
  support::LruCache<std::string, std::string> clips_{support::LruBounds{.max_bytes = kClipCacheBytes}};
  std::mutex clip_mutex_;  ///< held while a clip encodes
  const int max_waiters_;
  std::atomic<int> waiters_{0};
};

}  // namespace softtune::app
