// Animated WebP with libwebp's WebPAnimEncoder (libwebpmux 1.2, webp/mux.h): each frame added with its
// start timestamp in ms, then a last timestamp that ends the final frame (the encoder's documented
// protocol, examples/img2webp.c in libwebp). The encoder itself differences frames: it encodes only the
// rectangle that changed since the previous frame (anim_encode.c, GetSubRects), and with kmax <= 0 it
// tries no key-frame candidate beside it (anim_encode.c, SetFrame: one encode per candidate).
#include <webp/encode.h>
#include <webp/mux.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "clip_palette.h"
#include "softtune/render/clip.h"

namespace softtune::render {
namespace {

class WebpEncoder final : public ClipEncoder {
 public:
  WebpEncoder(ImageSize size, std::vector<int> durations_ms, const WebpClipOptions& o)
      : size_(size), durations_(std::move(durations_ms)) {
    WebPAnimEncoderOptions options;
    if (!WebPAnimEncoderOptionsInit(&options) || !WebPConfigInit(&config_)) {
      throw std::runtime_error("webp: library version mismatch");
    }
    options.anim_params.loop_count = 0;  // forever
    options.anim_params.bgcolor = 0xFFFFFFFF;
    options.kmin = o.kmin;
    options.kmax = o.kmax;
    options.minimize_size = o.minimize_size ? 1 : 0;
    config_.lossless = o.lossless ? 1 : 0;
    config_.method = o.method;
    config_.quality = o.quality;
    config_.near_lossless = o.near_lossless;
    config_.exact = 1;  // transparent pixels keep their colour: the frames are opaque anyway
    if (!WebPValidateConfig(&config_)) throw std::invalid_argument("webp: invalid encoder settings");
    enc_ = WebPAnimEncoderNew(size.width, size.height, &options);
    if (!enc_) throw std::runtime_error("webp: cannot create the animation encoder");
  }
  ~WebpEncoder() override { WebPAnimEncoderDelete(enc_); }

  void add(const std::vector<std::uint8_t>& rgba) override {
    if (added_ >= static_cast<int>(durations_.size())) throw std::logic_error("webp: more frames than times");
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error("webp: library version mismatch");
    picture.width = size_.width;
    picture.height = size_.height;
    picture.use_argb = 1;
    const bool ok = WebPPictureImportRGBA(&picture, rgba.data(), size_.width * 4) &&
                    WebPAnimEncoderAdd(enc_, &picture, timestamp_, &config_);
    WebPPictureFree(&picture);
    if (!ok) throw std::runtime_error("webp: frame " + std::to_string(added_) + ": " + WebPAnimEncoderGetError(enc_));
    timestamp_ += durations_[added_++];
  }

  std::string finish() override {
    if (added_ != static_cast<int>(durations_.size())) throw std::logic_error("webp: frames missing");
    WebPData data;
    WebPDataInit(&data);
    if (!WebPAnimEncoderAdd(enc_, nullptr, timestamp_, nullptr) || !WebPAnimEncoderAssemble(enc_, &data)) {
      throw std::runtime_error(std::string("webp: ") + WebPAnimEncoderGetError(enc_));
    }
    std::string out(reinterpret_cast<const char*>(data.bytes), data.size);
    WebPDataClear(&data);
    return out;
  }

 private:
  ImageSize size_;
  std::vector<int> durations_;
  WebPConfig config_;
  WebPAnimEncoder* enc_ = nullptr;
  int added_ = 0, timestamp_ = 0;
};

// Our own frame differencing over libwebpmux's WebPMux (webp/mux.h): each frame after the first is only
// the box of pixels that changed (offsets even, as the format wants), encoded alone with WebPEncode, the
// unchanged pixels in it fully transparent and the frame alpha-blended onto the last (WEBP_MUX_BLEND,
// WEBP_MUX_DISPOSE_NONE): the GIF's scheme. Lossless VP8L codes a run of transparent pixels in a few bits,
// and only the changed box is ever searched, so a mostly still frame costs little time and few bytes.
// Each pixel as its nearest clip palette colour (clip_palette.h, the GIF's): a frame of at most 255
// colours, which VP8L codes with its colour-indexing transform, a few bits a pixel.
const std::vector<std::uint8_t>& quantized(const std::vector<std::uint8_t>& rgba, std::vector<std::uint8_t>& out) {
  const ClipQuantizer& q = clip_quantizer();
  out.resize(rgba.size());
  for (std::size_t p = 0; p + 3 < rgba.size(); p += 4) {
    const Rgba c = q.colours[q.index(&rgba[p])];
    out[p] = c.r, out[p + 1] = c.g, out[p + 2] = c.b, out[p + 3] = 255;
  }
  return out;
}

class WebpDiffEncoder final : public ClipEncoder {
 public:
  WebpDiffEncoder(ImageSize size, std::vector<int> durations_ms, const WebpClipOptions& o)
      : size_(size), durations_(std::move(durations_ms)), palette_(o.palette) {
    if (!WebPConfigInit(&config_)) throw std::runtime_error("webp: library version mismatch");
    config_.lossless = o.lossless ? 1 : 0;
    config_.method = o.method;
    config_.quality = o.quality;
    config_.near_lossless = o.near_lossless;
    config_.exact = 0;  // the colour under a transparent pixel does not matter
    if (!WebPValidateConfig(&config_)) throw std::invalid_argument("webp: invalid encoder settings");
    mux_ = WebPMuxNew();
    if (!mux_) throw std::runtime_error("webp: out of memory");
    const WebPMuxAnimParams params{0xFFFFFFFFu, 0};  // background, loop forever
    if (WebPMuxSetCanvasSize(mux_, size.width, size.height) != WEBP_MUX_OK ||
        WebPMuxSetAnimationParams(mux_, &params) != WEBP_MUX_OK) {
      throw std::runtime_error("webp: cannot set up the animation");
    }
  }
  ~WebpDiffEncoder() override { WebPMuxDelete(mux_); }

