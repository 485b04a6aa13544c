#pragma once
// Clips: a preview's frames as one animated WebP (libwebp's WebPAnimEncoder, libwebpmux) or GIF (giflib),
// with the scene's real frame timing, for a chat or a bug report. Made from the cached PNG frames when
// first asked for (a preview nobody clips pays nothing), one frame decoded at a time.

#include <cstdint>
#include <memory>
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

/// libwebp settings of a WebP clip, chosen by measurement (bench/render_bench.cpp, BM_ClipWebpSettings;
/// docs/benchmarks.md): on 120 frames of the vehicle, lossless method 1 at effort 0 on the GIF's palette
/// with our own differencing made 363 kB in 2.7 ms of CPU a frame, against 1408 kB and 18.9 ms for the
/// previous setting (exact colours, WebPAnimEncoder, method 1, effort 20) and 950 kB for the GIF; exact
/// colours with differencing stayed at 1264 kB (anti-aliased fringes are many colours), lossy quality 75
/// at 1207 kB blurred the text.
struct WebpClipOptions {
  bool lossless = true;
  int method = 1;            ///< 0 (fastest) .. 6
  float quality = 0.0f;      ///< lossless: effort 0..100; lossy: quality
  int near_lossless = 100;   ///< 100: off; lower quantizes pixels near edges (lossless only)
  int kmax = 0;              ///< WebPAnimEncoderOptions::kmax: <= 0 makes only the first frame a key frame
  int kmin = 0;
  bool minimize_size = false;
  /// Our own frame differencing (the changed box alone, unchanged pixels transparent, blended onto the
  /// last frame) over WebPMux, instead of WebPAnimEncoder's sub-frames.
  bool differencing = true;
  /// Map each pixel to the GIF's 256-colour palette first (exact on the preview palette's own colours,
  /// fringes to the nearest of a 6x6x6 cube), so VP8L codes palette indices (with differencing only).
  bool palette = true;
};

/// A clip encoded frame by frame, in order, while the frames render (the frame pipeline's clip stage):
/// add() frame 0, 1, ... of the clip's size, then finish() once. Not thread-safe: one caller at a time.
class ClipEncoder {
 public:
  virtual ~ClipEncoder() = default;
  /// The next frame's RGBA pixels (rgba_bytes(size)).
  virtual void add(const std::vector<std::uint8_t>& rgba) = 0;
  /// After the last frame: the file's bytes. Throws std::logic_error when frames are missing.
  virtual std::string finish() = 0;
};

/// The encoder of a clip of these frames (their times in the run, one per frame, as for encode_clip).
/// Throws std::invalid_argument for no frames.
std::unique_ptr<ClipEncoder> make_clip_encoder(ClipFormat format, ImageSize size, const std::vector<double>& times_s,
                                               const WebpClipOptions& webp = {});

/// Encodes PNG frames (all of one size) as an animated WebP or GIF that plays once per loop, forever.
/// WebP: lossless (flat colours and sharp text compress well and stay exact). GIF: a 256-colour
/// palette (the preview palette's own colours and a 6x6x6 cube), frame delays in centiseconds with
/// frames closer than GIF's 2 cs floor merged into the next (browsers slow delays under 2 cs to 10 cs);
/// each frame after the first only the box of pixels that changed, the unchanged ones in it transparent.
/// Throws std::invalid_argument for no frames or mismatched sizes, std::runtime_error if a library fails.
std::string encode_clip(ClipFormat format, const std::vector<std::string>& frames_png, const std::vector<double>& times_s);

}  // namespace softtune::render
