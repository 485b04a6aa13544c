// Text (render/src/text.cpp): FreeType glyphs of DejaVu Sans blended into RGBA pixels.
#include "softtune/render/text.h"

#include <gtest/gtest.h>

#include <vector>

namespace softtune::render {
namespace {

// FreeType text: anti-aliased (partial coverage at glyph edges), inside the box measure_text gives,
// mixed case, clipped to the image.
TEST(BlitText, AntiAliasedGlyphsInsideTheirMeasuredBox) {
  ASSERT_TRUE(vector_font_available()) << "DejaVu Sans (fonts-dejavu-core) is in scripts/setup.sh";
  const ImageSize size{120, 40};
  std::vector<std::uint8_t> px(rgba_bytes(size), 0);
  const TextBox box = blit_text(px, size, "Hz \u03b6", 10, 5, 16, {255, 255, 255, 255});
  const TextBox measured = measure_text("Hz \u03b6", 10, 5, 16);
  EXPECT_EQ(box.right, measured.right);
  EXPECT_EQ(box.bottom, measured.bottom);
  int full = 0, partial = 0;
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const std::uint8_t v = px[(static_cast<std::size_t>(y) * size.width + x) * 4];
      if (v == 0) continue;
      (v == 255 ? full : partial) += 1;
      EXPECT_GE(x, box.left);
      EXPECT_LT(x, box.right);
      EXPECT_GE(y, box.top);
      EXPECT_LT(y, box.bottom);
    }
  }
  EXPECT_GT(full, 20);
  EXPECT_GT(partial, 20);  // edges blend: anti-aliasing
  // Lower case is its own glyph, narrower than upper case; lines stack line_height_px apart.
  EXPECT_LT(measure_text("aaaa", 0, 0, 16).right, measure_text("AAAA", 0, 0, 16).right);
  EXPECT_EQ(measure_text("A\nB", 0, 0, 16).bottom - measure_text("A", 0, 0, 16).bottom, line_height_px(16));
  // Off the edges: no writes out of bounds.
  blit_text(px, size, "Wide text\noff", 100, 30, 20, palette::kText);
  blit_text(px, size, "neg", -7, -9, 12, palette::kText);
  blit_text(px, size, "\xff\xfe broken utf-8", 0, 0, 12, palette::kText);
}

}  // namespace
}  // namespace softtune::render
