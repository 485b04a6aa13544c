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
inline constexpr Rgba kSpringCompressed{20, 70, 200, 255};  ///< at stretch ratio <= 1 - kFullStretch
inline constexpr double kFullStretch = 0.3;                  ///< |ratio - 1| that gives the full colour
inline constexpr std::uint8_t kGhostAlpha = 110;             ///< springs and anchors of the ghost
inline constexpr Rgba kRod{120, 84, 50, 255};                ///< a rigid distance joint
inline constexpr Rgba kMouseLink{150, 50, 200, 255};         ///< a mouse joint's link and target
inline constexpr Rgba kPinFace{246, 246, 242, 255};          ///< the face inside a pin's ring
inline constexpr Rgba kTrail{0, 130, 60, 220};               ///< a probed point's path (newest end)
inline constexpr Rgba kDivergence{160, 0, 90, 235};          ///< a blown-up method's last steps (Trail::divergent)
// Debug layers, as Box2D's testbed and MuJoCo's viewer draw them: dark marks with a light halo, so they
// read over any body.
inline constexpr Rgba kContact{20, 22, 28, 255};             ///< contact points and their normals
inline constexpr Rgba kHalo{255, 255, 255, 200};             ///< under contact, anchor and centre-of-mass marks
inline constexpr Rgba kAnchorGap{214, 48, 39, 255};          ///< a pin's anchor gap, magnified
inline constexpr Rgba kRestMark{20, 22, 28, 255};            ///< rest-length ticks, wheel axes and travel
inline constexpr Rgba kInsetPanel{252, 252, 249, 225};       ///< the probe inset's panel
inline constexpr Rgba kInsetProbe{28, 30, 36, 255};          ///< the probe's samples
inline constexpr Rgba kInsetFit{0, 150, 110, 255};           ///< its fitted response
inline constexpr Rgba kInsetAsked{200, 40, 130, 200};        ///< the asked response (the ghost's pink)
inline constexpr Rgba kInsetCursor{214, 48, 39, 255};        ///< the frame's time
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
