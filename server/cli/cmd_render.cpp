// `softtune render`: preview frames of a preset as PNG files (contract: docs/preview.md).
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/cli_io.h"
#include "cli/engine_flags.h"
#include "cli/flag_fields.h"
#include "codec/json_reader.h"
#include "app/preset_store.h"
#include "app/preview_service.h"
#include "codec/problem.h"

namespace softtune::cli {
namespace {

constexpr const char* kRenderHelp = R"(softtune render: preview frames of a preset as PNG files.

  softtune render --preset NAME --out DIR [options]
    --frames N            frames to render (default 60, at most 600)
    --presets DIR         where presets live (default $SOFTTUNE_PRESETS, else ./presets)
    --mass-model M        effective | box2d_reduced (scene presets)
    --engine NAME         the engine a scene preset runs in (default box2d_v2_4)
    --engine-settings name=value,...   that engine's own step settings
    --size WxH            frame size in pixels (default 640x360, at most 1920x1080)
    --filmstrip-every N   frames between filmstrip tiles (default: about 10 tiles)
    --animation F         also write the frames as a clip: webp or gif (DIR/animation.F)
  the oscillator preset's tuning, as in `softtune tune` (default: the preset's own):
    --request FILE        a tune request JSON (- for stdin), or these flags:
    --response-frames N   one oscillation period lasts N frames
    --basis-fps B   --frequency F   --oscillation free|some|none   --damping-ratio Z
    --mass M   --fps F   --substeps N   --mode standard|exact

Writes DIR/frame_0000.png ... (spread over the whole run: the first at t = 0, the last at its end),
DIR/frames.json (each frame's file and simulated time) and DIR/filmstrip.png (and DIR/animation.webp or
.gif), and prints {id, frames, manifest, filmstrip, animation, stages, timings}.
Presets: every file in presets/; oscillator draws the soft method beside the exact analytic ghost.
Bad input: exit code 2 and a problem JSON on stderr naming the field.
)";

// The tune flags of `softtune tune`, with --response-frames for its --frames.
constexpr FlagField kTuneFlags[] = {
    {"response-frames", "response_frames", true}, {"basis-fps", "basis_fps", true},
    {"frequency", "frequency_hz", true},          {"oscillation", "oscillation", false},
    {"damping-ratio", "damping_ratio", true},     {"mass", "effective_mass", true},
    {"fps", "fps", true},                         {"substeps", "substeps", true},
    {"mode", "mode", false},
};

nlohmann::json tune_request_from(const Flags& flags) {
  bool any_tune_flag = false;
  for (const FlagField& f : kTuneFlags) any_tune_flag = any_tune_flag || flags.has(f.flag);
  if (auto file = flags.get("request")) {
    if (any_tune_flag) throw codec::invalid_field("--request", "cannot be combined with tuning flags");
    return read_request_file(*file);
  }
  nlohmann::json request = {{"effective_mass", 1.0}};
  if (!flags.has("frequency")) request["response_frames"] = 30.0;
  if (!flags.has("damping-ratio")) request["oscillation"] = "some";
  set_fields_from_flags(flags, kTuneFlags, request);
  return request;
}

void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw codec::invalid_field("--out", "cannot write \"" + path.string() + "\"");
}

}  // namespace

int run_render(const Args& args) {
  return guarded([&] {
    std::vector<std::string> with_value = flag_names(kTuneFlags);
    with_value.insert(with_value.end(), {"preset", "frames", "size", "filmstrip-every", "out", "request", "presets",
                                         "mass-model", "animation", "engine", "engine-settings"});
    const Flags flags = parse_flags(args, with_value, {"help"});
    if (flags.has("help")) {
      std::cout << kRenderHelp;
      return kExitOk;
    }
    const auto preset = flags.get("preset");
    if (!preset) throw codec::invalid_field("--preset", "is required (softtune simulate lists none; see presets/)");
    const auto out_dir = flags.get("out");
    if (!out_dir || out_dir->empty()) throw codec::invalid_field("--out", "is required: the directory for the PNGs");

    // The same request as POST /api/v1/preview: a preset, or the oscillator with its tuning from flags.
    bool any_tune_flag = flags.has("request");
    for (const FlagField& f : kTuneFlags) any_tune_flag = any_tune_flag || flags.has(f.flag);
    nlohmann::json request = nlohmann::json::object();
    if (any_tune_flag) {
      if (*preset != "oscillator") throw codec::invalid_field("--preset", "tuning flags apply to the oscillator only");
      request = tune_request_from(flags);
    } else {
      request["preset"] = *preset;
    }
    if (flags.has("frames")) request["frames"] = flag_number(flags, "frames");
    if (flags.has("filmstrip-every")) request["filmstrip_every"] = flag_number(flags, "filmstrip-every");
    if (auto size = flags.get("size")) request["size"] = *size;
    if (auto model = flags.get("mass-model")) request["mass_model"] = *model;
    set_engine_from_flags(flags, request);
    std::optional<render::ClipFormat> clip;
    if (auto name = flags.get("animation")) {
      clip = render::clip_format(*name);
      if (!clip) throw codec::invalid_field("--animation", "must be webp or gif");
      request["animation"] = *name;  // encoded while the frames render; over the clip cap, refused before
    }
    const std::filesystem::path dir(*out_dir);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) {
      throw codec::invalid_field("--out", "cannot create the directory \"" + *out_dir + "\"");
    }

    app::PreviewService previews;
    const nlohmann::json answer = previews.start(request, app::resolve_presets_dir(flags.get("presets")), "");
    const std::string id = answer.at("id");
    auto frame_name = [](int i) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04d.png", i);
      return std::string(name);
    };
    nlohmann::json out = answer;
    out["frames"] = nlohmann::json::array();
    for (int i = 0; i < answer.at("frame_count").get<int>(); ++i) {
      write_file(dir / frame_name(i), *previews.frame_png(id, i));
      out["frames"].push_back((dir / frame_name(i)).string());
    }
    // frames.json: each frame's file and simulated time, as in the answer's manifest (with file names).
    nlohmann::json manifest = answer.at("manifest");
    for (nlohmann::json& f : manifest.at("frames")) f["file"] = frame_name(f.at("index").get<int>());
    write_file(dir / "frames.json", manifest.dump(2) + "\n");
    out["manifest"] = (dir / "frames.json").string();
    write_file(dir / "filmstrip.png", *previews.filmstrip_png(id));
    out["filmstrip"] = (dir / "filmstrip.png").string();
    if (clip) {
      const auto path = dir / ("animation." + std::string(render::clip_format_name(*clip)));
      write_file(path, *previews.clip(id, *clip));
      out["animation"] = path.string();
    }
    out.erase("progress_url");
    print_json(out);
    return kExitOk;
  });
}

}  // namespace softtune::cli
