#pragma once
// The preview contract (shared by `softtune render` and POST /api/v1/preview): the render settings
// ("frames", "size" as "WxH", "filmstrip_every") and the response {id, frames, filmstrip, stages,
// timings}. Caps: render/include/softtune/render/frame_pipeline.h.

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "codec/json_reader.h"
#include "softtune/render/frame_pipeline.h"
#include "softtune/render/oscillator_frames.h"

namespace softtune::codec {

/// "640x360" -> {640, 360}; nothing when the text is not two positive integers joined by 'x'.
std::optional<render::ImageSize> parse_image_size(std::string_view text);

/// Reads "frames", "size" and "filmstrip_every" (all optional, defaults 60 and "640x360") from an
/// object that may hold other fields; the caller calls finish(). Throws Problem (422) past a cap.
render::PreviewSettings read_preview_settings(ObjectReader& r);

/// The canonical request text of the 1-D oscillator preview: the resolved physics (mass, omega, zeta,
/// fps, substeps, method, initial displacement), so requests that mean the same motion share an id.
std::string canonical_oscillator_request(const render::OscillatorScene& scene);

/// {id, cached, frames: [frame_url(n)...], filmstrip, size, frame_count, filmstrip_every, stages,
///  timings: {wall_ms, prepare_ms, render_ms, png_ms, filmstrip_ms, workers}}. A cache hit lists no
/// stages (nothing ran) and keeps the timings of the render that made it.
nlohmann::json encode_preview(const render::Preview& preview, bool from_cache,
                              const std::function<std::string(int frame)>& frame_url, const std::string& filmstrip_url);

/// The frames' manifest (frames.json beside the PNGs, `manifest` in the preview answer): {frame_count,
/// run_end_s, frame_dt_s (the mean gap), frames: [{index, file: frame_file(index), time_s}]}, each time the
/// frame's simulated time in the run; frames count from 0, like their files.
nlohmann::json encode_frame_manifest(const render::Preview& preview, const std::function<std::string(int frame)>& frame_file);

}  // namespace softtune::codec
