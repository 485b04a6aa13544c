#include "softtune/render/text.h"

#include <algorithm>

#include "softtune/render/font.h"

namespace softtune::render {

void blit_text(std::span<std::uint8_t> rgba, ImageSize size, std::string_view text, int x, int y, int dot, Rgba colour) {
  if (rgba.size() < static_cast<std::size_t>(size.width) * size.height * 4) return;
  const int left = x;
  for (char c : text) {
    if (c == '\n') {
      x = left;
      y += (kGlyphHeight + 4) * dot;
      continue;
    }
    const auto rows = glyph_rows(c);
    for (int r = 0; r < kGlyphHeight; ++r) {
      for (int col = 0; col < kGlyphWidth; ++col) {
        if (!(rows[r] & (0x10 >> col))) continue;
        const int px0 = std::max(0, x + col * dot), px1 = std::min(size.width, x + (col + 1) * dot);
        const int py0 = std::max(0, y + r * dot), py1 = std::min(size.height, y + (r + 1) * dot);
        for (int py = py0; py < py1; ++py) {
          for (int px = px0; px < px1; ++px) {
            std::uint8_t* p = &rgba[(static_cast<std::size_t>(py) * size.width + px) * 4];
            p[0] = colour.r, p[1] = colour.g, p[2] = colour.b, p[3] = 255;
          }
        }
      }
    }
    x += kGlyphAdvance * dot;
  }
}

int text_width_px(std::string_view text, int dot) {
  int longest = 0, current = 0;
  for (char c : text) {
    current = c == '\n' ? 0 : current + 1;
    longest = std::max(longest, current);
  }
  return longest * kGlyphAdvance * dot;
}

}  // namespace softtune::render
