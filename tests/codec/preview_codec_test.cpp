// The preview contract shared by `softtune render` and POST /api/v1/preview: sizes, defaults and caps, the
// canonical request.
#include "codec/preview_codec.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

namespace softtune::codec {
namespace {

render::PreviewSettings read(const nlohmann::json& doc) {
  ObjectReader r = read_object(doc, "");
  render::PreviewSettings s = read_preview_settings(r);
  r.finish();
  return s;
}

std::string failing_field(const nlohmann::json& doc) {
  try {
    read(doc);
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    return p.field;
  }
  return "(accepted)";
}

TEST(PreviewCodec, ParsesSizes) {
  EXPECT_EQ(parse_image_size("640x360"), (render::ImageSize{640, 360}));
  EXPECT_FALSE(parse_image_size("640"));
  EXPECT_FALSE(parse_image_size("640x"));
  EXPECT_FALSE(parse_image_size("x360"));
  EXPECT_FALSE(parse_image_size("-640x360"));
  EXPECT_FALSE(parse_image_size("640x360x2"));
  EXPECT_FALSE(parse_image_size("0x360"));
  EXPECT_FALSE(parse_image_size("99999999999x360"));
}

TEST(PreviewCodec, DefaultsAndCaps) {
  const render::PreviewSettings d = read(nlohmann::json::object());
  EXPECT_EQ(d.frames, 60);
  EXPECT_EQ(d.size, (render::ImageSize{640, 360}));
  const render::PreviewSettings m = read({{"frames", 600}, {"size", "1920x1080"}});
  EXPECT_EQ(m.frames, 600);
  EXPECT_EQ(failing_field({{"frames", 601}}), "frames");
  EXPECT_EQ(failing_field({{"frames", 0}}), "frames");
  EXPECT_EQ(failing_field({{"frames", 2.5}}), "frames");
  EXPECT_EQ(failing_field({{"size", "1921x1080"}}), "size");
  EXPECT_EQ(failing_field({{"size", "640x1081"}}), "size");
  EXPECT_EQ(failing_field({{"size", "big"}}), "size");
  EXPECT_EQ(failing_field({{"size", 640}}), "size");
  EXPECT_EQ(failing_field({{"frames", 10}, {"filmstrip_every", 11}}), "filmstrip_every");
}

TEST(PreviewCodec, CanonicalRequestIsTheResolvedPhysics) {
  render::OscillatorScene a, b;
  EXPECT_EQ(canonical_oscillator_request(a), canonical_oscillator_request(b));
  b.damping_ratio = 0.25;
  EXPECT_NE(canonical_oscillator_request(a), canonical_oscillator_request(b));
  b = a;
  b.method = Method::soft_exact;
  EXPECT_NE(canonical_oscillator_request(a), canonical_oscillator_request(b));
}

}  // namespace
}  // namespace softtune::codec
