// Animated WebP with libwebp's WebPAnimEncoder (libwebpmux 1.2, webp/mux.h): each frame added with its
// start timestamp in ms, then a last timestamp that ends the final frame (the encoder's documented
// protocol, examples/img2webp.c in libwebp).
#include <webp/encode.h>
#include <webp/mux.h>

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "softtune/render/view.h"

namespace softtune::render {

std::string encode_webp_clip(int count, ImageSize size, const std::vector<int>& durations_ms,
                             const std::function<std::vector<std::uint8_t>(int)>& frame) {
  WebPAnimEncoderOptions options;
  if (!WebPAnimEncoderOptionsInit(&options)) throw std::runtime_error("webp: library version mismatch");
  options.anim_params.loop_count = 0;  // forever
  options.anim_params.bgcolor = 0xFFFFFFFF;
  WebPConfig config;
  if (!WebPConfigInit(&config)) throw std::runtime_error("webp: library version mismatch");
  // Lossless, so flat colours, springs and text stay exact. Method 1 at quality 20: on the vehicle's 60
  // frames 443 KB against 3.1 MB at method 0 (which skips the transforms that flat images need) for
  // about 3x its time; lossy method 0 at quality 75 is 518 KB, blurs text and is not much faster
  // (docs/preview.md, "Clips"; bench/render_bench.cpp, BM_Clip).
  config.lossless = 1;
  config.method = 1;
  config.quality = 20;
  struct Encoder {
    WebPAnimEncoder* p;
    ~Encoder() { WebPAnimEncoderDelete(p); }
  } enc{WebPAnimEncoderNew(size.width, size.height, &options)};
  if (!enc.p) throw std::runtime_error("webp: cannot create the animation encoder");
  int timestamp = 0;
  for (int i = 0; i < count; ++i) {
    const std::vector<std::uint8_t> rgba = frame(i);
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error("webp: library version mismatch");
    picture.width = size.width;
    picture.height = size.height;
    picture.use_argb = 1;
    const bool ok = WebPPictureImportRGBA(&picture, rgba.data(), size.width * 4) &&
                    WebPAnimEncoderAdd(enc.p, &picture, timestamp, &config);
    WebPPictureFree(&picture);
    if (!ok) throw std::runtime_error(std::string("webp: frame ") + std::to_string(i) + ": " + WebPAnimEncoderGetError(enc.p));
    timestamp += durations_ms[i];
  }
  WebPData data;
  WebPDataInit(&data);
  if (!WebPAnimEncoderAdd(enc.p, nullptr, timestamp, nullptr) || !WebPAnimEncoderAssemble(enc.p, &data)) {
    throw std::runtime_error(std::string("webp: ") + WebPAnimEncoderGetError(enc.p));
  }
  std::string out(reinterpret_cast<const char*>(data.bytes), data.size);
  WebPDataClear(&data);
  return out;
}

}  // namespace softtune::render
