#pragma once
// Bitmap text straight into RGBA pixels (the 5x7 font of font.h), clipped to the image.

#include <cstdint>
#include <span>
#include <string_view>

#include "softtune/render/palette.h"
#include "softtune/render/view.h"

namespace softtune::render {

/// Writes `text` with its top-left corner at pixel (x, y), `dot` x `dot` pixels per font dot, in an
/// opaque `colour`; '\n' starts a new line. Dots outside the image are skipped.
void blit_text(std::span<std::uint8_t> rgba, ImageSize size, std::string_view text, int x, int y, int dot, Rgba colour);

/// Pixel width of the longest line of `text`.
int text_width_px(std::string_view text, int dot);

}  // namespace softtune::render
