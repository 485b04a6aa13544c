#include "softtune/render/png.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "png_decode.h"

namespace softtune::render {
namespace {

std::vector<std::uint8_t> pattern(ImageSize s) {
  std::vector<std::uint8_t> px(static_cast<std::size_t>(s.width) * s.height * 4);
  for (int y = 0; y < s.height; ++y) {
    for (int x = 0; x < s.width; ++x) {
      std::uint8_t* p = &px[(static_cast<std::size_t>(y) * s.width + x) * 4];
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 13);
      p[2] = static_cast<std::uint8_t>((x ^ y) * 3);
      p[3] = 255;
    }
  }
  return px;
}

TEST(Png, RoundTripsExactlyAtEveryLevelAndFilter) {
  const ImageSize s{37, 23};  // odd sizes: no row padding assumptions
  const auto px = pattern(s);
  for (int level : {0, 1, 6, 9}) {
    for (PngFilter f : {PngFilter::none, PngFilter::up, PngFilter::paeth, PngFilter::all}) {
      const test::Decoded d = test::decode_png(encode_png(px, s, {level, f}));
      ASSERT_EQ(d.width, s.width);
      ASSERT_EQ(d.height, s.height);
      EXPECT_EQ(d.rgba, px) << "level " << level;
    }
  }
}

TEST(Png, OpaqueOutputFromAnyAlpha) {
  const ImageSize s{4, 4};
  std::vector<std::uint8_t> px(4 * 4 * 4, 100);  // alpha 100 in the input
  const test::Decoded d = test::decode_png(encode_png(px, s));
  EXPECT_EQ(d.at(2, 2)[0], 100);
  EXPECT_EQ(d.at(2, 2)[3], 255);  // RGB PNG: frames are opaque
}

TEST(Png, HigherLevelIsNotLarger) {
  const ImageSize s{64, 64};
  const auto px = pattern(s);
  EXPECT_LE(encode_png(px, s, {9, PngFilter::up}).size(), encode_png(px, s, {0, PngFilter::up}).size());
}

// Cached previews hold these strings for long: a flat frame compresses to a few hundred bytes and
// must not keep the encoder's guess of the size (an eighth of the RGBA) as capacity.
TEST(Png, HoldsNoMoreThanItsBytes) {
  const ImageSize s{640, 360};
  const std::vector<std::uint8_t> flat(static_cast<std::size_t>(s.width) * s.height * 4, 200);
  const std::string png = encode_png(flat, s);
  EXPECT_LT(png.size(), 4096u);
  EXPECT_LE(png.capacity(), png.size() + 64);
}

TEST(Png, RefusesABufferOfTheWrongSize) {
  std::vector<std::uint8_t> px(10);
  EXPECT_THROW(encode_png(px, {4, 4}), std::invalid_argument);
  EXPECT_THROW(encode_png(px, {0, 4}), std::invalid_argument);
}

}  // namespace
}  // namespace softtune::render
