#include "softtune/render/palette.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace softtune::render {
namespace {

TEST(SpringColour, NeutralAtRestFullAtTheStretchLimits) {
  EXPECT_EQ(spring_colour(2.0, 2.0), palette::kSpringNeutral);
  EXPECT_EQ(spring_colour(2.0 * (1.0 + palette::kFullStretch), 2.0), palette::kSpringStretched);
  EXPECT_EQ(spring_colour(5.0, 2.0), palette::kSpringStretched);
  EXPECT_EQ(spring_colour(2.0 * (1.0 - palette::kFullStretch), 2.0), palette::kSpringCompressed);
  EXPECT_EQ(spring_colour(0.0, 2.0), palette::kSpringCompressed);
}

TEST(SpringColour, HalfwayIsTheMidpointBlend) {
  const Rgba c = spring_colour(1.0 + 0.5 * palette::kFullStretch, 1.0);
  EXPECT_NEAR(c.r, 0.5 * (palette::kSpringNeutral.r + palette::kSpringStretched.r), 1.0);
  EXPECT_NEAR(c.b, 0.5 * (palette::kSpringNeutral.b + palette::kSpringStretched.b), 1.0);
}

TEST(SpringColour, ZeroRestLengthOrNonFiniteIsNeutral) {
  EXPECT_EQ(spring_colour(1.0, 0.0), palette::kSpringNeutral);
  EXPECT_EQ(spring_colour(std::numeric_limits<double>::quiet_NaN(), 1.0), palette::kSpringNeutral);
}

TEST(RoleColours, RolesAreDistinguishableAndGhostIsTranslucent) {
  EXPECT_NE(role_colours(Role::static_body).fill, role_colours(Role::dynamic_body).fill);
  EXPECT_NE(role_colours(Role::dynamic_body).fill, role_colours(Role::probed).fill);
  EXPECT_EQ(role_colours(Role::dynamic_body).fill.a, 255);
  EXPECT_LT(role_colours(Role::ghost).fill.a, 128);
}

// CIE L*a*b* (D65) of an sRGB colour (IEC 61966-2-1 transfer curve, the sRGB -> XYZ matrix).
struct Lab {
  double l, a, b;
};
Lab lab_of(Rgba c) {
  const auto lin = [](std::uint8_t u) {
    const double x = u / 255.0;
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
  };
  const double r = lin(c.r), g = lin(c.g), b = lin(c.b);
  const double x = (0.4124564 * r + 0.3575761 * g + 0.1804375 * b) / 0.95047;
  const double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
  const double z = (0.0193339 * r + 0.1191920 * g + 0.9503041 * b) / 1.08883;
  const auto f = [](double t) { return t > std::pow(6.0 / 29.0, 3) ? std::cbrt(t) : t / (3.0 * std::pow(6.0 / 29.0, 2)) + 4.0 / 29.0; };
  return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

// CIEDE2000 colour difference, as Sharma, Wu and Dalal give it ("The CIEDE2000 Color-Difference Formula:
// Implementation Notes, Supplementary Test Data, and Mathematical Observations", 2005, equations 1-22).
double ciede2000(Lab p, Lab q) {
  const double deg = std::numbers::pi / 180.0;
  const double c1 = std::hypot(p.a, p.b), c2 = std::hypot(q.a, q.b), cb = 0.5 * (c1 + c2);
  const double g = 0.5 * (1.0 - std::sqrt(std::pow(cb, 7) / (std::pow(cb, 7) + std::pow(25.0, 7))));
  const double a1 = (1.0 + g) * p.a, a2 = (1.0 + g) * q.a;
  const double c1p = std::hypot(a1, p.b), c2p = std::hypot(a2, q.b);
  const auto hue = [deg](double b, double a) {
    if (a == 0.0 && b == 0.0) return 0.0;
    double h = std::atan2(b, a) / deg;
    return h < 0.0 ? h + 360.0 : h;
  };
  const double h1 = hue(p.b, a1), h2 = hue(q.b, a2);
  const double dl = q.l - p.l, dc = c2p - c1p;
  double dh = 0.0;
  if (c1p * c2p != 0.0) {
    dh = h2 - h1;
    if (dh > 180.0) dh -= 360.0;
    if (dh < -180.0) dh += 360.0;
  }
  const double dH = 2.0 * std::sqrt(c1p * c2p) * std::sin(0.5 * dh * deg);
  const double lb = 0.5 * (p.l + q.l), cbp = 0.5 * (c1p + c2p);
  double hb = h1 + h2;
  if (c1p * c2p != 0.0) {
    hb = std::abs(h1 - h2) <= 180.0 ? 0.5 * (h1 + h2) : (h1 + h2 < 360.0 ? 0.5 * (h1 + h2 + 360.0) : 0.5 * (h1 + h2 - 360.0));
  }
  const double t = 1.0 - 0.17 * std::cos((hb - 30.0) * deg) + 0.24 * std::cos(2.0 * hb * deg) +
                   0.32 * std::cos((3.0 * hb + 6.0) * deg) - 0.20 * std::cos((4.0 * hb - 63.0) * deg);
  const double dtheta = 30.0 * std::exp(-std::pow((hb - 275.0) / 25.0, 2));
  const double rc = 2.0 * std::sqrt(std::pow(cbp, 7) / (std::pow(cbp, 7) + std::pow(25.0, 7)));
  const double sl = 1.0 + 0.015 * std::pow(lb - 50.0, 2) / std::sqrt(20.0 + std::pow(lb - 50.0, 2));
  const double sc = 1.0 + 0.045 * cbp, sh = 1.0 + 0.015 * cbp * t;
  const double rt = -std::sin(2.0 * dtheta * deg) * rc;
  return std::sqrt(std::pow(dl / sl, 2) + std::pow(dc / sc, 2) + std::pow(dH / sh, 2) + rt * (dc / sc) * (dH / sh));
}

TEST(ColourDifference, Ciede2000MatchesSharmasTestData) {
  // Sharma, Wu, Dalal 2005, Table 1, pairs 1, 2, 7, 17, 25 and 6.
  EXPECT_NEAR(ciede2000({50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}), 2.0425, 1e-4);
  EXPECT_NEAR(ciede2000({50.0, 3.1571, -77.2803}, {50.0, 0.0, -82.7485}), 2.8615, 1e-4);
  EXPECT_NEAR(ciede2000({50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}), 2.3669, 1e-4);
  EXPECT_NEAR(ciede2000({50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}), 27.1492, 1e-4);
  EXPECT_NEAR(ciede2000({60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}), 1.2644, 1e-4);
  EXPECT_NEAR(ciede2000({50.0, 2.5, 0.0}, {50.0, 0.0, -2.5}), 4.3065, 1e-4);
  // sRGB red is L* 53.24, a* 80.09, b* 67.20.
  const Lab red = lab_of({255, 0, 0, 255});
  EXPECT_NEAR(red.l, 53.24, 0.01);
  EXPECT_NEAR(red.a, 80.09, 0.01);
  EXPECT_NEAR(red.b, 67.20, 0.01);
}

Rgba over_background(Rgba c) {
  const auto mix = [&](std::uint8_t top, std::uint8_t below) {
    return static_cast<std::uint8_t>(std::lround((top * c.a + below * (255 - c.a)) / 255.0));
  };
  return {mix(c.r, palette::kBackground.r), mix(c.g, palette::kBackground.g), mix(c.b, palette::kBackground.b), 255};
}

TEST(Palette, EveryBodyClassSpringStateAndTrailSeparates) {
  // What the issue found mixed up: compressed springs blue on blue wheels, wheels and crates one blue, the
  // load and plank_5 both orange, trails orange on orange. Every pair of these, as drawn over the
  // background, at least 15 apart in CIEDE2000 (2.3 is a just noticeable difference; 15 tells apart at a
  // glance).
  const std::vector<std::pair<std::string, Rgba>> colours = {
      {"static body", role_colours(Role::static_body).fill},
      {"dynamic body", role_colours(Role::dynamic_body).fill},
      {"wheel", role_colours(Role::wheel).fill},
      {"probed body", role_colours(Role::probed).fill},
      {"second probed body", role_colours(Role::probed_second).fill},
      {"ghost", role_colours(Role::ghost).fill},
      {"spring at rest", palette::kSpringNeutral},
      {"spring stretched", palette::kSpringStretched},
      {"spring compressed", palette::kSpringCompressed},
      {"rod", palette::kRod},
      {"mouse link", palette::kMouseLink},
      {"trail", palette::kTrail},
      {"divergence", palette::kDivergence},
      {"background", palette::kBackground},
  };
  for (std::size_t i = 0; i < colours.size(); ++i) {
    for (std::size_t j = i + 1; j < colours.size(); ++j) {
      const double d = ciede2000(lab_of(over_background(colours[i].second)), lab_of(over_background(colours[j].second)));
      EXPECT_GE(d, 15.0) << colours[i].first << " against " << colours[j].first;
    }
  }
}

}  // namespace
}  // namespace softtune::render
