#include "app/scene_frames.h"

#include "app/probe_inset.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "softtune/scene/box2d_backend.h"

namespace softtune::app {

namespace {

render::Vec2 vec(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }

int body_index(const scene::Scene& scene, const std::string& id) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

// A direction fixed in body i at the start, turned with the body to this snapshot.
Eigen::Vector2d turned(const scene::Scene& scene, const scene::Snapshot& snap, int i, const Eigen::Vector2d& d) {
  if (i < 0 || i >= static_cast<int>(snap.bodies.size())) return d;
  return Eigen::Rotation2Dd(snap.bodies[i].angle - scene.bodies[i].angle) * d;
}

// A wheel joint's anchors coincide at rest (Box2D puts both at the wheel centre), so its spring is drawn
// the way a suspension looks: from a mount on body_a, up the suspension axis by the distance from the
// anchor to body_a's centre line, down to the wheel. Box2D's translation is dot(pB - pA, axis), so the
// drawn length is mount - translation and rests at `mount`.
render::SpringShape wheel_spring(const scene::Scene& scene, const scene::Snapshot& snap, std::size_t j) {
  const scene::JointSettings& settings = scene.joints[j];
  const scene::JointSnapshot& js = snap.joints[j];
  const int a = body_index(scene, settings.body_a);
  const Eigen::Vector2d axis0 = settings.axis.normalized();
  // b2WheelJointDef::Initialize puts both anchors at anchor_b (box2d_scene.cpp).
  double mount = a >= 0 ? (scene.bodies[a].position - settings.anchor_b).dot(axis0) : 0.0;
  if (!(mount > 0.05)) mount = 0.5;  // m: an anchor at or above the centre line still shows a spring
  const Eigen::Vector2d top = js.anchor_a + turned(scene, snap, a, axis0) * mount;
  render::SpringShape s;
  s.a_m = vec(top);
  s.b_m = vec(js.anchor_b);
  s.rest_length_m = mount;
  s.current_length_m = (js.anchor_b - top).norm();
  return s;
}

// The debug marks of joint j (scene_frames.h, SceneLayers).
void add_joint_marks(render::DrawFrame& frame, const scene::Scene& scene, const scene::Snapshot& snap, std::size_t j,
                     const SceneLayers& layers) {
  const scene::JointSettings& settings = scene.joints[j];
  const scene::JointSnapshot& js = snap.joints[j];
  const auto rest_mark = [&frame](const render::SpringShape& s) {
    const Eigen::Vector2d a(s.a_m.x, s.a_m.y), b(s.b_m.x, s.b_m.y);
    if ((b - a).norm() < 1e-9 || !(s.rest_length_m > 0.0)) return;
    const Eigen::Vector2d along = (b - a).normalized();
    frame.rest_marks.push_back({vec(a + along * s.rest_length_m), vec(along)});
  };
  switch (settings.kind) {
    case scene::JointKind::distance:
      if (layers.rest_marks && settings.tuning && js.rest_length) {
        render::SpringShape s;
        s.a_m = vec(js.anchor_a);
        s.b_m = vec(js.anchor_b);
        s.rest_length_m = *js.rest_length;
        rest_mark(s);
      }
      return;
    case scene::JointKind::wheel: {
      const render::SpringShape s = wheel_spring(scene, snap, j);
      if (layers.rest_marks) rest_mark(s);
      if (layers.wheel_axes) {
        // Box2D's translation is dot(pB - pA, axis): zero with the wheel centre at anchor A.
        const Eigen::Vector2d top(s.a_m.x, s.a_m.y);
        const Eigen::Vector2d rest = js.anchor_a;
        frame.axes.push_back({vec(top), vec(rest + (rest - top) * 0.5), vec(rest), vec(js.anchor_b)});
      }
      return;
    }
    case scene::JointKind::weld:
    case scene::JointKind::revolute:
      if (layers.anchors) frame.anchor_pairs.push_back({vec(js.anchor_a), vec(js.anchor_b), kAnchorGapMagnify});
      return;
    case scene::JointKind::mouse: return;
  }
}

void add_joint(render::DrawFrame& frame, const scene::Scene& scene, const scene::Snapshot& snap, std::size_t j) {
  const scene::JointSettings& settings = scene.joints[j];
  const scene::JointSnapshot& js = snap.joints[j];
  switch (settings.kind) {
    case scene::JointKind::distance: {
      render::SpringShape s;
      s.a_m = vec(js.anchor_a);
      s.b_m = vec(js.anchor_b);
      s.rest_length_m = js.rest_length.value_or(0.0);
      s.current_length_m = js.current_length;
      s.style = settings.tuning || settings.typed ? render::SpringStyle::coil : render::SpringStyle::rod;
      frame.springs.push_back(s);
      frame.anchors.push_back({vec(js.anchor_a)});
      frame.anchors.push_back({vec(js.anchor_b)});
      return;
    }
    case scene::JointKind::wheel: {
      const render::SpringShape s = wheel_spring(scene, snap, j);
      frame.springs.push_back(s);
      frame.anchors.push_back({s.a_m});
      frame.anchors.push_back({s.b_m});
      return;
    }
    case scene::JointKind::mouse: {
      // Box2D's mouse joint reports its target as anchor A.
      render::SpringShape s;
      s.a_m = vec(js.anchor_a);
      s.b_m = vec(js.anchor_b);
      s.rest_length_m = 0.0;
      s.current_length_m = js.current_length;
      s.style = render::SpringStyle::link;
      frame.springs.push_back(s);
      frame.targets.push_back({vec(js.anchor_a)});
      frame.anchors.push_back({vec(js.anchor_b)});
      return;
    }
    case scene::JointKind::weld:
    case scene::JointKind::revolute:
      frame.pins.push_back({vec(js.anchor_b), settings.kind == scene::JointKind::weld});
      return;
  }
}

// The point a probe follows, as (body index, -1) or (-1, joint index); (-1, -1) for none.
std::pair<int, int> probed_point(const scene::Scene& scene, const scene::ProbeSettings& p) {
  switch (p.kind) {
    case scene::ProbeKind::displacement:
    case scene::ProbeKind::angle: return {body_index(scene, p.body), -1};
    case scene::ProbeKind::joint_length:
    case scene::ProbeKind::joint_angle:
      for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        if (scene.joints[j].id == p.joint) return {-1, static_cast<int>(j)};
      }
      return {-1, -1};
    default: return {-1, -1};
  }
}

Eigen::Vector2d point_at(const scene::Snapshot& s, std::pair<int, int> point) {
  return point.first >= 0 ? s.bodies[point.first].center : s.joints[point.second].anchor_b;
}

const char* method_label(Method m) {
  switch (m) {
    case Method::explicit_euler: return "explicit Euler";
    case Method::semi_implicit_euler: return "semi-implicit";
    default: return "soft (core)";
  }
}

}  // namespace

