#include "clip_palette.h"

#include <algorithm>

namespace softtune::render {

namespace {

std::vector<Rgba> clip_palette() {
  std::vector<Rgba> p{palette::kBackground, palette::kEarth,          palette::kGroundLine,     palette::kText,
                      palette::kAnchor,     palette::kSpringNeutral,  palette::kSpringStretched, palette::kSpringCompressed,
                      palette::kRod,        palette::kMouseLink,      palette::kPinFace};
  for (Role r : {Role::static_body, Role::dynamic_body, Role::probed, Role::wheel, Role::probed_second}) {
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
  p.resize(std::min<std::size_t>(p.size(), kClipTransparentIndex), palette::kBackground);
  while (p.size() < 256) p.push_back(palette::kBackground);  // the transparent index: never a nearest colour
  return p;
}

}  // namespace

ClipQuantizer::ClipQuantizer() : colours(clip_palette()), table(32 * 32 * 32) {
  for (int i = 0; i < 32 * 32 * 32; ++i) {
    const int r = ((i >> 10) & 31) * 255 / 31, g = ((i >> 5) & 31) * 255 / 31, b = (i & 31) * 255 / 31;
    int best = 0, best_d = 1 << 30;
    for (int k = 0; k < kClipTransparentIndex; ++k) {
      const int dr = r - colours[k].r, dg = g - colours[k].g, db = b - colours[k].b;
      const int d = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
      if (d < best_d) best_d = d, best = k;
    }
    table[i] = static_cast<std::uint8_t>(best);
  }
  // The preview's own colours win their own cell, so a flat fill, a spring or the text keeps its exact
  // colour (the text's cell is nearer the anchor colour by the cell-centre rule).
  for (int k = kClipOwnColours - 1; k >= 0; --k) {
    const Rgba c = colours[k];
    table[((c.r >> 3) << 10) | ((c.g >> 3) << 5) | (c.b >> 3)] = static_cast<std::uint8_t>(k);
  }
}

const ClipQuantizer& clip_quantizer() {
  static const ClipQuantizer q;
  return q;
}

}  // namespace softtune::render
