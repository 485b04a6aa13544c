#pragma once
// The colours of a preview frame (8-bit sRGB, straight alpha). Tests read them back from pixels.

#include <cstdint>

#include "softtune/render/draw_model.h"

namespace softtune::render {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Rgba&) const = default;
};

namespace palette {
inline constexpr Rgba kBackground{246, 246, 242, 255};
inline constexpr Rgba kGrid{40, 50, 70, 28};          ///< faint: lines every grid step
inline constexpr Rgba kEarth{224, 219, 207, 255};     ///< below the ground line
inline constexpr Rgba kGroundLine{70, 66, 58, 255};
inline constexpr Rgba kText{28, 30, 36, 255};
inline constexpr Rgba kBand{252, 252, 249, 235};      ///< the title band's panel
inline constexpr Rgba kBandRule{40, 50, 70, 60};      ///< the line under the band
inline constexpr Rgba kAnchor{20, 22, 28, 255};
inline constexpr Rgba kSpringNeutral{80, 84, 92, 255};
inline constexpr Rgba kSpringStretched{214, 48, 39, 255};   ///< at stretch ratio >= 1 + kFullStretch
inline constexpr Rgba kSpringCompressed{33, 102, 222, 255};  ///< at stretch ratio <= 1 - kFullStretch
inline constexpr double kFullStretch = 0.3;                  ///< |ratio - 1| that gives the full colour
inline constexpr std::uint8_t kGhostAlpha = 110;             ///< springs and anchors of the ghost
inline constexpr Rgba kRod{62, 68, 80, 255};                 ///< a rigid distance joint
inline constexpr Rgba kMouseLink{142, 58, 196, 255};         ///< a mouse joint's link and target
inline constexpr Rgba kPinFace{246, 246, 242, 255};          ///< the face inside a pin's ring
inline constexpr Rgba kTrail{250, 140, 0, 200};              ///< a probed point's path (newest end)
}  // namespace palette

/// Fill and outline of a role.
struct RoleColours {
  Rgba fill;
  Rgba outline;
};
RoleColours role_colours(Role role);

/// Spring colour at stretch ratio current / rest: a linear blend from neutral to stretched (ratio above
/// 1) or compressed (below 1), full at |ratio - 1| = kFullStretch. A zero rest length is neutral.
Rgba spring_colour(double current_length_m, double rest_length_m);

}  // namespace softtune::render