int left_frame_at(const scene::OscillatorRun& run, double limit_m) {
  for (std::size_t f = 0; f < run.x.size(); ++f) {
    if (!std::isfinite(run.x[f]) || std::abs(run.x[f]) > limit_m) return static_cast<int>(f);
  }
  return run.diverged_at_s ? static_cast<int>(run.x.size()) : -1;
}

void add_oscillators(render::DrawFrame& frame, const scene::Scene& scene, const scene::SceneResult& result,
                     const std::vector<scene::Snapshot>& snapshots, int index) {
  const scene::Snapshot& snap = snapshots[index];
  int column = 0;
  for (std::size_t k = 0; k < scene.oscillators.size() && k < result.oscillators.size(); ++k) {
    const scene::OscillatorSettings& osc = scene.oscillators[k];
    int j = -1;
    for (std::size_t i = 0; i < scene.joints.size(); ++i) {
      if (scene.joints[i].id == osc.joint && scene.joints[i].kind == scene::JointKind::distance) j = static_cast<int>(i);
    }
    if (j < 0 || j >= static_cast<int>(snap.joints.size())) continue;
    const scene::JointSettings& joint = scene.joints[j];
    const int b = body_index(scene, joint.body_b);
    if (b < 0) continue;
    const Eigen::Vector2d along = (joint.anchor_b - joint.anchor_a).normalized();
    const double rest = joint.length.value_or((joint.anchor_b - joint.anchor_a).norm());
    // Columns alternate right and left of the joint, 0.7 rest lengths apart (at least the body's width).
    const scene::BodySnapshot& body = snap.bodies[b];
    double body_width = 0.0;
    for (const Eigen::Vector2d& v : body.vertices) body_width = std::max(body_width, 2.0 * std::abs((v - body.center).dot(Eigen::Vector2d(-along.y(), along.x()))));
    const double gap = std::max(rest, 1.6 * body_width + 0.1);
    if (++column == 1) frame.labels.push_back({"Box2D (soft)", vec(joint.anchor_a - along * (0.12 * rest)), true});
    const double side = (column % 2 == 1 ? 1.0 : -1.0) * gap * ((column + 1) / 2);
    const Eigen::Vector2d offset = Eigen::Vector2d(-along.y(), along.x()) * side;
    const Eigen::Vector2d top = joint.anchor_a + offset;
    const scene::OscillatorRun& run = result.oscillators[k];
    const double limit = kOscillatorLimit * rest;
    const int left = left_frame_at(run, limit);
    char label[64];
    const render::Vec2 label_at = vec(top - along * (0.12 * rest));
    frame.labels.push_back({method_label(osc.method), label_at, true});
    if (left >= 0 && snap.frame >= left) {
      // Drawn as divergence: where the block went over its last game frames, out past the limit (the
      // last point pulled in to 2 rest lengths: it may be 1e9 m out), and when it left, on the preview's
      // own frame numbering.
      render::Trail trail;
      trail.divergent = true;
      for (int f = std::max(0, left - kDivergenceTrailFrames); f <= left && f < static_cast<int>(run.x.size()); ++f) {
        const double x = std::isfinite(run.x[f]) ? std::clamp(run.x[f], -2.0 * rest, 2.0 * rest) : 2.0 * rest;
        trail.points_m.push_back(vec(top + along * (rest + x)));
      }
      if (trail.points_m.size() >= 2) frame.trails.push_back(std::move(trail));
      int shown = index;
      while (shown > 0 && snapshots[shown - 1].frame >= left) --shown;
      std::snprintf(label, sizeof label, "left the view\nat t = %.2f s (frame %d)", left / scene.world.fps, shown);
      frame.labels.push_back({label, vec(top + along * rest), true});
      frame.anchors.push_back({vec(top)});
      continue;
    }
    const double x = snap.frame < static_cast<int>(run.x.size()) ? run.x[snap.frame] : 0.0;
    const Eigen::Vector2d centre = top + along * (rest + x);
    render::PolygonShape block;
    block.role = render::Role::dynamic_body;
    for (const Eigen::Vector2d& v : body.vertices) block.vertices_m.push_back(vec(v - body.center + centre));
    frame.polygons.push_back(std::move(block));
    render::SpringShape spring;
    spring.a_m = vec(top);
    spring.b_m = vec(centre);
    spring.rest_length_m = rest;
    spring.current_length_m = rest + x;
    frame.springs.push_back(spring);
    frame.anchors.push_back({vec(top)});
    frame.anchors.push_back({vec(centre)});
  }
}

