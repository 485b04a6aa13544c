// Bitmap text into RGBA (text.cpp): each font dot is `dot` x `dot` opaque pixels of the colour at the right
// place, lines advance by glyph height plus a gap, dots off the image are clipped, and width is the longest line.
#include "softtune/render/text.h"

#include <gtest/gtest.h>

#include <vector>

#include "softtune/render/font.h"
#include "softtune/render/palette.h"

namespace softtune::render {
namespace {

constexpr Rgba kInk{10, 200, 30, 255};

struct Image {
  ImageSize size;
  std::vector<std::uint8_t> rgba;
  explicit Image(int w, int h) : size{w, h}, rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  bool inked(int x, int y) const {
    const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * size.width + x) * 4];
    return p[0] == kInk.r && p[1] == kInk.g && p[2] == kInk.b && p[3] == 255;
  }
  int inked_count() const {
    int n = 0;
    for (int y = 0; y < size.height; ++y) {
      for (int x = 0; x < size.width; ++x) n += inked(x, y);
    }
    return n;
  }
};

int font_dots(char c) {
  int n = 0;
  for (auto r : glyph_rows(c)) n += __builtin_popcount(r);
  return n;
}

TEST(BlitText, OneDotPerLitGlyphBitClippedToTheImage) {
  const ImageSize size{40, 20};
  std::vector<std::uint8_t> px(40 * 20 * 4, 0);
  blit_text(px, size, "1", 10, 5, 2, palette::kText);
  int lit_dots = 0;
  for (std::uint8_t row : glyph_rows('1')) {
    for (int b = 0; b < kGlyphWidth; ++b) lit_dots += (row >> b) & 1;
  }
  int lit_pixels = 0;
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 40; ++x) {
      if (px[(y * 40 + x) * 4 + 3] == 255) {
        ++lit_pixels;
        EXPECT_GE(x, 10);
        EXPECT_LT(x, 10 + kGlyphWidth * 2);
        EXPECT_GE(y, 5);
        EXPECT_LT(y, 5 + kGlyphHeight * 2);
      }
    }
  }
  EXPECT_EQ(lit_pixels, lit_dots * 4);
  // Off the edges: no writes out of bounds, and what is inside still appears.
  blit_text(px, size, "WIDE TEXT\nOFF", 30, 15, 3, palette::kText);
  blit_text(px, size, "NEG", -7, -4, 1, palette::kText);
  EXPECT_EQ(text_width_px("AB\nABCD", 2), 4 * kGlyphAdvance * 2);
}

TEST(Text, EachDotIsASquareOfPixelsWhereTheFontPutsIt) {
  Image img(40, 30);
  blit_text(img.rgba, img.size, "T", 4, 2, 3, kInk);
  EXPECT_EQ(img.inked_count(), font_dots('T') * 9);
  // T's top row is full: 5 dots x 3 px from x = 4, rows 2..4; its stem is the middle column below.
  for (int x = 4; x < 19; ++x) EXPECT_TRUE(img.inked(x, 2)) << x;
  EXPECT_FALSE(img.inked(3, 2));
  EXPECT_FALSE(img.inked(19, 2));
  EXPECT_TRUE(img.inked(4 + 2 * 3, 2 + 6 * 3));  // bottom of the stem
  EXPECT_FALSE(img.inked(4, 2 + 6 * 3));
}

TEST(Text, LinesAndCharactersAdvance) {
  Image img(60, 60);
  blit_text(img.rgba, img.size, "--\n-", 0, 0, 1, kInk);
  // '-' is row 3 of its glyph; the second '-' starts one advance (6 dots) right, the next line 7 + 4 down.
  EXPECT_TRUE(img.inked(0, 3));
  EXPECT_TRUE(img.inked(kGlyphAdvance, 3));
  EXPECT_FALSE(img.inked(kGlyphWidth, 3));  // the gap between characters
  EXPECT_TRUE(img.inked(0, 3 + kGlyphHeight + 4));
  EXPECT_FALSE(img.inked(kGlyphAdvance, 3 + kGlyphHeight + 4));
  EXPECT_EQ(img.inked_count(), 3 * kGlyphWidth);
}

TEST(Text, DotsOffTheImageAreClipped) {
  Image img(8, 8);
  blit_text(img.rgba, img.size, "WW", -3, 5, 2, kInk);  // mostly outside, never written out of bounds
  EXPECT_GT(img.inked_count(), 0);
  EXPECT_LT(img.inked_count(), 2 * font_dots('W') * 4);
  std::vector<std::uint8_t> short_buffer(10, 0);
  blit_text(short_buffer, img.size, "W", 0, 0, 1, kInk);  // a buffer too small for the size: nothing drawn
  for (auto b : short_buffer) EXPECT_EQ(b, 0);
}

TEST(Text, WidthIsTheLongestLine) {
  EXPECT_EQ(text_width_px("", 2), 0);
  EXPECT_EQ(text_width_px("ABC", 1), 3 * kGlyphAdvance);
  EXPECT_EQ(text_width_px("AB\nCDEF\nG", 2), 4 * kGlyphAdvance * 2);
}

}  // namespace
}  // namespace softtune::render
