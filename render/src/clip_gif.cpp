// Animated GIF with giflib 5.2 (gif_lib.h): one global 256-colour palette, a NETSCAPE2.0 loop block, and
// per frame a graphics control block carrying its delay in centiseconds.
#include <gif_lib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "softtune/render/palette.h"
#include "softtune/render/view.h"

namespace softtune::render {
namespace {

// The preview's own colours first (so backgrounds, bodies and text keep their exact colour), then a
// 6x6x6 cube for blends and fringes.
std::vector<Rgba> gif_palette() {
  std::vector<Rgba> p{palette::kBackground, palette::kEarth,          palette::kGroundLine,     palette::kText,
                      palette::kAnchor,     palette::kSpringNeutral,  palette::kSpringStretched, palette::kSpringCompressed,
                      palette::kRod,        palette::kMouseLink,      palette::kPinFace};
  for (Role r : {Role::static_body, Role::dynamic_body, Role::probed}) {
    p.push_back(role_colours(r).fill);
    p.push_back(role_colours(r).outline);
  }
  for (int r = 0; r < 6; ++r) {
    for (int g = 0; g < 6; ++g) {
      for (int b = 0; b < 6; ++b) {
        p.push_back({static_cast<std::uint8_t>(r * 51), static_cast<std::uint8_t>(g * 51), static_cast<std::uint8_t>(b * 51), 255});
      }
    }
  }
  p.resize(std::min<std::size_t>(p.size(), 256), palette::kBackground);
  while (p.size() < 256) p.push_back(palette::kBackground);
  return p;
}

// Nearest palette entry of every 5-bit-per-channel colour, made once.
struct Quantizer {
  std::vector<Rgba> colours = gif_palette();
  std::vector<std::uint8_t> table = std::vector<std::uint8_t>(32 * 32 * 32);
  Quantizer() {
    for (int i = 0; i < 32 * 32 * 32; ++i) {
      const int r = ((i >> 10) & 31) * 255 / 31, g = ((i >> 5) & 31) * 255 / 31, b = (i & 31) * 255 / 31;
      int best = 0, best_d = 1 << 30;
      for (int k = 0; k < static_cast<int>(colours.size()); ++k) {
        const int dr = r - colours[k].r, dg = g - colours[k].g, db = b - colours[k].b;
        const int d = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
        if (d < best_d) best_d = d, best = k;
      }
      table[i] = static_cast<std::uint8_t>(best);
    }
  }
  std::uint8_t index(const std::uint8_t* px) const { return table[((px[0] >> 3) << 10) | ((px[1] >> 3) << 5) | (px[2] >> 3)]; }
};

const Quantizer& quantizer() {
  static const Quantizer q;
  return q;
}

int write_to_string(GifFileType* gif, const GifByteType* bytes, int n) {
  static_cast<std::string*>(gif->UserData)->append(reinterpret_cast<const char*>(bytes), n);
  return n;
}

void check(int status, GifFileType* gif, const char* what) {
  if (status != GIF_OK) throw std::runtime_error(std::string("gif: ") + what + ": " + GifErrorString(gif->Error));
}

}  // namespace

std::string encode_gif_clip(int count, ImageSize size, const std::vector<int>& durations_ms,
                            const std::function<std::vector<std::uint8_t>(int)>& frame) {
  const Quantizer& q = quantizer();
  // Frame starts in cs, rounded from the ms timeline; a frame under 2 cs after the last kept one merges.
  std::vector<long long> start_cs(count + 1);
  long long ms = 0;
  for (int i = 0; i <= count; ++i) {
    start_cs[i] = (ms + 5) / 10;
    if (i < count) ms += durations_ms[i];
  }
  std::vector<int> kept;
  for (int i = 0; i < count; ++i) {
    if (kept.empty() || start_cs[i] - start_cs[kept.back()] >= 2) kept.push_back(i);
  }
  std::string out;
  int error = 0;
  GifFileType* gif = EGifOpen(&out, write_to_string, &error);
  if (!gif) throw std::runtime_error(std::string("gif: ") + GifErrorString(error));
  struct Closer {
    GifFileType* g;
    ~Closer() {
      int e = 0;
      if (g) EGifCloseFile(g, &e);
    }
  } closer{gif};
  ColorMapObject* map = GifMakeMapObject(256, nullptr);
  if (!map) throw std::runtime_error("gif: out of memory");
  for (int k = 0; k < 256; ++k) map->Colors[k] = {q.colours[k].r, q.colours[k].g, q.colours[k].b};
  EGifSetGifVersion(gif, true);
  const int screen = EGifPutScreenDesc(gif, size.width, size.height, 8, 0, map);
  GifFreeMapObject(map);
  check(screen, gif, "screen");
  // Loop forever: the NETSCAPE2.0 application block with loop count 0.
  check(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), gif, "loop");
  check(EGifPutExtensionBlock(gif, 11, "NETSCAPE2.0"), gif, "loop");
  const unsigned char loop[3] = {1, 0, 0};
  check(EGifPutExtensionBlock(gif, 3, loop), gif, "loop");
  check(EGifPutExtensionTrailer(gif), gif, "loop");
  std::vector<GifByteType> row(size.width);
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const int i = kept[k];
    const long long end = k + 1 < kept.size() ? start_cs[kept[k + 1]] : start_cs[count];
    GraphicsControlBlock gcb{};
    gcb.DisposalMode = DISPOSE_DO_NOT;
    gcb.DelayTime = static_cast<int>(std::clamp<long long>(end - start_cs[i], 2, 65535));
    gcb.TransparentColor = NO_TRANSPARENT_COLOR;
    GifByteType ext[4];
    EGifGCBToExtension(&gcb, ext);
    check(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, 4, ext), gif, "delay");
    check(EGifPutImageDesc(gif, 0, 0, size.width, size.height, false, nullptr), gif, "image");
    const std::vector<std::uint8_t> rgba = frame(i);
    for (int y = 0; y < size.height; ++y) {
      const std::uint8_t* px = &rgba[static_cast<std::size_t>(y) * size.width * 4];
      for (int x = 0; x < size.width; ++x) row[x] = q.index(px + 4 * x);
      check(EGifPutLine(gif, row.data(), size.width), gif, "pixels");
    }
  }
  closer.g = nullptr;
  if (EGifCloseFile(gif, &error) != GIF_OK) throw std::runtime_error(std::string("gif: close: ") + GifErrorString(error));
  return out;
}

}  // namespace softtune::render
