#include "softtune/render/frame_pipeline.h"

#include <chrono>
#include <stdexcept>

#include "softtune/render/content_hash.h"
#include "softtune/render/png.h"
#include "softtune/render/tessellate.h"
#include "softtune/support/run_limit.h"

namespace softtune::render {

using Clock = std::chrono::steady_clock;

namespace {

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

}  // namespace

/// Everything one request shares between the submitter, the workers and the waiters.
struct JobState {
  std::string id;
  PreviewSettings settings;
  Clock::time_point started = Clock::now();
  bool from_cache = false;

  // Filled before the first task is queued, then read-only until finish().
  FrameSet frames;
  std::vector<Camera> cameras;  // one per frame
  std::optional<Filmstrip> filmstrip;
  double prepare_ms = 0.0;
  std::vector<std::string> pngs;  // each worker writes only its own frames' entries
  // ready[i] is set (release) once pngs[i] is written, so frame_png() can serve it before the job ends.
  std::unique_ptr<std::atomic<bool>[]> ready;

  // The clip stage (submit's `clip`): the encoder, the next frame it takes, and frames rendered before
  // their turn (pixels, or empty: decode pngs[i]). clip_mutex is held while encoding; clip_queue_mutex
  // guards clip_next and clip_pixels.
  std::optional<ClipFormat> clip_format;
  std::unique_ptr<ClipEncoder> clip;
  std::mutex clip_mutex, clip_queue_mutex;
  int clip_next = 0;
  std::vector<std::vector<std::uint8_t>> clip_pixels;
  std::atomic<std::int64_t> clip_ns{0};

  std::atomic<int> done{0};
  std::atomic<bool> failed{false};
  std::atomic<std::int64_t> render_ns{0}, png_ns{0};
  // The job's CPU time so far (PipelineOptions::job_cpu_seconds), ns: workers' threads and raster processes.
  double cpu_limit_s = 0.0;
  std::atomic<std::int64_t> cpu_ns{0};
  std::atomic<bool> over_budget{false};

  mutable std::mutex mutex;  // guards the fields below
  mutable std::condition_variable cv;
  bool finished = false;
  std::string error;
  std::shared_ptr<const Preview> result;
  // The preview finish() is building: it holds the frames from their move until complete() (frame_png()
  // serves them from here in that window, when `pngs` is already empty).
  std::shared_ptr<const Preview> building;

