// The clips' palette (render/src/clip_palette.cpp): the preview's own colours map to themselves, so flat
// fills, springs and text keep their exact colour in a GIF or a palette WebP; the transparent index is
// never anyone's nearest colour; any colour lands within a cube step of where it was.
#include "clip_palette.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace softtune::render {
namespace {

TEST(ClipPalette, ThePreviewsOwnColoursStayExact) {
  const ClipQuantizer& q = clip_quantizer();
  std::vector<Rgba> own{palette::kBackground, palette::kText, palette::kAnchor, palette::kSpringNeutral,
                        palette::kSpringStretched, palette::kSpringCompressed, palette::kRod, palette::kMouseLink};
  for (Role r : {Role::static_body, Role::dynamic_body, Role::probed, Role::wheel, Role::probed_second}) {
    own.push_back(role_colours(r).fill);
    own.push_back(role_colours(r).outline);
  }
  for (const Rgba c : own) {
    const std::uint8_t px[4] = {c.r, c.g, c.b, 255};
    const Rgba got = q.colours[q.index(px)];
    // The table is indexed by 5 bits a channel: an own colour is its cell's nearest entry, within the
    // cell's 8 levels of it.
    EXPECT_LE(std::abs(got.r - c.r) + std::abs(got.g - c.g) + std::abs(got.b - c.b), 0)
        << int(c.r) << "," << int(c.g) << "," << int(c.b) << " -> " << int(got.r) << "," << int(got.g) << "," << int(got.b);
  }
}

TEST(ClipPalette, TheTransparentIndexIsNoColoursNearestAndEveryColourLandsNear) {
  const ClipQuantizer& q = clip_quantizer();
  constexpr int kMaxError = 3 * (26 + 8);
  for (int r = 0; r < 256; r += 5) {
    for (int g = 0; g < 256; g += 5) {
      for (int b = 0; b < 256; b += 5) {
        const std::uint8_t px[4] = {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b), 255};
        const int i = q.index(px);
        ASSERT_NE(i, kClipTransparentIndex);
        const Rgba c = q.colours[i];
        // The 6x6x6 cube is 51 levels a step: no further than half a step a channel and the 5-bit cell.
        ASSERT_LE(std::abs(c.r - r) + std::abs(c.g - g) + std::abs(c.b - b), kMaxError)
            << r << "," << g << "," << b << " -> " << int(c.r) << "," << int(c.g) << "," << int(c.b);
      }
    }
  }
}

}  // namespace
}  // namespace softtune::render
