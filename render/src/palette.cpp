#include "softtune/render/palette.h"

#include <algorithm>
#include <cmath>

namespace softtune::render {

RoleColours role_colours(Role role) {
  switch (role) {
    case Role::static_body: return {{150, 156, 166, 255}, {62, 68, 80, 255}};
    case Role::dynamic_body: return {{88, 142, 240, 255}, {24, 66, 160, 255}};
    case Role::probed: return {{250, 168, 40, 255}, {160, 92, 0, 255}};
    case Role::ghost: return {{200, 40, 130, 60}, {200, 40, 130, 230}};
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
