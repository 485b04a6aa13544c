// Animated WebP with libwebp's WebPAnimEncoder (libwebpmux 1.2, webp/mux.h): each frame added with its
// start timestamp in ms, then a last timestamp that ends the final frame (the encoder's documented
// protocol, examples/img2webp.c in libwebp). The encoder itself differences frames: it encodes only the
// rectangle that changed since the previous frame (anim_encode.c, GetSubRects), and with kmax <= 0 it
// tries no key-frame candidate beside it (anim_encode.c, SetFrame: one encode per candidate).
#include <webp/encode.h>
#include <webp/mux.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

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

}  // namespace

std::unique_ptr<ClipEncoder> make_webp_encoder(ImageSize size, std::vector<int> durations_ms, const WebpClipOptions& options) {
  return std::make_unique<WebpEncoder>(size, std::move(durations_ms), options);
}

}  // namespace softtune::render