SceneLayers default_layers(const scene::Scene& scene) {
  SceneLayers l;
  int dynamic = 0;
  for (const scene::BodySettings& b : scene.bodies) dynamic += !b.is_static;
  l.contacts = dynamic >= 1 && scene.bodies.size() >= 2;
  l.anchors = l.rest_marks = l.wheel_axes = l.mass_centres = false;
  for (const scene::JointSettings& j : scene.joints) {
    l.anchors = l.anchors || j.kind == scene::JointKind::revolute || j.kind == scene::JointKind::weld;
    l.rest_marks = l.rest_marks || j.kind == scene::JointKind::wheel || (j.kind == scene::JointKind::distance && j.tuning);
    l.wheel_axes = l.wheel_axes || j.kind == scene::JointKind::wheel;
  }
  for (const scene::ProbeSettings& p : scene.probes) l.mass_centres = l.mass_centres || p.kind == scene::ProbeKind::angle;
  l.inset = !scene.probes.empty();
  return l;
}

std::vector<render::Role> body_roles(const scene::Scene& scene) {
  std::vector<render::Role> roles(scene.bodies.size(), render::Role::dynamic_body);
  for (const scene::JointSettings& j : scene.joints) {
    const int b = body_index(scene, j.body_b);
    if (j.kind == scene::JointKind::wheel && b >= 0) roles[b] = render::Role::wheel;
  }
  int probed = 0;
  for (const scene::ProbeSettings& p : scene.probes) {
    const int b = p.body.empty() ? -1 : body_index(scene, p.body);
    if (b < 0 || roles[b] == render::Role::probed || roles[b] == render::Role::probed_second) continue;
    if (p.kind != scene::ProbeKind::displacement && p.kind != scene::ProbeKind::angle) continue;
    roles[b] = probed++ == 0 ? render::Role::probed : render::Role::probed_second;
  }
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (scene.bodies[i].is_static) roles[i] = render::Role::static_body;
  }
  return roles;
}

