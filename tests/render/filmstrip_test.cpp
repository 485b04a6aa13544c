#include "softtune/render/filmstrip.h"

#include <gtest/gtest.h>

#include <vector>

#include "png_decode.h"

namespace softtune::render {
namespace {

TEST(FilmstripLayout, AutomaticEveryGivesAboutTenTiles) {
  const FilmstripLayout l = filmstrip_layout(60, 0, {640, 360});
  EXPECT_EQ(l.every, 6);
  EXPECT_EQ(l.tiles, 10);
  EXPECT_EQ(l.columns, 5);
  EXPECT_EQ(l.rows, 2);
  EXPECT_EQ(l.shrink, 4);
  EXPECT_EQ(l.tile, (ImageSize{160, 90}));
  EXPECT_EQ(l.sheet, (ImageSize{5 * 160 + 6 * 4, 2 * 90 + 3 * 4}));
}

TEST(FilmstripLayout, EveryFrameAndOddCounts) {
  EXPECT_EQ(filmstrip_layout(3, 1, {640, 360}).tiles, 3);
  EXPECT_EQ(filmstrip_layout(3, 1, {640, 360}).columns, 3);
  EXPECT_EQ(filmstrip_layout(61, 0, {640, 360}).tiles, 9);  // every 7: frames 0..56
  EXPECT_EQ(filmstrip_layout(600, 0, {1920, 1080}).tile, (ImageSize{160, 90}));
}

TEST(Filmstrip, TilesAreTheBoxMeanOfTheirFrames) {
  const ImageSize frame{64, 32};
  const FilmstripLayout l = filmstrip_layout(4, 2, frame);  // frames 0 and 2
  ASSERT_EQ(l.shrink, 1);
  Filmstrip strip(l);
  // Frame 2: left half black, right half white, so tile 1 has both.
  std::vector<std::uint8_t> px(64 * 32 * 4, 255);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      for (int c = 0; c < 3; ++c) px[(y * 64 + x) * 4 + c] = 0;
    }
  }
  strip.place(1, px, frame);  // not shown: ignored
  strip.place(2, px, frame);
  const test::Decoded d = test::decode_png(strip.encode({}));
  ASSERT_EQ(d.width, l.sheet.width);
  const int x0 = l.gap_px * 2 + l.tile.width, y0 = l.gap_px;
  EXPECT_EQ(d.at(x0 + 20, y0 + 25)[0], 0);     // black half, below the number tag
  EXPECT_EQ(d.at(x0 + 50, y0 + 25)[0], 255);   // white half
  EXPECT_NE(d.at(l.gap_px + 30, y0 + 20)[0], 0);  // tile 0 never placed: sheet colour
}

TEST(Filmstrip, ShrinksByAveraging) {
  const ImageSize frame{640, 360};
  const FilmstripLayout l = filmstrip_layout(1, 1, frame);
  ASSERT_EQ(l.shrink, 4);
  Filmstrip strip(l);
  // Alternating black and white columns average to mid grey.
  std::vector<std::uint8_t> px(640 * 360 * 4, 255);
  for (int y = 0; y < 360; ++y) {
    for (int x = 0; x < 640; x += 2) {
      for (int c = 0; c < 3; ++c) px[(y * 640 + x) * 4 + c] = 0;
    }
  }
  strip.place(0, px, frame);
  const std::uint8_t* p = &strip.pixels()[((l.gap_px + 60) * l.sheet.width + l.gap_px + 100) * 4];
  EXPECT_NEAR(p[0], 128, 1);
}

}  // namespace
}  // namespace softtune::render
