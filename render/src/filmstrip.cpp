#include "softtune/render/filmstrip.h"

#include <algorithm>
#include <string>

#include "softtune/render/font.h"
#include "softtune/render/palette.h"
#include "softtune/render/text.h"

namespace softtune::render {
namespace {

constexpr Rgba kSheet{52, 54, 60, 255};
constexpr Rgba kTagBackground{255, 255, 255, 255};

void fill(std::vector<std::uint8_t>& px, int stride, int x0, int y0, int w, int h, Rgba c) {
  for (int y = y0; y < y0 + h; ++y) {
    for (int x = x0; x < x0 + w; ++x) {
      std::uint8_t* p = &px[(static_cast<std::size_t>(y) * stride + x) * 4];
      p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = c.a;
    }
  }
}

}  // namespace

FilmstripLayout filmstrip_layout(int frames, int every, ImageSize frame) {
  FilmstripLayout l;
  frames = std::max(frames, 1);
  l.every = every > 0 ? every : std::max(1, (frames + kFilmstripTargetTiles - 1) / kFilmstripTargetTiles);
  l.tiles = (frames + l.every - 1) / l.every;
  l.columns = std::min(l.tiles, kFilmstripColumns);
  l.rows = (l.tiles + l.columns - 1) / l.columns;
  l.shrink = std::max(1, (frame.width + kFilmstripTileWidth - 1) / kFilmstripTileWidth);
  l.tile = {std::max(1, frame.width / l.shrink), std::max(1, frame.height / l.shrink)};
  l.sheet = {l.columns * l.tile.width + (l.columns + 1) * l.gap_px, l.rows * l.tile.height + (l.rows + 1) * l.gap_px};
  return l;
}

Filmstrip::Filmstrip(const FilmstripLayout& layout)
    : layout_(layout), pixels_(static_cast<std::size_t>(layout.sheet.width) * layout.sheet.height * 4) {
  fill(pixels_, layout_.sheet.width, 0, 0, layout_.sheet.width, layout_.sheet.height, kSheet);
}

void Filmstrip::place(int index, std::span<const std::uint8_t> rgba, ImageSize frame) {
  if (index < 0 || index % layout_.every != 0) return;
  const int t = index / layout_.every;
  if (t >= layout_.tiles) return;
  const int s = layout_.shrink, tw = layout_.tile.width, th = layout_.tile.height;
  const int stride_in = frame.width;
  if (rgba.size() < static_cast<std::size_t>(frame.width) * frame.height * 4 || frame.width < tw * s ||
      frame.height < th * s) {
    return;
  }
  const int x0 = layout_.gap_px + (t % layout_.columns) * (tw + layout_.gap_px);
  const int y0 = layout_.gap_px + (t / layout_.columns) * (th + layout_.gap_px);
  // Box filter: each tile pixel is the mean of an s x s block.
  for (int y = 0; y < th; ++y) {
    for (int x = 0; x < tw; ++x) {
      unsigned sum[4] = {0, 0, 0, 0};
      for (int dy = 0; dy < s; ++dy) {
        const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y * s + dy) * stride_in + x * s) * 4];
        for (int dx = 0; dx < s; ++dx, p += 4) {
          for (int c = 0; c < 4; ++c) sum[c] += p[c];
        }
      }
      std::uint8_t* q = &pixels_[(static_cast<std::size_t>(y0 + y) * layout_.sheet.width + x0 + x) * 4];
      for (int c = 0; c < 4; ++c) q[c] = static_cast<std::uint8_t>((sum[c] + s * s / 2) / (s * s));
    }
  }
  // The frame number, top-left, dark on white.
  constexpr int kTagPx = 10;
  const std::string tag = std::to_string(index);
  const TextBox box = measure_text(tag, 0, 0, kTagPx);
  const int tag_w = box.right + 4, tag_h = box.bottom + 2;
  if (tag_w > tw || tag_h > th) return;
  fill(pixels_, layout_.sheet.width, x0, y0, tag_w, tag_h, kTagBackground);
  blit_text(pixels_, layout_.sheet, tag, x0 + 2, y0 + 1, kTagPx, palette::kText);
}

std::string Filmstrip::encode(PngOptions options) const { return encode_png(pixels_, layout_.sheet, options); }

}  // namespace softtune::render
