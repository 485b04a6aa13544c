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
  wheel,         ///< a dynamic body a wheel joint carries (the vehicle's wheels)
  probed_second, ///< a second probed body (the bridge's load beside its deck): its own colour
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
  bool divergent = false;  ///< a blown-up method's last steps out of the view: the divergence colour
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

/// Debug marks, as the engines' own debug views draw them (Box2D's testbed: contact points and normals,
/// b2Draw::e_centerOfMassBit; MuJoCo's viewer: joint anchors and axes). Each layer is switchable in the
/// request (server/app/scene_frames.h, SceneLayers).
struct ContactMark {
  Vec2 at_m;
  Vec2 normal{0.0, 1.0};  ///< unit, world
};
/// A joint's two anchors (a on body_a, b on body_b): a ring at a, a dot at b, and the gap a -> b drawn
/// `magnify` times its length from a, so a pin's 1.6 cm stretch shows.
struct AnchorPair {
  Vec2 a_m;
  Vec2 b_m;
  double magnify = 1.0;
};
/// A tick across a spring where its rest length ends, measured from its first anchor.
struct RestMark {
  Vec2 at_m;
  Vec2 along{1.0, 0.0};  ///< unit, the spring's direction
};
/// A wheel joint's axis through the wheel: the line it may travel on, its rest point (zero translation)
/// and where the wheel centre is now (the travel, rest to now, drawn thick).
struct AxisMark {
  Vec2 from_m;
  Vec2 to_m;
  Vec2 rest_m;
  Vec2 now_m;
};
struct MassCentre {
  Vec2 at_m;
};

/// A small plot in a corner of the frame (below the title band): a probe over the run (`value` at `t_s`), the response
/// its fit gives and the one that was asked for (NaN where a curve has no value, e.g. before the fit's
/// window), and a cursor at the frame's own time. `title` names the probe, its unit and the two curves.
enum class Corner : std::uint8_t { bottom_right, bottom_left, top_right, top_left };

struct Inset {
  std::string title;
  Corner corner = Corner::bottom_right;  ///< where it goes (the frame pipeline picks the run's quietest)
  std::vector<double> t_s;     ///< s
  std::vector<double> value;   ///< probe units, one per t_s
  std::vector<double> fitted;  ///< one per t_s, or empty
  std::vector<double> asked;   ///< one per t_s, or empty
  double cursor_s = 0.0;       ///< s
};

/// One frame of a scene. Drawn back to front: grid, ground, trails, polygons and circles in order,
/// springs, pins, targets, anchors, the debug marks (rest marks, axes, anchor pairs, centres of mass,
/// contacts), inset, labels, caption.
struct DrawFrame {
  std::vector<PolygonShape> polygons;
  std::vector<CircleShape> circles;
  std::vector<SpringShape> springs;
  std::vector<PinShape> pins;
  std::vector<TargetShape> targets;
  std::vector<Trail> trails;
  std::vector<AnchorDot> anchors;
  std::vector<Label> labels;
  std::vector<ContactMark> contacts;
  std::vector<AnchorPair> anchor_pairs;
  std::vector<RestMark> rest_marks;
  std::vector<AxisMark> axes;
  std::vector<MassCentre> mass_centres;
  std::optional<double> ground_y_m;  ///< m; a ground line with earth below when set
  std::string caption;               ///< title band, top-left: what and when (name, time, frame); UTF-8
  std::string settings;              ///< title band, top-right: mode, fps, substeps (the grid step is added)
  std::vector<std::string> legend;   ///< title band, under the caption: asked against measured, per joint
  std::optional<Inset> inset;        ///< the probe over time, in a corner
  /// The ghost is part of the picture, not a second run: the oscillator's exact analytic lane on its
  /// shelf. Then the camera frames it too (action_bounds); an A/B ghost never does.
  bool ghost_in_camera = false;
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

/// Bounds of every shape, spring, pin, target, trail (but a divergent one) and anchor of a frame, and
/// the ground height (labels and the other debug marks excluded).
Bounds bounds_of(const DrawFrame& frame);

}  // namespace softtune::render
