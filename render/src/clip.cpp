#include "softtune/render/clip.h"

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

#include "softtune/render/png.h"
#include "softtune/support/run_limit.h"

namespace softtune::render {

// Each format's encoder (clip_webp.cpp, clip_gif.cpp), given every frame's display time up front.
std::unique_ptr<ClipEncoder> make_webp_encoder(ImageSize size, std::vector<int> durations_ms, const WebpClipOptions& options);
std::unique_ptr<ClipEncoder> make_gif_encoder(ImageSize size, std::vector<int> durations_ms);

std::optional<ClipFormat> clip_format(std::string_view name) {
  if (name == "webp") return ClipFormat::webp;
  if (name == "gif") return ClipFormat::gif;
  return std::nullopt;
}

std::string_view clip_format_name(ClipFormat f) { return f == ClipFormat::webp ? "webp" : "gif"; }
std::string_view clip_content_type(ClipFormat f) { return f == ClipFormat::webp ? "image/webp" : "image/gif"; }

std::optional<FieldError> validate_clip(int frames, ImageSize size) {
  const std::int64_t pixels = std::int64_t{frames} * size.width * size.height;
  if (frames < 1) return FieldError{"frames", "a clip needs at least one frame"};
  if (pixels > caps::kMaxClipPixels) {
    return FieldError{"frames", "a clip holds at most " + std::to_string(caps::kMaxClipPixels) +
                                    " pixels (frames x width x height, 120 frames of 1280x720); this preview has " +
                                    std::to_string(pixels) + ": ask for fewer frames or a smaller size"};
  }
  return std::nullopt;
}

std::vector<int> frame_durations_ms(const std::vector<double>& t) {
  const std::size_t n = t.size();
  std::vector<int> out(n, 17);
  if (n < 2) return out;
  std::vector<long long> stamp(n);
  for (std::size_t i = 0; i < n; ++i) {
    stamp[i] = std::llround(1000.0 * (std::isfinite(t[i]) ? t[i] - t[0] : 0.0));
    if (i > 0 && stamp[i] <= stamp[i - 1]) stamp[i] = stamp[i - 1] + 1;
  }
  for (std::size_t i = 0; i + 1 < n; ++i) out[i] = static_cast<int>(stamp[i + 1] - stamp[i]);
  out[n - 1] = out[n - 2];
  return out;
}

std::unique_ptr<ClipEncoder> make_clip_encoder(ClipFormat format, ImageSize size, const std::vector<double>& times_s,
                                               const WebpClipOptions& webp) {
  if (times_s.empty()) throw std::invalid_argument("clip: no frames");
  std::vector<int> durations = frame_durations_ms(times_s);
  return format == ClipFormat::webp ? make_webp_encoder(size, std::move(durations), webp)
                                    : make_gif_encoder(size, std::move(durations));
}

std::string encode_clip(ClipFormat format, const std::vector<std::string>& frames_png, const std::vector<double>& times_s) {
  if (frames_png.empty()) throw std::invalid_argument("clip: no frames");
  if (times_s.size() != frames_png.size()) throw std::invalid_argument("clip: one time per frame");
  ImageSize size;
  decode_png(frames_png.front(), size);
  const std::unique_ptr<ClipEncoder> encoder = make_clip_encoder(format, size, times_s);
  for (const std::string& png : frames_png) {
    // The calling request's run-time limit, once per frame (a 1280x720 WebP frame takes about 40 ms):
    // a clip asked of a finished preview encodes on the request's thread, and stops at 2x its budget.
    support::check_run_limit();
    ImageSize s;
    const std::vector<std::uint8_t> rgba = decode_png(png, s);
    if (!(s == size)) throw std::invalid_argument("clip: frames differ in size");
    encoder->add(rgba);
  }
  return encoder->finish();
}

}  // namespace softtune::render