std::vector<std::pair<int, int>> trailed_points(const scene::Scene& scene) {
  std::set<std::pair<int, int>> seen;
  std::vector<std::pair<int, int>> out;
  for (const scene::ProbeSettings& p : scene.probes) {
    const auto point = probed_point(scene, p);
    if ((point.first >= 0 || point.second >= 0) && seen.insert(point).second) out.push_back(point);
  }
  return out;
}

render::DrawFrame scene_frame(const scene::Scene& scene, const std::vector<scene::Snapshot>& snapshots, int index,
                              const SceneLayers& layers) {
  const scene::Snapshot& snapshot = snapshots[index];
  const int count = static_cast<int>(snapshots.size());
  const std::vector<render::Role> roles = body_roles(scene);
  // Centres of mass of what the tuning moves: probed bodies and bodies a joint holds (not a crate stack).
  std::vector<bool> jointed(scene.bodies.size(), false);
  for (const scene::JointSettings& j : scene.joints) {
    for (const std::string& id : {j.body_a, j.body_b}) {
      if (const int k = body_index(scene, id); k >= 0) jointed[k] = true;
    }
  }
  for (std::size_t i = 0; i < roles.size(); ++i) {
    if (roles[i] == render::Role::probed || roles[i] == render::Role::probed_second) jointed[i] = true;
  }
  render::DrawFrame frame;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    const scene::BodySnapshot& b = snapshot.bodies[i];
    const render::Role role = i < roles.size() ? roles[i] : render::Role::dynamic_body;
    if (layers.mass_centres && !b.is_static && jointed[i]) frame.mass_centres.push_back({vec(b.mass_centre)});
    if (b.is_circle) {
      frame.circles.push_back({vec(b.center), b.radius, b.angle, role});
      continue;
    }
    render::PolygonShape polygon;
    polygon.role = role;
    for (const Eigen::Vector2d& v : b.vertices) polygon.vertices_m.push_back(vec(v));
    frame.polygons.push_back(std::move(polygon));
  }
  for (std::size_t j = 0; j < snapshot.joints.size() && j < scene.joints.size(); ++j) {
    add_joint(frame, scene, snapshot, j);
    add_joint_marks(frame, scene, snapshot, j, layers);
  }
  if (layers.contacts) {
    for (const scene::ContactSnapshot& c : snapshot.contacts) frame.contacts.push_back({vec(c.point), vec(c.normal)});
  }
  for (const auto& point : trailed_points(scene)) {
    render::Trail trail;
    for (int k = index; k >= 0 && snapshot.time_s - snapshots[k].time_s <= kTrailSeconds + 1e-9; --k) {
      trail.points_m.insert(trail.points_m.begin(), vec(point_at(snapshots[k], point)));
    }
    if (trail.points_m.size() >= 2) frame.trails.push_back(std::move(trail));
  }
  char caption[160];
  std::snprintf(caption, sizeof caption, "%s  \u00b7  t = %.2f s  \u00b7  frame %d/%d", scene.name.c_str(), snapshot.time_s,
                index, count - 1);
  frame.caption = caption;
  frame.settings = scene_settings(scene);
  if (layers.anchors && !frame.anchor_pairs.empty()) {
    char gap[48];
    std::snprintf(gap, sizeof gap, "  \u00b7  pin gaps \u00d7%g", kAnchorGapMagnify);
    frame.settings += gap;
  }
  return frame;
}

