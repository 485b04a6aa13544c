#include "softtune/render/draw_model.h"

#include <algorithm>

namespace softtune::render {

void Bounds::add(Vec2 p) {
  if (empty()) {
    lo = hi = p;
    return;
  }
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
}

void Bounds::add(const Bounds& b) {
  if (b.empty()) return;
  add(b.lo);
  add(b.hi);
}

Bounds bounds_of(const DrawFrame& f) {
  Bounds b;
  for (const PolygonShape& p : f.polygons) {
    for (Vec2 v : p.vertices_m) b.add(v);
  }
  for (const CircleShape& c : f.circles) {
    b.add(Vec2{c.centre_m.x - c.radius_m, c.centre_m.y - c.radius_m});
    b.add(Vec2{c.centre_m.x + c.radius_m, c.centre_m.y + c.radius_m});
  }
  for (const SpringShape& s : f.springs) {
    b.add(s.a_m);
    b.add(s.b_m);
  }
  for (const AnchorDot& a : f.anchors) b.add(a.at_m);
  for (const PinShape& p : f.pins) b.add(p.at_m);
  for (const TargetShape& t : f.targets) b.add(t.at_m);
  for (const Trail& t : f.trails) {
    if (t.divergent) continue;  // a blow-up's steps run out of the view on purpose
    for (Vec2 v : t.points_m) b.add(v);
  }
  for (const AnchorPair& p : f.anchor_pairs) b.add(p.a_m), b.add(p.b_m);
  // The ground has no horizontal extent; its height still belongs in the picture.
  if (f.ground_y_m && !b.empty()) b.add(Vec2{b.lo.x, *f.ground_y_m});
  return b;
}

}  // namespace softtune::render
