#include "softtune/render/palette.h"

#include <algorithm>
#include <cmath>

namespace softtune::render {

RoleColours role_colours(Role role) {
  switch (role) {
    // Chosen so that every body class, spring state and trail is at least 15 apart in CIEDE2000 over the
    // background (tests/render/palette_test.cpp): compressed springs no longer blue on blue bodies,
    // wheels apart from crates, a second probed body apart from the first, trails apart from both.
    case Role::static_body: return {{140, 140, 140, 255}, {62, 68, 80, 255}};
    case Role::dynamic_body: return {{120, 165, 245, 255}, {24, 66, 160, 255}};
    case Role::probed: return {{250, 168, 40, 255}, {160, 92, 0, 255}};
    case Role::ghost: return {{200, 40, 130, 60}, {200, 40, 130, 230}};
    case Role::wheel: return {{110, 200, 220, 255}, {20, 100, 120, 255}};
    case Role::probed_second: return {{255, 222, 80, 255}, {170, 130, 0, 255}};
  }
  return {{0, 0, 0, 255}, {0, 0, 0, 255}};
}

namespace {

Rgba mix(Rgba a, Rgba b, double t) {
  auto lerp = [t](std::uint8_t x, std::uint8_t y) {
    return static_cast<std::uint8_t>(std::lround(x + (y - x) * t));
  };
  return {lerp(a.r, b.r), lerp(a.g, b.g), lerp(a.b, b.b), lerp(a.a, b.a)};
}

}  // namespace

Rgba spring_colour(double current_length_m, double rest_length_m) {
  if (!(rest_length_m > 0.0) || !std::isfinite(current_length_m)) return palette::kSpringNeutral;
  const double strain = current_length_m / rest_length_m - 1.0;
  const double t = std::min(1.0, std::abs(strain) / palette::kFullStretch);
  return mix(palette::kSpringNeutral, strain > 0.0 ? palette::kSpringStretched : palette::kSpringCompressed, t);
}

}  // namespace softtune::render
