#pragma once
// A 5x7 bitmap font for labels and captions: enough to be readable at 640x360 without a font library.

#include <array>
#include <cstdint>

namespace softtune::render {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;  ///< dots from one character to the next

/// Rows top to bottom; bit 4 is the leftmost dot. Lower case maps to upper case; a character the font
/// lacks shows as '?'.
std::array<std::uint8_t, kGlyphHeight> glyph_rows(char c);

}  // namespace softtune::render
