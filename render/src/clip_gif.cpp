// Animated GIF with giflib 5.2 (gif_lib.h): one global 256-colour palette, a NETSCAPE2.0 loop block, and
// per frame a graphics control block carrying its delay in centiseconds. Frames are differenced: after
// the first, each holds only the box of pixels whose palette index changed, the unchanged ones in it the
// transparent index (kept, DISPOSE_DO_NOT), so a still background costs neither LZW time nor bytes.
#include <gif_lib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "clip_palette.h"
#include "softtune/render/clip.h"
#include "softtune/render/palette.h"
#include "softtune/render/view.h"

namespace softtune::render {
namespace {

// Unchanged pixels of a differenced frame: the last index, which no colour maps to (clip_palette.h).
constexpr int kTransparent = kClipTransparentIndex;

int write_to_string(GifFileType* gif, const GifByteType* bytes, int n) {
  static_cast<std::string*>(gif->UserData)->append(reinterpret_cast<const char*>(bytes), n);
  return n;
}

void check(int status, GifFileType* gif, const char* what) {
  if (status != GIF_OK) throw std::runtime_error(std::string("gif: ") + what + ": " + GifErrorString(gif->Error));
}

class GifEncoder final : public ClipEncoder {
 public:
  GifEncoder(ImageSize size, const std::vector<int>& durations_ms) : size_(size), count_(static_cast<int>(durations_ms.size())) {
    // Frame starts in cs, rounded from the ms timeline; a frame under 2 cs after the last kept one merges.
    start_cs_.resize(count_ + 1);
    long long ms = 0;
    for (int i = 0; i <= count_; ++i) {
      start_cs_[i] = (ms + 5) / 10;
      if (i < count_) ms += durations_ms[i];
    }
    for (int i = 0; i < count_; ++i) {
      if (kept_.empty() || start_cs_[i] - start_cs_[kept_.back()] >= 2) kept_.push_back(i);
    }
    int error = 0;
    gif_ = EGifOpen(&out_, write_to_string, &error);
    if (!gif_) throw std::runtime_error(std::string("gif: ") + GifErrorString(error));
    const ClipQuantizer& q = clip_quantizer();
    ColorMapObject* map = GifMakeMapObject(256, nullptr);
    if (!map) throw std::runtime_error("gif: out of memory");
    for (int k = 0; k < 256; ++k) map->Colors[k] = {q.colours[k].r, q.colours[k].g, q.colours[k].b};
    EGifSetGifVersion(gif_, true);
    const int screen = EGifPutScreenDesc(gif_, size.width, size.height, 8, 0, map);
    GifFreeMapObject(map);
    check(screen, gif_, "screen");
    // Loop forever: the NETSCAPE2.0 application block with loop count 0.
    check(EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE), gif_, "loop");
    check(EGifPutExtensionBlock(gif_, 11, "NETSCAPE2.0"), gif_, "loop");
    const unsigned char loop[3] = {1, 0, 0};
    check(EGifPutExtensionBlock(gif_, 3, loop), gif_, "loop");
    check(EGifPutExtensionTrailer(gif_), gif_, "loop");
  }
  ~GifEncoder() override {
    int e = 0;
    if (gif_) EGifCloseFile(gif_, &e);
  }

  void add(const std::vector<std::uint8_t>& rgba) override {
    if (added_ >= count_) throw std::logic_error("gif: more frames than times");
    const int i = added_++;
    if (next_kept_ >= kept_.size() || kept_[next_kept_] != i) return;  // merged into the frame before it
    const std::size_t k = next_kept_++;
    const int w = size_.width, h = size_.height;
    const ClipQuantizer& q = clip_quantizer();
    std::vector<std::uint8_t>& now = indices_[k % 2];
    const std::vector<std::uint8_t>& before = indices_[(k + 1) % 2];
    now.resize(static_cast<std::size_t>(w) * h);
    for (std::size_t p = 0; p < now.size(); ++p) now[p] = q.index(&rgba[4 * p]);
    // The box of changed pixels (the whole frame first); a frame like the last still shows one pixel.
    int x0 = 0, y0 = 0, x1 = w, y1 = h;
    if (k > 0) {
      x0 = w, y0 = h, x1 = 0, y1 = 0;
      for (int y = 0; y < h; ++y) {
        const std::uint8_t* a = &now[static_cast<std::size_t>(y) * w];
        const std::uint8_t* b = &before[static_cast<std::size_t>(y) * w];
        if (std::memcmp(a, b, w) == 0) continue;
        y0 = std::min(y0, y), y1 = y + 1;
        int l = 0, r = w;
        while (a[l] == b[l]) ++l;
        while (a[r - 1] == b[r - 1]) --r;
        x0 = std::min(x0, l), x1 = std::max(x1, r);
      }
      if (x1 <= x0) x0 = 0, y0 = 0, x1 = 1, y1 = 1;
    }
    const long long end = k + 1 < kept_.size() ? start_cs_[kept_[k + 1]] : start_cs_[count_];
    GraphicsControlBlock gcb{};
    gcb.DisposalMode = DISPOSE_DO_NOT;
    gcb.DelayTime = static_cast<int>(std::clamp<long long>(end - start_cs_[i], 2, 65535));
    gcb.TransparentColor = k > 0 ? kTransparent : NO_TRANSPARENT_COLOR;
    GifByteType ext[4];
    EGifGCBToExtension(&gcb, ext);
    check(EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, 4, ext), gif_, "delay");
    check(EGifPutImageDesc(gif_, x0, y0, x1 - x0, y1 - y0, false, nullptr), gif_, "image");
    row_.resize(w);
    for (int y = y0; y < y1; ++y) {
      const std::uint8_t* a = &now[static_cast<std::size_t>(y) * w];
      const std::uint8_t* b = k > 0 ? &before[static_cast<std::size_t>(y) * w] : a;
      for (int x = x0; x < x1; ++x) row_[x - x0] = k > 0 && a[x] == b[x] ? kTransparent : a[x];
      check(EGifPutLine(gif_, row_.data(), x1 - x0), gif_, "pixels");
    }
  }

  std::string finish() override {
    if (added_ != count_) throw std::logic_error("gif: frames missing");
    int error = 0;
    GifFileType* gif = gif_;
    gif_ = nullptr;
    if (EGifCloseFile(gif, &error) != GIF_OK) throw std::runtime_error(std::string("gif: close: ") + GifErrorString(error));
    return std::move(out_);
  }

 private:
  ImageSize size_;
  int count_ = 0, added_ = 0;
  std::vector<long long> start_cs_;
  std::vector<int> kept_;
  std::size_t next_kept_ = 0;
  std::string out_;
  GifFileType* gif_ = nullptr;
  std::vector<std::uint8_t> indices_[2];  // this kept frame's palette indices and the last one's
  std::vector<GifByteType> row_;
};

}  // namespace

std::unique_ptr<ClipEncoder> make_gif_encoder(ImageSize size, std::vector<int> durations_ms) {
  return std::make_unique<GifEncoder>(size, durations_ms);
}

}  // namespace softtune::render
