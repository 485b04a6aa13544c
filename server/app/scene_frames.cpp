#include "app/scene_frames.h"

#include <cstdio>

namespace softtune::app {

namespace {

render::Vec2 vec(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }

render::Role role_of(const scene::BodySnapshot& b) {
  if (b.is_static) return render::Role::static_body;
  return b.probed ? render::Role::probed : render::Role::dynamic_body;
}

// Joints that act as springs in the picture; weld and revolute joints show only their anchors.
bool drawn_as_spring(const scene::JointSnapshot& j) {
  return j.kind == "distance" || j.kind == "wheel" || j.kind == "mouse";
}

}  // namespace

render::DrawFrame scene_frame(const scene::Scene& scene, const scene::Snapshot& snapshot, int index, int count) {
  render::DrawFrame frame;
  for (const scene::BodySnapshot& b : snapshot.bodies) {
    if (b.is_circle) {
      frame.circles.push_back({vec(b.center), b.radius, b.angle, role_of(b)});
      continue;
    }
    render::PolygonShape polygon;
    polygon.role = role_of(b);
    for (const Eigen::Vector2d& v : b.vertices) polygon.vertices_m.push_back(vec(v));
    frame.polygons.push_back(std::move(polygon));
  }
  for (const scene::JointSnapshot& j : snapshot.joints) {
    if (drawn_as_spring(j)) {
      render::SpringShape spring;
      spring.a_m = vec(j.anchor_a);
      spring.b_m = vec(j.anchor_b);
      // A mouse or wheel joint rests at zero length; 0 draws the spring neutral (palette.h).
      spring.rest_length_m = j.rest_length.value_or(0.0);
      spring.current_length_m = j.current_length;
      frame.springs.push_back(spring);
    }
    frame.anchors.push_back({vec(j.anchor_a)});
    frame.anchors.push_back({vec(j.anchor_b)});
  }
  char caption[160];
  std::snprintf(caption, sizeof caption, "%s  t = %.2f s  frame %d/%d", scene.name.c_str(), snapshot.time_s,
                index + 1, count);
  frame.caption = caption;
  return frame;
}

render::FrameSet scene_frames(const scene::Scene& scene, const std::vector<scene::Snapshot>& snapshots) {
  render::FrameSet set;
  set.camera.auto_fit = false;
  set.camera.centre_m = vec(scene.camera.center);
  set.camera.width_m = scene.camera.width_m;
  const int count = static_cast<int>(snapshots.size());
  for (int i = 0; i < count; ++i) set.frames.push_back(scene_frame(scene, snapshots[i], i, count));
  return set;
}

}  // namespace softtune::app
