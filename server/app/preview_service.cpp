#include "app/preview_service.h"

#include "app/scene_tuning.h"
#include "app/scene_cost.h"
#include "app/simulate_app.h"

#include <algorithm>

#include "codec/json_reader.h"
#include "codec/json_writer.h"
#include "app/preset_store.h"
#include "codec/preview_codec.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "app/ghost_tuning.h"
#include "app/scene_frames.h"
#include "codec/tune_codec.h"
#include "softtune/render/oscillator_frames.h"

namespace softtune::app {

using namespace softtune::codec;  // the codec is this layer's JSON vocabulary

namespace {

using nlohmann::json;

constexpr const char* kTuneFields[] = {"fps", "substeps", "response_frames", "basis_fps", "frequency_hz",
                                       "oscillation", "damping_ratio", "mode", "effective_mass", "constraint"};

// The oscillator preset's first oscillator as a tune request, with the preset's step rate.
json oscillator_preset_tuning(const json& preset, double& initial_displacement) {
  const json& osc = preset.at("oscillators").at(0);
  json tune = json::object();
  for (const char* key : kTuneFields) {
    if (osc.contains(key)) tune[key] = osc[key];
  }
  const json& world = preset.value("world", json::object());
  for (const char* key : {"fps", "substeps"}) {
    if (world.contains(key)) tune[key] = world[key];
  }
  initial_displacement = osc.value("initial_displacement", 0.5);
  return tune;
}

void plan_oscillator(PreviewPlan& plan, const TuneRequest& request, double initial_displacement) {
  render::OscillatorScene scene = render::oscillator_scene(request, tune(request));
  scene.initial_displacement_m = initial_displacement;
  plan.canonical = "oscillator:" + canonical_oscillator_request(scene);
  plan.frame_dt_s = 1.0 / scene.fps;  // one frame per game frame (oscillator_frames.h)
  const int frames = plan.settings.frames;
  auto stages = plan.prepare_stages;
  plan.make_frames = [scene, frames, stages] {
    stages->add(Stage::core_integrator);
    return render::oscillator_frames(scene, frames);
  };
}

// `prefix` is where the scene sits in the request ("scene." or ""), for the cost's field names.
void plan_scene(PreviewPlan& plan, const json& scene_doc, std::optional<scene::MassModel> mass_model,
                const json* ghost_doc, const std::string& prefix) {
  const scene::Scene scene = decode_requested_scene(scene_doc, prefix);
  std::optional<scene::Scene> ghost;
  if (ghost_doc) ghost = ghost_scene(scene, *ghost_doc);
  const int total = scene::frame_count(scene.world);
  if (total + 1 < plan.settings.frames) {
    plan.warnings.push_back({{"code", "frames_clamped"},
                             {"message", "the scene runs " + std::to_string(total + 1) + " frames; " +
                                             std::to_string(plan.settings.frames) + " were asked for"}});
    plan.settings.frames = total + 1;
  }
  // Snapshots at frames 0, stride, 2 stride, ...: at least settings.frames of them.
  scene::RunOptions options;
  options.record_frames = true;
  options.frame_stride = plan.settings.frames > 1 ? std::max(1, total / (plan.settings.frames - 1)) : 1;
  options.mass_model = mass_model;
  plan.frame_dt_s = options.frame_stride / scene.world.fps;
  // The run happens on the render pool, which draws one preview at a time: a scene over the budget would
  // hold every preview behind it. A ghost runs the scene a second time.
  RequestCost cost = scene_cost(scene, options, prefix);
  if (ghost) {
    const RequestCost second = scene_cost(*ghost, options, prefix);
    cost.cpu_seconds += second.cpu_seconds;
    cost.peak_bytes += second.peak_bytes;
    cost.work += " (twice: the ghost tuning runs the scene again)";
  }
  require_within_budget(cost);
  plan.canonical = "scene:" + scene_doc.dump() + "|mass_model:" +
                   (mass_model ? std::string(scene::mass_model_name(*mass_model)) : "scene") +
                   "|stride:" + std::to_string(options.frame_stride) + (ghost_doc ? "|ghost:" + ghost_doc->dump() : "");
  const int frames = plan.settings.frames;
  auto stages = plan.prepare_stages;
  plan.make_frames = [scene, ghost, options, frames, stages] {
    const scene::SceneResult result = scene::run_scene(scene, options);
    stages->append(result.stages);
    if (result.error) throw invalid_field(result.error->field, result.error->rule);
    if (result.snapshots.empty()) throw invalid_field("scene", "has no bodies to draw (an oscillator-only scene: "
                                                              "ask with its tune fields instead)");
    std::vector<scene::Snapshot> used(result.snapshots.begin(),
                                      result.snapshots.begin() + std::min<std::size_t>(frames, result.snapshots.size()));
    while (static_cast<int>(used.size()) < frames) used.push_back(used.back());  // a run that stopped early
    render::FrameSet set = scene_frames(scene, used, &result);
    if (ghost) {
      const scene::SceneResult b = scene::run_scene(*ghost, options);
      if (b.error) throw invalid_field("ghost", b.error->rule);
      for (int i = 0; i < frames && !b.snapshots.empty(); ++i) {
        add_ghost(set.frames[i], *ghost, b.snapshots[std::min<std::size_t>(i, b.snapshots.size() - 1)]);
      }
      // The ghost's first legend line (its mode target, or its first joint's ask), once for every frame; a
      // legend with nothing to say (no line) still names the ghost.
      const std::vector<std::string> lines = scene_legend(*ghost, b);
      const std::string ghost_line = "pink ghost: " + (lines.empty() ? std::string("the second tuning") : lines.front());
      for (render::DrawFrame& f : set.frames) f.legend.push_back(ghost_line);
    }
    return set;
  };
}

}  // namespace

PreviewPlan plan_preview(const json& request, const std::string& presets_dir) {
  ObjectReader r = read_object(request, "");
  PreviewPlan plan;
  plan.settings = read_preview_settings(r);
  if (auto v = r.raw("wait")) {
    if (!v->is_boolean()) throw invalid_field("wait", "must be true or false");
    plan.wait = v->get<bool>();
  }
  const auto mass_model = read_mass_model(r);
  const bool has_tune_fields = std::any_of(std::begin(kTuneFields), std::end(kTuneFields),
                                           [&r](const char* key) { return r.has(key); });
  const bool oscillator_preset = r.has("preset") && request["preset"] == "oscillator";
  const json* ghost = r.raw("ghost");
  if (ghost && !(r.has("preset") || r.has("scene"))) {
    throw invalid_field("ghost", "a second tuning applies to preset and scene previews (the oscillator has its exact ghost)");
  }
  if ((r.has("preset") || r.has("scene")) && has_tune_fields) {
    throw invalid_field("preset", "give a preset or scene, or tune fields for the oscillator, not both");
  }
  if (oscillator_preset) {
    if (ghost) throw invalid_field("ghost", "a second tuning applies to Box2D scene previews (the oscillator has its exact ghost)");
    r.raw("preset");
    double x0 = 0.5;
    json preset = load_preset(presets_dir, "oscillator");
    if (const json* t = r.raw("tuning")) apply_scene_tuning(preset, *t);
    const json tuning = oscillator_preset_tuning(preset, x0);
    plan_oscillator(plan, decode_tune_request(tuning), x0);
  } else if (r.has("preset") || r.has("scene")) {
    plan_scene(plan, requested_scene_document(r, request, presets_dir, {}), mass_model, ghost, r.has("scene") ? "scene." : "");
  } else if (has_tune_fields) {
    plan_oscillator(plan, read_tune_fields(r), 0.5);
  } else {
    throw invalid_field("preset", "give a preset name, a scene, or tune fields (an oscillator)");
  }
  r.finish();
  if (auto e = render::validate_preview_settings(plan.settings)) throw invalid_field(e->field, e->rule);
  return plan;
}

PreviewService::PreviewService(render::PipelineOptions options, int max_waiters)
    : pipeline_(std::move(options)), max_waiters_(max_waiters) {}

json PreviewService::answer(const render::PreviewJob& job, const std::string& url_prefix) const {
  const std::string base = url_prefix + "/" + job.id();
  const render::PreviewProgress p = job.progress();
  if (!p.finished) {
    return {{"id", job.id()}, {"status", p.failed ? "failed" : "rendering"},
            {"progress", {{"done", p.done}, {"total", p.total}, {"ready", p.ready}}}, {"progress_url", base}};
  }
  json out = encode_preview(*job.wait(), job.from_cache(), [&base](int n) { return base + "/" + std::to_string(n) + ".png"; },
                            base + "/filmstrip.png");
  out["status"] = "done";
  if (!render::validate_clip(p.total, job.wait()->settings.size)) {
    out["animation"] = {{"webp", base + "/animation.webp"}, {"gif", base + "/animation.gif"}};
  }
  out["progress"] = {{"done", p.done}, {"total", p.total}, {"ready", p.ready}};
  out["progress_url"] = base;
  return out;
}

json PreviewService::start(const json& request, const std::string& presets_dir, const std::string& url_prefix) {
  PreviewPlan plan = plan_preview(request, presets_dir);
  const auto job = pipeline_.submit(plan.canonical, plan.settings, plan.make_frames);
  if (plan.wait) {
    // A request whose frames are done (cached, or failed already) takes no waiter's slot. A slot is
    // taken before the check, so two racing requests cannot both pass at the cap.
    struct Slot {
      std::atomic<int>* n = nullptr;
      ~Slot() {
        if (n) n->fetch_sub(1, std::memory_order_acq_rel);
      }
    } slot;
    bool may_wait = true;
    if (!job->progress().finished) {
      slot.n = &waiters_;
      may_wait = waiters_.fetch_add(1, std::memory_order_acq_rel) < max_waiters_;
    }
    if (may_wait) {
      try {
        job->wait();
      } catch (const std::runtime_error& e) {
        throw Problem(500, "Render failed", "", e.what());
      }
    } else {
      plan.warnings.push_back({{"code", "wait_declined"},
                               {"message", std::to_string(max_waiters_) +
                                               " requests already wait for frames; answered at once: "
                                               "poll progress_url"}});
    }
  }
  json out = answer(*job, url_prefix);
  const render::PreviewProgress p = job->progress();
  if (!job->from_cache() && p.finished && !p.failed) {
    // The stages that ran this time: the simulation, then rendering.
    StageList all = *plan.prepare_stages;
    all.append(job->wait()->stages);
    out["stages"] = stages_json(all);
  }
  out["frame_dt_s"] = plan.frame_dt_s;
  out["warnings"] = plan.warnings;
  return out;
}

std::optional<json> PreviewService::status(const std::string& id, const std::string& url_prefix) {
  const auto job = pipeline_.find(id);
  if (!job) return std::nullopt;
  return answer(*job, url_prefix);
}

std::optional<std::string> PreviewService::frame_png(const std::string& id, int n) {
  if (const auto preview = pipeline_.cached(id)) {
    if (n < 0 || n >= static_cast<int>(preview->frames_png.size())) return std::nullopt;
    return preview->frames_png[n];
  }
  // Frames stream: one already encoded is served while the others still render.
  const auto job = pipeline_.find(id);
  return job ? job->frame_png(n) : std::nullopt;
}

std::optional<std::string> PreviewService::filmstrip_png(const std::string& id) {
  const auto preview = pipeline_.cached(id);
  if (!preview) return std::nullopt;
  return preview->filmstrip_png;
}

std::optional<std::string> PreviewService::clip(const std::string& id, render::ClipFormat format) {
  const std::string key = id + "." + std::string(render::clip_format_name(format));
  if (auto hit = clips_.get(key)) return *hit;
  const auto preview = pipeline_.cached(id);
  if (!preview) return std::nullopt;
  if (auto e = render::validate_clip(static_cast<int>(preview->frames_png.size()), preview->settings.size)) {
    throw invalid_field(e->field, e->rule);
  }
  std::lock_guard lock(clip_mutex_);
  if (auto hit = clips_.get(key)) return *hit;  // made while this request waited
  auto bytes = std::make_shared<const std::string>(render::encode_clip(format, preview->frames_png, preview->frame_times_s));
  clips_.put(key, bytes, bytes->size() + key.size());
  return *bytes;
}

}  // namespace softtune::app
