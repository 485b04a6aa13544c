#pragma once
// What a preview frame shows, in world space (metres, y up), independent of Box2D and of the scene types:
// filled and outlined bodies with a role, soft joints as springs, anchor dots, a ground line and labels.
// A scene snapshot (bodies: world polygon vertices or circle centre + radius; joints: world anchors, rest
// length, current length) maps onto it one to one.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace softtune::render {

/// A point or vector in metres, world frame (y up).
struct Vec2 {
  double x = 0.0;
  double y = 0.0;
};

/// What a body is to the viewer; the palette (palette.h) gives each role its colours.
enum class Role : std::uint8_t {
  static_body,   ///< does not move (walls, ground boxes, shelves)
  dynamic_body,  ///< simulated
  probed,        ///< the body whose motion the scene measures
  ghost,         ///< the exact analytic motion, drawn translucent beside the simulated one
};

/// A convex polygon given by its world vertices (either winding).
struct PolygonShape {
  std::vector<Vec2> vertices_m;
  Role role = Role::dynamic_body;
};

/// A circle; a radius line at `angle_rad` shows its rotation.
struct CircleShape {
  Vec2 centre_m;
  double radius_m = 0.5;
  double angle_rad = 0.0;
  Role role = Role::dynamic_body;
};

/// How a joint between two points looks.
enum class SpringStyle : std::uint8_t {
  coil,  ///< a soft distance or wheel joint: a zig-zag coloured by stretch
  rod,   ///< a rigid distance joint: a straight bar
  link,  ///< a mouse joint's soft link from its target to the body: a zig-zag in the link colour
};

/// A joint drawn from `a_m` to `b_m` (a zig-zag spring unless `style` says otherwise). A coil's colour
/// shows the stretch ratio current / rest: red when stretched, blue when compressed, grey at rest
/// (palette.h).
struct SpringShape {
  Vec2 a_m;
  Vec2 b_m;
  double rest_length_m = 1.0;                ///< m; 0 means "no rest length" (drawn neutral)
  std::optional<double> current_length_m;    ///< m; the anchor distance |b - a| when empty
  bool ghost = false;                        ///< the analytic spring: translucent
  SpringStyle style = SpringStyle::coil;
};

/// A rigid pin: a revolute joint (a ring) or a weld (a square), at its world anchor.
struct PinShape {
  Vec2 at_m;
  bool weld = false;
  bool ghost = false;
};

/// A mouse joint's target: a cross-hair the body is pulled to.
struct TargetShape {
  Vec2 at_m;
};

/// The recent path of a probed point, oldest first; drawn fading in from the oldest point.
struct Trail {
  std::vector<Vec2> points_m;
};

/// A joint anchor.
struct AnchorDot {
  Vec2 at_m;
  bool ghost = false;
};

/// A short text at a world position (its lower-left corner, or the middle of its bottom when
/// `centred`), UTF-8.
struct Label {
  std::string text;
  Vec2 at_m;
  bool centred = false;
};

/// One frame of a scene. Drawn back to front: grid, ground, trails, polygons and circles in order,
/// springs, pins, targets, anchors, labels, caption.
struct DrawFrame {
  std::vector<PolygonShape> polygons;
  std::vector<CircleShape> circles;
  std::vector<SpringShape> springs;
  std::vector<PinShape> pins;
  std::vector<TargetShape> targets;
  std::vector<Trail> trails;
  std::vector<AnchorDot> anchors;
  std::vector<Label> labels;
  std::optional<double> ground_y_m;  ///< m; a ground line with earth below when set
  std::string caption;               ///< title band, top-left: what and when (name, time, frame); UTF-8
  std::string settings;              ///< title band, top-right: mode, fps, substeps (the grid step is added)
  std::vector<std::string> legend;   ///< title band, under the caption: asked against measured, per joint
};

/// Where the camera looks. Fixed (from a preset) or fitted to the bounds of every frame of a run.
struct Camera {
  bool auto_fit = true;
  Vec2 centre_m;          ///< m, when fixed
  double width_m = 10.0;  ///< m visible across the image width, when fixed
};

/// An axis-aligned box in metres; empty until something is added.
struct Bounds {
  Vec2 lo{1.0, 1.0};
  Vec2 hi{-1.0, -1.0};
  bool empty() const { return lo.x > hi.x || lo.y > hi.y; }
  void add(Vec2 p);
  void add(const Bounds& b);
};

/// Bounds of every shape, spring, pin, target, trail and anchor of a frame, and the ground height
/// (labels excluded).
Bounds bounds_of(const DrawFrame& frame);

}  // namespace softtune::render