void add_ghost(render::DrawFrame& frame, const scene::Scene& ghost, const scene::Snapshot& snap) {
  for (const scene::BodySnapshot& b : snap.bodies) {
    if (b.is_static) continue;
    if (b.is_circle) {
      frame.circles.push_back({vec(b.center), b.radius, b.angle, render::Role::ghost});
      continue;
    }
    render::PolygonShape polygon;
    polygon.role = render::Role::ghost;
    for (const Eigen::Vector2d& v : b.vertices) polygon.vertices_m.push_back(vec(v));
    frame.polygons.push_back(std::move(polygon));
  }
  for (std::size_t j = 0; j < snap.joints.size() && j < ghost.joints.size(); ++j) {
    if (!ghost.joints[j].tuning && !ghost.joints[j].typed) continue;
    render::DrawFrame joint;
    add_joint(joint, ghost, snap, j);
    for (render::SpringShape& s : joint.springs) {
      s.ghost = true;
      frame.springs.push_back(s);
    }
  }
}

render::Bounds followed_bounds(const scene::Scene& scene, const scene::Snapshot& snap) {
  render::Bounds box;
  const int followed = body_index(scene, scene.camera.follow);
  if (followed < 0 || followed >= static_cast<int>(snap.bodies.size())) return box;
  std::set<int> bodies{followed};
  render::DrawFrame joints;
  for (std::size_t j = 0; j < scene.joints.size() && j < snap.joints.size(); ++j) {
    const scene::JointSettings& js = scene.joints[j];
    if (js.body_a != scene.camera.follow && js.body_b != scene.camera.follow) continue;
    bodies.insert(body_index(scene, js.body_a));
    bodies.insert(body_index(scene, js.body_b));
    add_joint(joints, scene, snap, j);
  }
  box.add(render::bounds_of(joints));
  for (int i : bodies) {
    if (i < 0 || snap.bodies[i].is_static) continue;
    const scene::BodySnapshot& b = snap.bodies[i];
    if (b.is_circle) {
      box.add(render::Vec2{b.center.x() - b.radius, b.center.y() - b.radius});
      box.add(render::Vec2{b.center.x() + b.radius, b.center.y() + b.radius});
    }
    for (const Eigen::Vector2d& v : b.vertices) box.add(vec(v));
  }
  return box;
}

render::FrameSet scene_frames(const scene::Scene& scene, const std::vector<scene::Snapshot>& snapshots,
                              const scene::SceneResult* result, const SceneLayers& layers) {
  render::FrameSet set;
  const std::vector<std::string> legend = result ? scene_legend(scene, *result) : std::vector<std::string>{};
  const std::optional<render::Inset> inset =
      result && layers.inset ? probe_inset(scene, *result, inset_probe(scene, *result)) : std::nullopt;
  set.camera.auto_fit = scene.camera.fit;
  set.camera.centre_m = vec(scene.camera.center);
  set.camera.width_m = scene.camera.width_m;
  set.follow.width_m = scene.camera.width_m;
  set.run_end_s = scene::frame_count(scene.world) / scene.world.fps;
  const int count = static_cast<int>(snapshots.size());
  for (int i = 0; i < count; ++i) {
    set.frames.push_back(scene_frame(scene, snapshots, i, layers));
    set.frames.back().legend = legend;
    // Frames from another engine's run say so in the settings line; Box2D 2.4's, the default, keep it as it was.
    if (result && result->engine != scene::kBox2DV24SceneBackend.name) {
      set.frames.back().settings = result->engine + " \u00b7 " + set.frames.back().settings;
    }
    if (inset) {
      set.frames.back().inset = inset;
      set.frames.back().inset->cursor_s = snapshots[i].time_s;
    }
    if (result) add_oscillators(set.frames.back(), scene, *result, snapshots, i);
    set.times_s.push_back(snapshots[i].time_s);
    if (!scene.camera.follow.empty()) set.follow.bounds_m.push_back(followed_bounds(scene, snapshots[i]));
  }
  return set;
}

}  // namespace softtune::app
