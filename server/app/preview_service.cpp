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
#include "softtune/render/frame_schedule.h"
#include "softtune/support/run_limit.h"
#include "softtune/render/oscillator_frames.h"

namespace softtune::app {

using namespace softtune::codec;  // the codec is this layer's JSON vocabulary

namespace {

using nlohmann::json;

constexpr const char* kTuneFields[] = {"fps", "substeps", "response_frames", "basis_fps", "frequency_hz",
                                       "oscillation", "damping_ratio", "mode", "effective_mass", "constraint"};

// The oscillator preset's first oscillator as a tune request, with the preset's step rate.
json oscillator_preset_tuning(const json& preset, double& initial_displacement, double& duration_s) {
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
  duration_s = world.value("duration_s", render::OscillatorScene{}.duration_s);
  return tune;
}

// A run of `run_frames` steps shows at most run_frames + 1 frames (spread_frames).
void clamp_frames(PreviewPlan& plan, int run_frames) {
  if (run_frames + 1 >= plan.settings.frames) return;
  plan.warnings.push_back({{"code", "frames_clamped"},
                           {"message", "the run has " + std::to_string(run_frames + 1) + " frames; " +
                                           std::to_string(plan.settings.frames) + " were asked for"}});
  plan.settings.frames = run_frames + 1;
}

// s between two frames on average (they fall on game frames, so one gap may be a step longer than the next).
double mean_frame_dt(int run_frames, double fps, int frames) {
  return frames > 1 ? run_frames / fps / (frames - 1) : 0.0;
}

void plan_oscillator(PreviewPlan& plan, const TuneRequest& request, double initial_displacement, double duration_s) {
  render::OscillatorScene scene = render::oscillator_scene(request, tune(request));
  scene.initial_displacement_m = initial_displacement;
  scene.duration_s = duration_s;
  plan.canonical = "oscillator:" + canonical_oscillator_request(scene);
  const int run_frames = render::oscillator_run_frames(scene);
  clamp_frames(plan, run_frames);
  plan.frame_dt_s = mean_frame_dt(run_frames, scene.fps, plan.settings.frames);
  plan.run_end_s = run_frames / scene.fps;
  const int frames = plan.settings.frames;
  auto stages = plan.prepare_stages;
  plan.make_frames = [scene, frames, stages] {
    stages->add(Stage::core_integrator);
    return render::oscillator_frames(scene, frames);
  };
}

// "layers": {"contacts": bool, ...} over the scene's defaults (scene_frames.h, SceneLayers).
SceneLayers read_layers(const json* doc, const scene::Scene& scene) {
  SceneLayers layers = default_layers(scene);
  if (!doc) return layers;
  if (!doc->is_object()) throw invalid_field("layers", "must be an object of layer names and true or false");
  const std::pair<const char*, bool SceneLayers::*> names[] = {
      {"contacts", &SceneLayers::contacts},     {"anchors", &SceneLayers::anchors},
      {"rest_marks", &SceneLayers::rest_marks}, {"wheel_axes", &SceneLayers::wheel_axes},
      {"mass_centres", &SceneLayers::mass_centres}, {"inset", &SceneLayers::inset}};
  for (const auto& item : doc->items()) {
    // Named, not a structured binding: clang 14 (the sanitizer builds) cannot capture one in a lambda.
    const std::string& key = item.key();
    const json& value = item.value();
    const auto it = std::find_if(std::begin(names), std::end(names), [&key](const auto& n) { return key == n.first; });
    if (it == std::end(names)) {
      throw invalid_field("layers." + key, "is not a layer (contacts, anchors, rest_marks, wheel_axes, mass_centres, inset)");
    }
    if (!value.is_boolean()) throw invalid_field("layers." + key, "must be true or false");
    layers.*(it->second) = value.get<bool>();
  }
  return layers;
}

std::string layers_text(const SceneLayers& l) {
  return std::string(l.contacts ? "c" : "-") + (l.anchors ? "a" : "-") + (l.rest_marks ? "r" : "-") +
         (l.wheel_axes ? "w" : "-") + (l.mass_centres ? "m" : "-") + (l.inset ? "i" : "-");
}

// `prefix` is where the scene sits in the request ("scene." or ""), for the cost's field names.
void plan_scene(PreviewPlan& plan, const json& scene_doc, std::optional<scene::MassModel> mass_model,
                const SceneEngineChoice& engine, const json* ghost_doc, const json* layers_doc, const std::string& prefix) {
  const scene::Scene scene = decode_requested_scene(scene_doc, prefix);
  const SceneLayers layers = read_layers(layers_doc, scene);
  std::optional<scene::Scene> ghost;
  if (ghost_doc) ghost = ghost_scene(scene, *ghost_doc);
  const int total = scene::frame_count(scene.world);
  clamp_frames(plan, total);
  // Snapshots spread over the whole run: the first at t = 0, the last at the run's end.
  scene::RunOptions options;
  options.record_frames = true;
  options.record_at = render::spread_frames(total, plan.settings.frames);
  options.mass_model = mass_model;
  apply_scene_engine(engine, options);
  plan.engine = scene_engine_json(engine);
  plan.frame_dt_s = mean_frame_dt(total, scene.world.fps, plan.settings.frames);
  plan.run_end_s = total / scene.world.fps;
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
                   "|engine:" + scene_engine_key(engine) + "|spread:" + std::to_string(plan.settings.frames) + "|layers:" + layers_text(layers) + (ghost_doc ? "|ghost:" + ghost_doc->dump() : "");
  const int frames = plan.settings.frames;
  auto stages = plan.prepare_stages;
  plan.make_frames = [scene, ghost, options, frames, stages, layers] {
    const scene::SceneResult result = scene::run_scene(scene, options);
    stages->append(result.stages);
    if (result.error) throw invalid_field(result.error->field, result.error->rule);
    if (result.snapshots.empty()) throw invalid_field("scene", "has no bodies to draw (an oscillator-only scene: "
                                                              "ask with its tune fields instead)");
    std::vector<scene::Snapshot> used(result.snapshots.begin(),
                                      result.snapshots.begin() + std::min<std::size_t>(frames, result.snapshots.size()));
    while (static_cast<int>(used.size()) < frames) used.push_back(used.back());  // a run that stopped early
    render::FrameSet set = scene_frames(scene, used, &result, layers);
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
  // Read for every preview, so a page sends its engine with each one; the oscillator's core integrators
  // ignore it, as a simulate of a scene without bodies does.
  const SceneEngineChoice engine = read_request_engine(r);
  if (auto name = r.string("animation")) {
    plan.clip = render::clip_format(*name);
    if (!plan.clip) throw invalid_field("animation", "must be \"webp\" or \"gif\"");
  }
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
  if (r.has("layers") && !(r.has("preset") || r.has("scene")) ) {
    throw invalid_field("layers", "debug layers apply to preset and scene previews");
  }
  if (oscillator_preset) {
    if (r.has("layers")) throw invalid_field("layers", "debug layers apply to Box2D scene previews");
    if (ghost) throw invalid_field("ghost", "a second tuning applies to Box2D scene previews (the oscillator has its exact ghost)");
    r.raw("preset");
    double x0 = 0.5, duration_s = 0.0;
    json preset = load_preset(presets_dir, "oscillator");
    if (const json* t = r.raw("tuning")) apply_scene_tuning(preset, *t);
    const json tuning = oscillator_preset_tuning(preset, x0, duration_s);
    plan_oscillator(plan, decode_tune_request(tuning), x0, duration_s);
  } else if (r.has("preset") || r.has("scene")) {
    plan_scene(plan, requested_scene_document(r, request, presets_dir, {}), mass_model, engine, ghost, r.raw("layers"),
               r.has("scene") ? "scene." : "");
  } else if (has_tune_fields) {
    plan_oscillator(plan, read_tune_fields(r), 0.5, render::OscillatorScene{}.duration_s);
  } else {
    throw invalid_field("preset", "give a preset name, a scene, or tune fields (an oscillator)");
  }
  r.finish();
  if (auto e = render::validate_preview_settings(plan.settings)) throw invalid_field(e->field, e->rule);
  // A clip over its cap is refused here, before anything is simulated or rendered.
  if (plan.clip) {
    if (auto e = render::validate_clip(plan.settings.frames, plan.settings.size)) throw invalid_field(e->field, e->rule);
  }
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
  const auto frame_url = [&base](int n) { return base + "/" + std::to_string(n) + ".png"; };
  json out = encode_preview(*job.wait(), job.from_cache(), frame_url, base + "/filmstrip.png");
  out["manifest"] = encode_frame_manifest(*job.wait(), frame_url);
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
  const auto job = pipeline_.submit(plan.canonical, plan.settings, plan.make_frames, plan.clip);
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
      } catch (const support::RunStopped&) {
        throw;  // past the frames' CPU limit: the service's 422 request-over-budget
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
  if (!plan.engine.is_null()) out["engine"] = plan.engine;
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
  if (preview->clip_format == format) return preview->clip;  // encoded while the frames rendered
  std::lock_guard lock(clip_mutex_);
  if (auto hit = clips_.get(key)) return *hit;  // made while this request waited
  auto bytes = std::make_shared<const std::string>(render::encode_clip(format, preview->frames_png, preview->frame_times_s));
  clips_.put(key, bytes, bytes->size() + key.size());
  return *bytes;
}

}  // namespace softtune::app
