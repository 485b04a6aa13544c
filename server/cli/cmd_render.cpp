// `softtune render`: preview frames of a preset as PNG files (contract: README.md, "Preview frames").
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/cli_io.h"
#include "cli/flag_fields.h"
#include "codec/json_reader.h"
#include "codec/preview_codec.h"
#include "codec/problem.h"
#include "codec/tune_codec.h"
#include "softtune/render/oscillator_frames.h"

namespace softtune::cli {
namespace {

constexpr const char* kHelp = R"(softtune render: preview frames of a preset as PNG files.

  softtune render --preset oscillator --out DIR [options]
    --frames N            frames to render (default 60, at most 600)
    --size WxH            frame size in pixels (default 640x360, at most 1920x1080)
    --filmstrip-every N   frames between filmstrip tiles (default: about 10 tiles)
  the oscillator's tuning, as in `softtune tune` (default: 30 frames, some, 1 kg):
    --request FILE        a tune request JSON (- for stdin), or these flags:
    --response-frames N   one oscillation period lasts N frames
    --basis-fps B   --frequency F   --oscillation free|some|none   --damping-ratio Z
    --mass M   --fps F   --substeps N   --mode standard|exact

Writes DIR/frame_0000.png ... and DIR/filmstrip.png, and prints {id, frames, filmstrip, stages, timings}.
Presets: oscillator (the 1-D oscillator: soft method vs the exact analytic ghost).
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
    with_value.insert(with_value.end(), {"preset", "frames", "size", "filmstrip-every", "out", "request"});
    const Flags flags = parse_flags(args, with_value, {"help"});
    if (flags.has("help")) {
      std::cout << kHelp;
      return kExitOk;
    }
    const auto preset = flags.get("preset");
    if (!preset) throw codec::invalid_field("--preset", "is required (available: oscillator)");
    if (*preset != "oscillator") {
      throw codec::invalid_field("--preset", "unknown preset \"" + *preset + "\" (available: oscillator)");
    }
    const auto out_dir = flags.get("out");
    if (!out_dir || out_dir->empty()) throw codec::invalid_field("--out", "is required: the directory for the PNGs");

    // The render settings go through the same reader as POST /api/v1/preview.
    nlohmann::json settings_doc = nlohmann::json::object();
    if (flags.has("frames")) settings_doc["frames"] = flag_number(flags, "frames");
    if (flags.has("filmstrip-every")) settings_doc["filmstrip_every"] = flag_number(flags, "filmstrip-every");
    if (auto size = flags.get("size")) settings_doc["size"] = *size;
    codec::ObjectReader settings_reader = codec::read_object(settings_doc, "");
    const render::PreviewSettings settings = codec::read_preview_settings(settings_reader);

    const TuneRequest request = codec::decode_tune_request(tune_request_from(flags));
    const render::OscillatorScene scene = render::oscillator_scene(request, tune(request));

    const std::filesystem::path dir(*out_dir);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir)) {
      throw codec::invalid_field("--out", "cannot create the directory \"" + *out_dir + "\"");
    }

    render::FramePipeline pipeline;
    const auto job = pipeline.submit(codec::canonical_oscillator_request(scene), settings,
                                     [&] { return render::oscillator_frames(scene, settings.frames); });
    const auto preview = job->wait();
    auto frame_name = [](int i) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04d.png", i);
      return std::string(name);
    };
    for (int i = 0; i < static_cast<int>(preview->frames_png.size()); ++i) {
      write_file(dir / frame_name(i), preview->frames_png[i]);
    }
    write_file(dir / "filmstrip.png", preview->filmstrip_png);
    print_json(codec::encode_preview(*preview, job->from_cache(),
                                     [&](int i) { return (dir / frame_name(i)).string(); },
                                     (dir / "filmstrip.png").string()));
    return kExitOk;
  });
}

}  // namespace softtune::cli
