#pragma once
// Text straight into RGBA pixels, clipped to the image: anti-aliased glyphs of DejaVu Sans rasterised by
// FreeType (the font found through fontconfig, else Debian's documented path), with the 5x7 bitmap font
// (font.h) as the fallback on a machine without the font.
//
// Why here, in the process that calls the renderer, and not in softtune-raster: text is blended into the
// read-back pixels on the CPU (a few thousand pixel writes; as GL triangles each glyph would cost llvmpipe
// more than the scene), FreeType and fontconfig are small libraries that pull in no LLVM, and keeping
// the raster process a plain triangle rasterizer keeps the only OSMesa program small and the text
// layout testable without a GL context.

#include <cstdint>
#include <span>
#include <string_view>

#include "softtune/render/palette.h"
#include "softtune/render/view.h"

namespace softtune::render {

/// A text's box in pixels: x right, y down; top is the line's ascent, bottom its descent.
struct TextBox {
  int left = 0, top = 0, right = 0, bottom = 0;
};

/// Blends `text` into `rgba` with the top of its first line at pixel row `y` and its left at `x`, glyphs
/// `px` pixels tall (the em size), in `colour`; '\n' starts a new line (line_height_px apart). Pixels
/// outside the image are skipped. Returns the box the text covers.
TextBox blit_text(std::span<std::uint8_t> rgba, ImageSize size, std::string_view text, int x, int y, int px, Rgba colour);

/// The box blit_text() would cover, without drawing.
TextBox measure_text(std::string_view text, int x, int y, int px);

/// Pixels from one line's top to the next at em size `px`.
int line_height_px(int px);

/// True when a FreeType font was found (false: the 5x7 bitmap fallback draws).
bool vector_font_available();

}  // namespace softtune::render
