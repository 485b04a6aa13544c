#pragma once
// Clips: a preview's frames as one animated WebP (libwebp's WebPAnimEncoder, libwebpmux) or GIF (giflib),
// with the scene's real frame timing, for a chat or a bug report. Made from the cached PNG frames when
// first asked for (a preview nobody clips pays nothing), one frame decoded at a time.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "softtune/diagnostics.h"
#include "softtune/render/view.h"

namespace softtune::render {

enum class ClipFormat : std::uint8_t { webp, gif };

/// "webp" or "gif"; nullopt for anything else.
std::optional<ClipFormat> clip_format(std::string_view name);
std::string_view clip_format_name(ClipFormat f);
std::string_view clip_content_type(ClipFormat f);

namespace caps {
/// Pixels a clip may hold (frames x width x height): 120 frames of 1280x720. Encoding costs about
/// 20-40 ns per pixel on this machine (bench/render_bench.cpp), so a clip stays under a few seconds.
inline constexpr std::int64_t kMaxClipPixels = std::int64_t{120} * 1280 * 720;
}  // namespace caps

/// Why a preview of `frames` frames of `size` cannot be clipped ("size" or "frames"), or nothing.
std::optional<FieldError> validate_clip(int frames, ImageSize size);

/// Each frame's display time in ms, from the frames' times in the run: frame i lasts until frame i + 1
/// starts (timestamps rounded from t_i - t_0, so rounding never accumulates); the last frame lasts as
/// long as the one before it (1/60 s for a single frame). Non-increasing times count as 1 ms apart.
std::vector<int> frame_durations_ms(const std::vector<double>& times_s);

/// Encodes PNG frames (all of one size) as an animated WebP or GIF that plays once per loop, forever.
/// WebP: lossless (flat colours and sharp text compress well and stay exact). GIF: a 256-colour
/// palette (the preview palette's own colours and a 6x6x6 cube), frame delays in centiseconds with
/// frames closer than GIF's 2 cs floor merged into the next (browsers slow delays under 2 cs to 10 cs).
/// Throws std::invalid_argument for no frames or mismatched sizes, std::runtime_error if a library fails.
std::string encode_clip(ClipFormat format, const std::vector<std::string>& frames_png, const std::vector<double>& times_s);

}  // namespace softtune::render