  void add(const std::vector<std::uint8_t>& source) override {
    if (added_ >= static_cast<int>(durations_.size())) throw std::logic_error("webp: more frames than times");
    const std::vector<std::uint8_t>& rgba = palette_ ? quantized(source, quantized_) : source;
    const int w = size_.width, h = size_.height;
    int x0 = 0, y0 = 0, x1 = w, y1 = h;
    const bool first = previous_.empty();
    if (!first) {
      x0 = w, y0 = h, x1 = 0, y1 = 0;
      for (int y = 0; y < h; ++y) {
        const std::uint32_t* a = row(rgba, y);
        const std::uint32_t* b = row(previous_, y);
        if (std::memcmp(a, b, 4 * static_cast<std::size_t>(w)) == 0) continue;
        y0 = std::min(y0, y), y1 = y + 1;
        int l = 0, r = w;
        while (a[l] == b[l]) ++l;
        while (a[r - 1] == b[r - 1]) --r;
        x0 = std::min(x0, l), x1 = std::max(x1, r);
      }
      if (x1 <= x0) x0 = 0, y0 = 0, x1 = 1, y1 = 1;  // nothing changed: one transparent pixel
      x0 &= ~1, y0 &= ~1;                            // ANMF offsets are stored halved
    }
    const int rw = x1 - x0, rh = y1 - y0;
    std::vector<std::uint8_t> box(static_cast<std::size_t>(rw) * rh * 4, 0);
    for (int y = 0; y < rh; ++y) {
      const std::uint32_t* a = row(rgba, y0 + y) + x0;
      const std::uint32_t* b = first ? a : row(previous_, y0 + y) + x0;
      std::uint32_t* out = reinterpret_cast<std::uint32_t*>(&box[static_cast<std::size_t>(y) * rw * 4]);
      for (int x = 0; x < rw; ++x) out[x] = !first && a[x] == b[x] ? 0u : a[x];
    }
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error("webp: library version mismatch");
    picture.width = rw;
    picture.height = rh;
    picture.use_argb = 1;
    WebPMemoryWriter writer;
    WebPMemoryWriterInit(&writer);
    picture.writer = WebPMemoryWrite;
    picture.custom_ptr = &writer;
    const bool ok = WebPPictureImportRGBA(&picture, box.data(), rw * 4) && WebPEncode(&config_, &picture);
    const int error = picture.error_code;
    WebPPictureFree(&picture);
    if (!ok) {
      WebPMemoryWriterClear(&writer);
      throw std::runtime_error("webp: frame " + std::to_string(added_) + ": encoder error " + std::to_string(error));
    }
    WebPMuxFrameInfo frame{};
    frame.bitstream.bytes = writer.mem;
    frame.bitstream.size = writer.size;
    frame.x_offset = x0;
    frame.y_offset = y0;
    frame.duration = durations_[added_];
    frame.id = WEBP_CHUNK_ANMF;
    frame.dispose_method = WEBP_MUX_DISPOSE_NONE;
    frame.blend_method = first ? WEBP_MUX_NO_BLEND : WEBP_MUX_BLEND;
    const WebPMuxError pushed = WebPMuxPushFrame(mux_, &frame, 1);
    WebPMemoryWriterClear(&writer);
    if (pushed != WEBP_MUX_OK) throw std::runtime_error("webp: cannot add frame " + std::to_string(added_));
    previous_ = rgba;
    ++added_;
  }

  std::string finish() override {
    if (added_ != static_cast<int>(durations_.size())) throw std::logic_error("webp: frames missing");
    WebPData data;
    WebPDataInit(&data);
    if (WebPMuxAssemble(mux_, &data) != WEBP_MUX_OK) throw std::runtime_error("webp: cannot assemble the animation");
    std::string out(reinterpret_cast<const char*>(data.bytes), data.size);
    WebPDataClear(&data);
    return out;
  }

 private:
  const std::uint32_t* row(const std::vector<std::uint8_t>& rgba, int y) const {
    return reinterpret_cast<const std::uint32_t*>(&rgba[static_cast<std::size_t>(y) * size_.width * 4]);
  }
  ImageSize size_;
  std::vector<int> durations_;
  WebPConfig config_;
  WebPMux* mux_ = nullptr;
  bool palette_ = false;
  std::vector<std::uint8_t> previous_, quantized_;
  int added_ = 0;
};

}  // namespace

std::unique_ptr<ClipEncoder> make_webp_encoder(ImageSize size, std::vector<int> durations_ms, const WebpClipOptions& options) {
  if (options.differencing) return std::make_unique<WebpDiffEncoder>(size, std::move(durations_ms), options);
  return std::make_unique<WebpEncoder>(size, std::move(durations_ms), options);
}

}  // namespace softtune::render
