#pragma once
// The clips' 256-colour palette (clip_gif.cpp uses it as the GIF's palette; clip_webp.cpp maps WebP
// frames through it when WebpClipOptions::palette is set): the preview's own colours first, so
// backgrounds, bodies and text keep their exact colour, then a 6x6x6 cube for blends and fringes; index
// kClipTransparentIndex is left for a differenced frame's unchanged pixels.

#include <cstdint>
#include <vector>

#include "softtune/render/palette.h"

namespace softtune::render {

inline constexpr int kClipTransparentIndex = 255;
/// The palette's first entries: the preview's own colours (11 of the palette, 2 for each of 5 roles).
inline constexpr int kClipOwnColours = 21;

/// Nearest palette entry of every 5-bit-per-channel colour, made once.
struct ClipQuantizer {
  std::vector<Rgba> colours;
  std::vector<std::uint8_t> table;
  ClipQuantizer();
  std::uint8_t index(const std::uint8_t* px) const { return table[((px[0] >> 3) << 10) | ((px[1] >> 3) << 5) | (px[2] >> 3)]; }
};
const ClipQuantizer& clip_quantizer();

}  // namespace softtune::render
