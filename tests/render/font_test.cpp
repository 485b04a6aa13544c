// The 5x7 font (font.cpp): every glyph fits five dots, the mirror-symmetric letters are symmetric, lower case
// is upper case, the characters are told apart, and one the font lacks shows as '?'.
#include "softtune/render/font.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace softtune::render {
namespace {

using Rows = std::array<std::uint8_t, kGlyphHeight>;

Rows mirrored(Rows rows) {
  for (auto& r : rows) {
    std::uint8_t m = 0;
    for (int col = 0; col < kGlyphWidth; ++col) {
      if (r & (1 << col)) m |= static_cast<std::uint8_t>(1 << (kGlyphWidth - 1 - col));
    }
    r = m;
  }
  return rows;
}

int dots(const Rows& rows) {
  int n = 0;
  for (auto r : rows) n += __builtin_popcount(r);
  return n;
}

const std::string kCharacters = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.,:=-+/()%_'?";

TEST(Font, LowerCaseIsUpperCaseAndUnknownIsQuestionMark) {
  EXPECT_EQ(glyph_rows('a'), glyph_rows('A'));
  EXPECT_EQ(glyph_rows('~'), glyph_rows('?'));
  EXPECT_NE(glyph_rows('0'), glyph_rows('O'));
}

TEST(Font, GlyphsFitFiveDotsAndAreToldApart) {
  std::set<Rows> shapes;
  for (char c : kCharacters) {
    const Rows rows = glyph_rows(c);
    for (auto r : rows) EXPECT_LT(r, 1 << kGlyphWidth) << c;
    EXPECT_GT(dots(rows), 0) << c;
    EXPECT_TRUE(shapes.insert(rows).second) << c << " looks like another character";
  }
  EXPECT_EQ(dots(glyph_rows(' ')), 0);
}

TEST(Font, SymmetricLettersAreSymmetric) {
  for (char c : std::string("AHIMOTUVWXY8=-+")) EXPECT_EQ(mirrored(glyph_rows(c)), glyph_rows(c)) << c;
  EXPECT_NE(mirrored(glyph_rows('R')), glyph_rows('R'));
  EXPECT_EQ(mirrored(glyph_rows('(')), glyph_rows(')'));
  // '-' is one full row; '_' is the bottom row.
  EXPECT_EQ(dots(glyph_rows('-')), kGlyphWidth);
  EXPECT_EQ(glyph_rows('_')[kGlyphHeight - 1], (1 << kGlyphWidth) - 1);
}

TEST(Font, EveryLowerCaseLetterAndSeveralMissingCharacters) {
  for (char c = 'a'; c <= 'z'; ++c) EXPECT_EQ(glyph_rows(c), glyph_rows(static_cast<char>(c - 'a' + 'A'))) << c;
  for (char c : std::string("~#@\x7f")) EXPECT_EQ(glyph_rows(c), glyph_rows('?')) << int(c);
}

}  // namespace
}  // namespace softtune::render
