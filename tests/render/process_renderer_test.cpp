// Pixels read back from the OSMesa backend: background, body colours at their projected positions,
// spring colours, the context counter.
#include "softtune/render/renderer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "softtune/render/palette.h"

namespace softtune::render {
namespace {

constexpr ImageSize kSize{640, 360};

Camera fixed_camera() {
  Camera c;
  c.auto_fit = false;
  c.centre_m = {0.0, 0.0};
  c.width_m = 10.0;  // 64 px per metre; grid every metre on pixel columns 320 + 64 k
  return c;
}

struct Image {
  std::vector<std::uint8_t> px = std::vector<std::uint8_t>(kSize.width * kSize.height * 4);
  Rgba at(double x_m, double y_m) const {
    const View v = make_view(fixed_camera(), kSize);
    return at_px(static_cast<int>(v.px(x_m)), static_cast<int>(v.py(y_m)));
  }
  Rgba at_px(int x, int y) const {
    const std::uint8_t* p = &px[(static_cast<std::size_t>(y) * kSize.width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
  }
};

Image render(Renderer& r, const DrawFrame& f) {
  Image img;
  r.render(f, fixed_camera(), kSize, img.px);
  return img;
}

void expect_near(Rgba got, Rgba want, int tolerance, const char* what) {
  EXPECT_LE(std::abs(got.r - want.r), tolerance) << what << " r " << int(got.r) << " vs " << int(want.r);
  EXPECT_LE(std::abs(got.g - want.g), tolerance) << what << " g " << int(got.g) << " vs " << int(want.g);
  EXPECT_LE(std::abs(got.b - want.b), tolerance) << what << " b " << int(got.b) << " vs " << int(want.b);
  EXPECT_EQ(got.a, 255) << what;
}

// Straight-alpha "over" of a translucent colour on an opaque one.
Rgba over(Rgba top, Rgba below) {
  auto ch = [&](int t, int b) { return static_cast<std::uint8_t>((t * top.a + b * (255 - top.a)) / 255); };
  return {ch(top.r, below.r), ch(top.g, below.g), ch(top.b, below.b), 255};
}

PolygonShape box(double cx, double cy, double half, Role role) {
  return {{{cx - half, cy - half}, {cx + half, cy - half}, {cx + half, cy + half}, {cx - half, cy + half}}, role};
}

TEST(OsMesaRenderer, NoContextUntilTheFirstFrameThenOneForItsLife) {
  const int before = gl_contexts_created();
  auto r = make_osmesa_renderer();
  EXPECT_EQ(gl_contexts_created(), before);
  render(*r, DrawFrame{});
  EXPECT_EQ(gl_contexts_created(), before + 1);
  render(*r, DrawFrame{});
  EXPECT_EQ(gl_contexts_created(), before + 1);
}

TEST(OsMesaRenderer, BackgroundWhereNothingIs) {
  auto r = make_osmesa_renderer();
  const Image img = render(*r, DrawFrame{});
  // Between grid lines (columns 320 + 64 k, rows 180 + 64 k) and away from the text at the top.
  for (auto [x, y] : {std::pair{352, 212}, std::pair{100, 300}, std::pair{560, 300}}) {
    EXPECT_EQ(img.at_px(x, y), palette::kBackground) << x << "," << y;
  }
  // A grid line is faint: darker than the background, but only slightly.
  const Rgba grid = img.at_px(320, 300);
  EXPECT_LT(grid.r, palette::kBackground.r);
  EXPECT_GT(grid.r, palette::kBackground.r - 40);
}

TEST(OsMesaRenderer, BodiesShowTheirRoleColourAtTheirProjectedPosition) {
  for (int samples : {0, 4}) {
    auto r = make_osmesa_renderer({.msaa_samples = samples});
    DrawFrame f;
    f.polygons.push_back(box(2.0, 1.0, 0.5, Role::dynamic_body));
    f.polygons.push_back(box(-2.0, -1.0, 0.5, Role::static_body));
    f.circles.push_back({{-3.5, 1.5}, 0.6, 0.0, Role::probed});
    f.polygons.push_back(box(3.5, -1.5, 0.5, Role::ghost));
    const Image img = render(*r, f);
    expect_near(img.at(2.0, 1.0), role_colours(Role::dynamic_body).fill, 1, "dynamic");
    expect_near(img.at(-2.0, -1.0), role_colours(Role::static_body).fill, 1, "static");
    expect_near(img.at(-3.5, 1.3), role_colours(Role::probed).fill, 1, "probed circle");
    expect_near(img.at(3.6, -1.6), over(role_colours(Role::ghost).fill, palette::kBackground), 2, "ghost");
    // Just inside a box edge is the outline; just outside is the background.
    expect_near(img.at(2.0 + 0.5 - 0.5 / 64.0, 1.2), role_colours(Role::dynamic_body).outline, 40, "outline");
    expect_near(img.at(2.0 + 0.5 + 4.0 / 64.0, 1.2), palette::kBackground, 0, "outside");
  }
}

TEST(OsMesaRenderer, GroundFillsBelowItsLine) {
  auto r = make_osmesa_renderer();
  DrawFrame f;
  f.ground_y_m = -1.0;
  const Image img = render(*r, f);
  expect_near(img.at(0.3, -2.0), palette::kEarth, 0, "earth");
  expect_near(img.at(0.3, -1.0), palette::kGroundLine, 2, "ground line");
  expect_near(img.at(0.3, 0.5), palette::kBackground, 0, "sky");
}

TEST(OsMesaRenderer, SpringColourShowsStretchAndCompression) {
  auto r = make_osmesa_renderer();
  DrawFrame f;
  // Along y = 0 (pixel row boundary 180): the straight lead of each spring lies on that line.
  f.springs.push_back({{-4.0, 0.0}, {-1.0, 0.0}, 2.0, std::nullopt, false});  // 3 m for 2: stretched
  f.springs.push_back({{1.0, 0.0}, {2.0, 0.0}, 2.0, std::nullopt, false});    // 1 m for 2: compressed
  const Image img = render(*r, f);
  expect_near(img.at(-3.9, 0.0), palette::kSpringStretched, 1, "stretched");
  expect_near(img.at(1.04, 0.0), palette::kSpringCompressed, 1, "compressed");
}

TEST(OsMesaRenderer, SameFrameSamePixelsMovedBodyDifferentPixels) {
  auto r = make_osmesa_renderer();
  DrawFrame f;
  f.polygons.push_back(box(0.3, 0.2, 0.5, Role::dynamic_body));
  const Image a = render(*r, f), b = render(*r, f);
  EXPECT_EQ(a.px, b.px);
  f.polygons[0] = box(0.35, 0.2, 0.5, Role::dynamic_body);  // 3.2 px to the right
  EXPECT_NE(render(*r, f).px, a.px);
}

TEST(OsMesaRenderer, RefusesAMismatchedBuffer) {
  auto r = make_osmesa_renderer();
  std::vector<std::uint8_t> small(10);
  EXPECT_THROW(r->render(DrawFrame{}, fixed_camera(), kSize, small), std::invalid_argument);
}

TEST(OsMesaRenderer, SizeChangesBetweenFrames) {
  auto r = make_osmesa_renderer();
  for (ImageSize s : {ImageSize{64, 48}, ImageSize{1920, 1080}, ImageSize{17, 16}}) {
    std::vector<std::uint8_t> px(static_cast<std::size_t>(s.width) * s.height * 4);
    DrawFrame f;
    f.polygons.push_back(box(0.0, 0.0, 2.0, Role::dynamic_body));
    r->render(f, fixed_camera(), s, px);
    const std::uint8_t* centre = &px[(static_cast<std::size_t>(s.height / 2) * s.width + s.width / 2) * 4];
    EXPECT_EQ(centre[0], role_colours(Role::dynamic_body).fill.r) << s.width;
  }
}

}  // namespace
}  // namespace softtune::render