  void complete(std::shared_ptr<const Preview> preview, std::string failure) {
    {
      std::lock_guard lock(mutex);
      result = std::move(preview);
      error = std::move(failure);
      building.reset();
      finished = true;
    }
    cv.notify_all();
  }
};

std::optional<FieldError> validate_preview_settings(const PreviewSettings& s) {
  if (s.frames < 1 || s.frames > caps::kMaxFrames) {
    return FieldError{"frames", "must be an integer in [1, " + std::to_string(caps::kMaxFrames) + "]"};
  }
  if (s.size.width < caps::kMinSide || s.size.height < caps::kMinSide || s.size.width > caps::kMaxWidth ||
      s.size.height > caps::kMaxHeight) {
    return FieldError{"size", "must be WxH with " + std::to_string(caps::kMinSide) + " <= W <= " +
                                  std::to_string(caps::kMaxWidth) + " and " + std::to_string(caps::kMinSide) +
                                  " <= H <= " + std::to_string(caps::kMaxHeight) + " pixels"};
  }
  if (s.filmstrip_every < 0 || s.filmstrip_every > s.frames) {
    return FieldError{"filmstrip_every", "must be 0 (automatic) or an integer in [1, frames]"};
  }
  return std::nullopt;
}

Camera run_camera(const FrameSet& set, ImageSize size) {
  const std::vector<Camera> cameras = run_cameras(set.camera, set.follow, set.frames, size);
  return cameras.empty() ? set.camera : cameras.front();
}

// What the cache really holds: string capacities, not sizes.
std::size_t Preview::bytes() const {
  std::size_t n = sizeof(Preview) + id.capacity() + filmstrip_png.capacity() + clip.capacity() + frames_png.capacity() * sizeof(std::string) +
                  frame_times_s.capacity() * sizeof(double);
  for (const std::string& f : frames_png) n += f.capacity();
  return n;
}

const std::string& PreviewJob::id() const { return state_->id; }
bool PreviewJob::from_cache() const { return state_->from_cache; }

PreviewProgress PreviewJob::progress() const {
  PreviewProgress p;
  p.total = state_->settings.frames;
  p.done = state_->done.load(std::memory_order_acquire);
  std::lock_guard lock(state_->mutex);
  p.finished = state_->finished;
  p.failed = state_->finished && !state_->result;
  if (p.finished && state_->result) p.done = p.total;
  if (p.finished) {
    p.ready = state_->result ? p.total : 0;
  } else if (state_->ready) {
    while (p.ready < p.total && state_->ready[p.ready].load(std::memory_order_acquire)) ++p.ready;
  }
  return p;
}

std::optional<std::string> PreviewJob::frame_png(int n) const {
  if (n < 0 || n >= state_->settings.frames) return std::nullopt;
  // Under the job's mutex: finish() moves the frames into the result under it too.
  std::lock_guard lock(state_->mutex);
  if (state_->finished) {
    if (!state_->result) return std::nullopt;
    return state_->result->frames_png[n];
  }
  if (state_->building) return state_->building->frames_png[n];
  if (!state_->ready || !state_->ready[n].load(std::memory_order_acquire)) return std::nullopt;
  return state_->pngs[n];
}

std::shared_ptr<const Preview> PreviewJob::wait() const {
  std::unique_lock lock(state_->mutex);
  state_->cv.wait(lock, [this] { return state_->finished; });
  if (!state_->result && state_->over_budget.load(std::memory_order_acquire)) {
    throw support::RunStopped(support::RunStopped::Why::budget, state_->cpu_ns.load() * 1e-9, state_->cpu_limit_s);
  }
  if (!state_->result) throw std::runtime_error("preview " + state_->id + " failed: " + state_->error);
  return state_->result;
}

bool PreviewJob::wait_for(int timeout_ms) const {
  std::unique_lock lock(state_->mutex);
  return state_->cv.wait_for(lock, std::chrono::milliseconds(timeout_ms), [this] { return state_->finished; });
}

FramePipeline::FramePipeline(PipelineOptions options)
    : options_(std::move(options)), cache_(support::LruBounds{.max_bytes = options_.cache_bytes}) {
  if (!options_.make_renderer) {
    const RendererOptions ro = options_.renderer;
    options_.make_renderer = [ro] { return make_osmesa_renderer(ro); };
  }
  const int n = std::max(1, options_.workers);
  for (int i = 0; i < n; ++i) threads_.emplace_back([this] { worker_loop(); });
}

FramePipeline::~FramePipeline() {
  {
    std::lock_guard lock(queue_mutex_);
    stopping_ = true;
  }
  queue_cv_.notify_all();
  for (std::thread& t : threads_) t.join();
}

std::string FramePipeline::preview_id(std::string_view canonical_request, const PreviewSettings& s) {
  // The renderer's look is part of the result: bump the version when the drawing changes.
  constexpr std::string_view kRenderVersion = "softtune-preview-1";
  std::string text;
  text.reserve(canonical_request.size() + 96);
  text.append(kRenderVersion).append("\n");
  text.append(canonical_request).append("\nframes=").append(std::to_string(s.frames));
  text.append(" size=").append(std::to_string(s.size.width)).append("x").append(std::to_string(s.size.height));
  text.append(" filmstrip_every=").append(std::to_string(s.filmstrip_every));
  return sha256_hex(text);
}

namespace {

std::shared_ptr<PreviewJob> finished_job(std::shared_ptr<const Preview> preview) {
  auto state = std::make_shared<JobState>();
  state->id = preview->id;
  state->settings = preview->settings;
  state->from_cache = true;
  state->complete(std::move(preview), "");
  return std::make_shared<PreviewJob>(state);
}

}  // namespace

std::shared_ptr<const Preview> FramePipeline::cached(const std::string& id) { return cache_.get(id); }

std::shared_ptr<PreviewJob> FramePipeline::find(const std::string& id) {
  std::lock_guard lock(jobs_mutex_);
  if (auto it = in_flight_.find(id); it != in_flight_.end()) return std::make_shared<PreviewJob>(it->second);
  auto preview = cache_.get(id);
  return preview ? finished_job(std::move(preview)) : nullptr;
}

std::shared_ptr<PreviewJob> FramePipeline::submit(std::string_view canonical_request, const PreviewSettings& settings,
                                                  const std::function<FrameSet()>& make_frames,
                                                  std::optional<ClipFormat> clip) {
  if (auto e = validate_preview_settings(settings)) throw std::invalid_argument(e->field + " " + e->rule);
  if (clip) {
    if (auto e = validate_clip(settings.frames, settings.size)) throw std::invalid_argument(e->field + " " + e->rule);
  }
  const std::string id = preview_id(canonical_request, settings);
  std::shared_ptr<JobState> job;
  {
    // Looking in flight and in the cache under one lock: finish() caches before it leaves in_flight_.
    std::lock_guard lock(jobs_mutex_);
    if (auto it = in_flight_.find(id); it != in_flight_.end()) return std::make_shared<PreviewJob>(it->second);
    if (auto preview = cache_.get(id)) return finished_job(std::move(preview));
    job = std::make_shared<JobState>();
    job->id = id;
    job->settings = settings;
    job->cpu_limit_s = options_.job_cpu_seconds;
    in_flight_[id] = job;
  }
  try {
    const auto t0 = Clock::now();
    job->frames = make_frames();
    job->prepare_ms = ms_since(t0);
    if (static_cast<int>(job->frames.frames.size()) != settings.frames) {
      throw std::logic_error("preview: make_frames returned " + std::to_string(job->frames.frames.size()) +
                             " frames, settings ask for " + std::to_string(settings.frames));
    }
  } catch (const std::exception& e) {
    {
      std::lock_guard lock(jobs_mutex_);
      in_flight_.erase(id);
    }
    job->complete(nullptr, e.what());
    throw;
  }
  job->cameras = run_cameras(job->frames.camera, job->frames.follow, job->frames.frames, settings.size);
  if (!job->frames.frames.empty() && job->frames.frames.front().inset) {
    // One corner for the whole run, where the action is not.
    const Corner corner = quietest_corner(job->frames.frames, job->cameras, settings.size);
    for (DrawFrame& f : job->frames.frames) {
      if (f.inset) f.inset->corner = corner;
    }
  }
  job->filmstrip.emplace(filmstrip_layout(settings.frames, settings.filmstrip_every, settings.size));
  job->pngs.resize(settings.frames);
  job->ready = std::make_unique<std::atomic<bool>[]>(settings.frames);
  if (clip) {
    job->clip_format = clip;
    std::vector<double> times = job->frames.times_s;
    if (times.size() != static_cast<std::size_t>(settings.frames)) {
      times.resize(settings.frames);
      for (int i = 0; i < settings.frames; ++i) times[i] = i / 60.0;
    }
    job->clip = make_clip_encoder(*clip, settings.size, times, options_.webp);
    job->clip_pixels.resize(settings.frames);
  }
  {
    // Newest job first: a designer's latest change is the preview they wait for, while the frames of the one
    // it replaced still render after it (cached, for undo). With a FIFO a drag's new first frame waited for
    // the whole tail of the previous preview (a page-latency p95 of 0.8 s). Within a job, frame 0 first.
    std::lock_guard lock(queue_mutex_);
    for (int i = settings.frames - 1; i >= 0; --i) queue_.push_front({job, i});
  }
  queue_cv_.notify_all();
  return std::make_shared<PreviewJob>(job);
}

void FramePipeline::worker_loop() {
  // Made on this thread's first frame and kept while frames keep coming (a raster process and its GL
  // context take about 60 ms to start); destroyed after release_renderer_after_ms without one.
  std::unique_ptr<Renderer> renderer;
  std::vector<std::uint8_t> pixels;
  const auto ready = [this] { return stopping_ || !queue_.empty(); };
  for (;;) {
    Task task;
    {
      std::unique_lock lock(queue_mutex_);
      if (renderer && options_.release_renderer_after_ms > 0) {
        if (!queue_cv_.wait_for(lock, std::chrono::milliseconds(options_.release_renderer_after_ms), ready)) {
          lock.unlock();
          renderer.reset();
          std::vector<std::uint8_t>().swap(pixels);
          continue;
        }
      } else {
        queue_cv_.wait(lock, ready);
      }
      if (queue_.empty()) return;
      task = std::move(queue_.front());
      queue_.pop_front();
    }
    run_task(task, renderer, pixels);
  }
}

void FramePipeline::run_task(const Task& task, std::unique_ptr<Renderer>& renderer, std::vector<std::uint8_t>& pixels) {
  JobState& job = *task.job;
  if (!job.failed.load(std::memory_order_acquire)) {
    try {
      const ImageSize size = job.settings.size;
      pixels.resize(rgba_bytes(size));
      if (!renderer) renderer = options_.make_renderer();
      const double cpu0 = support::thread_cpu_seconds() + renderer->raster_cpu_seconds();
      const auto t0 = Clock::now();
      renderer->render(job.frames.frames[task.index], job.cameras[task.index], size, pixels);
      job.filmstrip->place(task.index, pixels, size);
      const auto t1 = Clock::now();
      job.pngs[task.index] = encode_png(pixels, size, options_.png);
      if (job.clip) {
        std::lock_guard lock(job.clip_queue_mutex);
        if (task.index - job.clip_next < kClipPendingFrames) job.clip_pixels[task.index] = pixels;
      }
      job.ready[task.index].store(true, std::memory_order_release);
      const auto t2 = Clock::now();
      job.render_ns.fetch_add(std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count());
      job.png_ns.fetch_add(std::chrono::duration_cast<std::chrono::nanoseconds>(t2 - t1).count());
      if (job.clip) feed_clip(job, false);
      charge_frame(job, support::thread_cpu_seconds() + renderer->raster_cpu_seconds() - cpu0);
    } catch (const std::exception& e) {
      std::lock_guard lock(job.mutex);
      if (job.error.empty()) job.error = "frame " + std::to_string(task.index) + ": " + e.what();
      job.failed.store(true, std::memory_order_release);
    }
  }
  // The last frame's worker sees every other worker's writes (acq_rel) and finishes the job.
  if (job.done.fetch_add(1, std::memory_order_acq_rel) + 1 == job.settings.frames) finish(job);
}

// Adds a frame's CPU time to its job; past the job's limit the job fails, so its frames still queued are
// skipped (run_task) and the preview ends within one frame per worker of its limit.
void FramePipeline::charge_frame(JobState& job, double cpu_seconds) {
  const std::int64_t total = job.cpu_ns.fetch_add(static_cast<std::int64_t>(cpu_seconds * 1e9)) +
                             static_cast<std::int64_t>(cpu_seconds * 1e9);
  if (job.cpu_limit_s <= 0.0 || total * 1e-9 <= job.cpu_limit_s) return;
  std::lock_guard lock(job.mutex);
  if (job.error.empty()) {
    job.error = "its frames took " + std::to_string(total * 1e-9) + " s of CPU time, past the limit of " +
                std::to_string(job.cpu_limit_s) + " s";
  }
  job.over_budget.store(true, std::memory_order_release);
  job.failed.store(true, std::memory_order_release);
}

// Hands the encoder every frame whose turn has come, in order. Without `wait` it returns at once when
// another worker holds the encoder; that worker looks again after it lets go, so no frame is left behind
// (a frame is marked ready before its worker comes here). A failure fails the job.
void FramePipeline::feed_clip(JobState& job, bool wait) {
  for (;;) {
    std::unique_lock encoding(job.clip_mutex, std::defer_lock);
    if (wait) {
      encoding.lock();
    } else if (!encoding.try_lock()) {
      return;
    }
    for (;;) {
      int i = 0;
      std::vector<std::uint8_t> pixels;
      {
        std::lock_guard lock(job.clip_queue_mutex);
        i = job.clip_next;
        if (i >= job.settings.frames || !job.ready[i].load(std::memory_order_acquire)) break;
        pixels = std::move(job.clip_pixels[i]);
        std::vector<std::uint8_t>().swap(job.clip_pixels[i]);
      }
      const auto t0 = Clock::now();
      try {
        if (!job.failed.load(std::memory_order_acquire)) {
          if (pixels.empty()) {
            ImageSize decoded;
            pixels = decode_png(job.pngs[i], decoded);
          }
          job.clip->add(pixels);
        }
      } catch (const std::exception& e) {
        std::lock_guard lock(job.mutex);
        if (job.error.empty()) job.error = "clip, frame " + std::to_string(i) + ": " + e.what();
        job.failed.store(true, std::memory_order_release);
      }
      job.clip_ns.fetch_add(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count());
      std::lock_guard lock(job.clip_queue_mutex);
      job.clip_next = i + 1;
    }
    encoding.unlock();
    if (wait) return;
    std::lock_guard lock(job.clip_queue_mutex);
    const int next = job.clip_next;
    if (next >= job.settings.frames || !job.ready[next].load(std::memory_order_acquire)) return;
  }
}

void FramePipeline::finish(JobState& job) {
  double clip_tail_ms = 0.0;
  std::string clip_bytes;
  if (job.clip) {
    const auto t0 = Clock::now();
    feed_clip(job, true);
    try {
      if (!job.failed.load(std::memory_order_acquire)) clip_bytes = job.clip->finish();
    } catch (const std::exception& e) {
      std::lock_guard lock(job.mutex);
      if (job.error.empty()) job.error = std::string("clip: ") + e.what();
      job.failed.store(true, std::memory_order_release);
    }
    job.clip.reset();
    clip_tail_ms = ms_since(t0);
  }
  std::shared_ptr<Preview> preview;
  std::string error;
  if (job.failed.load(std::memory_order_acquire)) {
    std::lock_guard lock(job.mutex);
    error = job.error;
  } else {
    try {
      preview = std::make_shared<Preview>();
      preview->id = job.id;
      preview->settings = job.settings;
      preview->filmstrip = job.filmstrip->layout();
      {
        std::lock_guard lock(job.mutex);  // frame_png() may be reading a frame of this job
        preview->frames_png = std::move(job.pngs);
        job.building = preview;  // frame_png() reads the frames here until complete()
      }
      preview->frame_times_s = job.frames.times_s;
      preview->run_end_s = job.frames.run_end_s;
      if (job.clip_format) {
        preview->clip_format = job.clip_format;
        preview->clip = std::move(clip_bytes);
      }
      if (preview->frame_times_s.size() != preview->frames_png.size()) {
        preview->frame_times_s.resize(preview->frames_png.size());
        for (std::size_t i = 0; i < preview->frame_times_s.size(); ++i) preview->frame_times_s[i] = i / 60.0;
      }
      const auto t0 = Clock::now();
      preview->filmstrip_png = job.filmstrip->encode(options_.png);
      preview->stages.add(Stage::render);
      preview->stages.add(Stage::png_encode);
      PreviewTimings& t = preview->timings;
      t.filmstrip_ms = ms_since(t0);
      t.prepare_ms = job.prepare_ms;
      t.render_ms = job.render_ns.load() * 1e-6;
      t.png_ms = job.png_ns.load() * 1e-6;
      t.clip_ms = job.clip_ns.load() * 1e-6;
      t.clip_tail_ms = clip_tail_ms;
      t.workers = workers();
      t.wall_ms = ms_since(job.started);
      cache_.put(job.id, preview, preview->bytes());
    } catch (const std::exception& e) {
      preview.reset();
      error = e.what();
    }
  }
  job.frames = {};
  job.cameras.clear();
  job.filmstrip.reset();
  {
    std::lock_guard lock(jobs_mutex_);
    in_flight_.erase(job.id);
  }
  job.complete(preview, error);
}

}  // namespace softtune::render
