#include "softtune/render/camera_path.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "softtune/render/tessellate.h"

namespace softtune::render {
namespace {

Bounds box_of(const std::vector<Vec2>& pts) {
  Bounds b;
  for (Vec2 p : pts) b.add(p);
  return b;
}

Bounds circle_box(const CircleShape& c) {
  Bounds b;
  b.add(Vec2{c.centre_m.x - c.radius_m, c.centre_m.y - c.radius_m});
  b.add(Vec2{c.centre_m.x + c.radius_m, c.centre_m.y + c.radius_m});
  return b;
}

Bounds intersect(const Bounds& a, const Bounds& b) {
  Bounds out;
  if (a.empty() || b.empty()) return out;
  const Vec2 lo{std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y)};
  const Vec2 hi{std::min(a.hi.x, b.hi.x), std::min(a.hi.y, b.hi.y)};
  if (lo.x > hi.x || lo.y > hi.y) return out;
  out.add(lo);
  out.add(hi);
  return out;
}

// Everything but static shapes, the ground and ghosts.
Bounds moving_bounds(const DrawFrame& f) {
  DrawFrame moving;
  const bool all = f.ghost_in_camera;
  std::copy_if(f.springs.begin(), f.springs.end(), std::back_inserter(moving.springs), [all](const SpringShape& s) { return all || !s.ghost; });
  std::copy_if(f.pins.begin(), f.pins.end(), std::back_inserter(moving.pins), [all](const PinShape& p) { return all || !p.ghost; });
  std::copy_if(f.anchors.begin(), f.anchors.end(), std::back_inserter(moving.anchors), [all](const AnchorDot& a) { return all || !a.ghost; });
  moving.targets = f.targets;
  moving.trails = f.trails;
  Bounds b = bounds_of(moving);
  for (const PolygonShape& p : f.polygons) {
    if (p.role != Role::static_body && (all || p.role != Role::ghost)) b.add(box_of(p.vertices_m));
  }
  for (const CircleShape& c : f.circles) {
    if (c.role != Role::static_body && (all || c.role != Role::ghost)) b.add(circle_box(c));
  }
  return b;
}

}  // namespace

Bounds action_bounds(const std::vector<DrawFrame>& frames) {
  Bounds moving;
  for (const DrawFrame& f : frames) moving.add(moving_bounds(f));
  if (moving.empty()) {
    Bounds all;
    for (const DrawFrame& f : frames) all.add(bounds_of(f));
    return all;
  }
  const double reach = kStaticReach * std::max(moving.hi.x - moving.lo.x, moving.hi.y - moving.lo.y);
  Bounds region;
  region.add(Vec2{moving.lo.x - reach, moving.lo.y - reach});
  region.add(Vec2{moving.hi.x + reach, moving.hi.y + reach});
  Bounds out = moving;
  // Static shapes do not move: the first frame has them all.
  const DrawFrame& f = frames.front();
  for (const PolygonShape& p : f.polygons) {
    if (p.role == Role::static_body) out.add(intersect(box_of(p.vertices_m), region));
  }
  for (const CircleShape& c : f.circles) {
    if (c.role == Role::static_body) out.add(intersect(circle_box(c), region));
  }
  if (f.ground_y_m && *f.ground_y_m >= region.lo.y && *f.ground_y_m <= region.hi.y) {
    out.add(Vec2{out.lo.x, *f.ground_y_m});
  }
  return out;
}

Bounds visible_below_band(const Camera& c, ImageSize size, double band) {
  const View v = make_view(c, size);
  Bounds b;
  b.add(Vec2{v.world_x(0.0), v.world_y(size.height)});
  b.add(Vec2{v.world_x(size.width), v.world_y(band * size.height)});
  return b;
}

std::vector<Camera> run_cameras(const Camera& fixed, const Follow& follow, const std::vector<DrawFrame>& frames,
                                ImageSize size) {
  const std::size_t n = frames.size();
  if (!fixed.auto_fit) return std::vector<Camera>(n, fixed);
  const double aspect = static_cast<double>(size.width) / size.height;
  const Bounds action = action_bounds(frames);
  const double band = n == 0 ? kCaptionBand : caption_band(size, static_cast<int>(frames.front().legend.size()));
  if (follow.bounds_m.size() != n || n == 0) return std::vector<Camera>(n, fit_camera(action, aspect, 0.06, 0.5, band));

  constexpr double kMargin = 0.06;  // of the view width, on every side of the followed box
  // Wide enough for the followed box in every frame, below the band and inside the margins.
  double width = std::max(follow.width_m, 0.5);
  for (const Bounds& b : follow.bounds_m) {
    if (b.empty()) continue;
    width = std::max({width, (b.hi.x - b.lo.x) / (1.0 - 2.0 * kMargin),
                      (b.hi.y - b.lo.y) * aspect / (1.0 - band - 2.0 * kMargin)});
  }
  const double view_h = width / aspect, scene_h = view_h * (1.0 - band);
  // Centre x of each frame's box, smoothed by a centred moving average so the camera glides.
  std::vector<double> cx(n), cy(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Bounds& b = follow.bounds_m[i].empty() ? action : follow.bounds_m[i];
    cx[i] = 0.5 * (b.lo.x + b.hi.x);
    cy[i] = 0.5 * (b.lo.y + b.hi.y);
  }
  const int half = static_cast<int>(n / 8);
  std::vector<Camera> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t lo = i >= static_cast<std::size_t>(half) ? i - half : 0, hi = std::min(n - 1, i + half);
    double sum = 0.0;
    for (std::size_t k = lo; k <= hi; ++k) sum += cx[k];
    double x = sum / static_cast<double>(hi - lo + 1);
    // Hold the action's height when it fits under the band; else follow the box's height.
    const double action_h = action.hi.y - action.lo.y;
    double y_mid = action_h <= scene_h * (1.0 - 2.0 * kMargin) ? 0.5 * (action.lo.y + action.hi.y) : cy[i];
    // The followed box stays whole inside the margins whatever the smoothing did.
    const Bounds& b = follow.bounds_m[i];
    if (!b.empty()) {
      const double mx = kMargin * width, my = kMargin * view_h;
      x = std::clamp(x, b.hi.x + mx - 0.5 * width, b.lo.x - mx + 0.5 * width);
      y_mid = std::clamp(y_mid, b.hi.y + my - 0.5 * scene_h, b.lo.y - my + 0.5 * scene_h);
    }
    Camera& c = out[i];
    c.auto_fit = false;
    c.width_m = width;
    // y_mid is the middle of the part under the band; the view's centre sits half a band higher.
    c.centre_m = {x, y_mid + 0.5 * band * view_h};
  }
  return out;
}

}  // namespace softtune::render
