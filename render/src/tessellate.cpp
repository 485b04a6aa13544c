#include "softtune/render/tessellate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "softtune/render/text.h"

namespace softtune::render {
namespace {

struct P {
  double x, y;
};
P operator+(P a, P b) { return {a.x + b.x, a.y + b.y}; }
P operator-(P a, P b) { return {a.x - b.x, a.y - b.y}; }
P operator*(P a, double s) { return {a.x * s, a.y * s}; }
double dot(P a, P b) { return a.x * b.x + a.y * b.y; }
double norm(P a) { return std::sqrt(dot(a, a)); }
P unit(P a) {
  const double n = norm(a);
  return n > 0.0 ? a * (1.0 / n) : P{0.0, 0.0};
}
P perp(P a) { return {-a.y, a.x}; }

Rgba with_alpha(Rgba c, double scale) {
  c.a = static_cast<std::uint8_t>(std::lround(std::clamp(c.a * scale, 0.0, 255.0)));
  return c;
}

class Builder {
 public:
  Builder(Mesh& mesh, bool fringe) : mesh_(mesh), fringe_(fringe) {}

  void tri(P a, Rgba ca, P b, Rgba cb, P c, Rgba cc) {
    mesh_.vertices.push_back({static_cast<float>(a.x), static_cast<float>(a.y), ca});
    mesh_.vertices.push_back({static_cast<float>(b.x), static_cast<float>(b.y), cb});
    mesh_.vertices.push_back({static_cast<float>(c.x), static_cast<float>(c.y), cc});
  }
  // Quad a-b-c-d (in order around), a and b coloured ca, c and d coloured cd.
  void quad(P a, P b, Rgba cab, P c, P d, Rgba ccd) {
    tri(a, cab, b, cab, c, ccd);
    tri(a, cab, c, ccd, d, ccd);
  }
  void rect(double x0, double y0, double x1, double y1, Rgba c) { quad({x0, y0}, {x1, y0}, c, {x1, y1}, {x0, y1}, c); }

  // A convex polygon; with fringe, shrunk by half a pixel and ringed by a one-pixel alpha ramp.
  void fill_convex(std::vector<P> pts, Rgba colour) {
    dedupe(pts, true);
    if (pts.size() < 3) return;
    const std::vector<P> normals = vertex_normals(pts, true);
    const double inset = fringe_ ? 0.5 : 0.0;
    std::vector<P> inner(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) inner[i] = pts[i] - normals[i] * inset;
    for (std::size_t i = 1; i + 1 < inner.size(); ++i) tri(inner[0], colour, inner[i], colour, inner[i + 1], colour);
    if (!fringe_) return;
    const Rgba clear = with_alpha(colour, 0.0);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::size_t j = (i + 1) % pts.size();
      quad(inner[i], inner[j], colour, pts[j] + normals[j] * 0.5, pts[i] + normals[i] * 0.5, clear);
    }
  }

  // A polyline `width_px` wide with mitred joins (mitres capped so sharp zig-zags stay bounded).
  void stroke(std::vector<P> pts, bool closed, double width_px, Rgba colour) {
    dedupe(pts, closed);
    if (pts.size() < 2) return;
    std::vector<P> normals = vertex_normals(pts, closed);
    const double half = 0.5 * width_px;
    const double core = fringe_ ? std::max(0.0, half - 0.5) : half;
    // Lines thinner than a pixel fade instead of thinning below the pixel grid.
    const Rgba c = fringe_ ? with_alpha(colour, std::min(1.0, width_px)) : colour;
    const Rgba clear = with_alpha(colour, 0.0);
    const std::size_t segments = closed ? pts.size() : pts.size() - 1;
    for (std::size_t i = 0; i < segments; ++i) {
      const std::size_t j = (i + 1) % pts.size();
      const P a = pts[i], b = pts[j], na = normals[i], nb = normals[j];
      quad(a + na * core, b + nb * core, c, b - nb * core, a - na * core, c);
      if (!fringe_) continue;
      quad(a + na * core, b + nb * core, c, b + nb * (half + 0.5), a + na * (half + 0.5), clear);
      quad(a - na * core, b - nb * core, c, b - nb * (half + 0.5), a - na * (half + 0.5), clear);
    }
  }

  void disc(P centre, double radius_px, Rgba colour) { fill_convex(circle_points(centre, radius_px), colour); }

  static std::vector<P> circle_points(P centre, double radius_px) {
    const int n = std::clamp(static_cast<int>(std::ceil(radius_px * 0.9)), 12, 128);
    std::vector<P> pts(n);
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * std::numbers::pi * i / n;
      pts[i] = {centre.x + radius_px * std::cos(a), centre.y + radius_px * std::sin(a)};
    }
    return pts;
  }

 private:
  static void dedupe(std::vector<P>& pts, bool closed) {
    std::vector<P> out;
    out.reserve(pts.size());
    for (const P& p : pts) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      if (out.empty() || norm(p - out.back()) > 1e-4) out.push_back(p);
    }
    if (closed && out.size() > 1 && norm(out.front() - out.back()) <= 1e-4) out.pop_back();
    pts = std::move(out);
  }

  // Unit offsets per vertex, pointing out of a closed convex polygon (or to the left of an open
  // polyline), scaled to the mitre length 1 / cos(half the turn), capped at 4.
  static std::vector<P> vertex_normals(const std::vector<P>& pts, bool closed) {
    const std::size_t n = pts.size();
    const std::size_t segments = closed ? n : n - 1;
    std::vector<P> seg(segments);
    for (std::size_t i = 0; i < segments; ++i) seg[i] = unit(perp(pts[(i + 1) % n] - pts[i]));
    if (closed) {
      // Point the normals outwards: the signed area tells the winding.
      double area = 0.0;
      for (std::size_t i = 0; i < n; ++i) area += pts[i].x * pts[(i + 1) % n].y - pts[(i + 1) % n].x * pts[i].y;
      if (area > 0.0) {
        for (P& s : seg) s = s * -1.0;
      }
    }
    std::vector<P> out(n);
    for (std::size_t i = 0; i < n; ++i) {
      const bool has_prev = closed || i > 0, has_next = closed || i < segments;
      const P prev = has_prev ? seg[(i + segments - 1) % segments] : seg[i];
      const P next = has_next ? seg[i % segments] : prev;
      const P mid = unit(prev + next);
      const double c = dot(mid, next);
      out[i] = c > 0.25 ? mid * (1.0 / c) : (c > 0.0 ? mid * 4.0 : next);
    }
    return out;
  }

  Mesh& mesh_;
  bool fringe_;
};

P to_px(const View& v, Vec2 w) { return {v.px(w.x), v.py(w.y)}; }

// One-pixel rows and columns: exact pixel coverage, so no fringe is needed (and fewer triangles).
void draw_grid(Builder& b, const View& v, double step) {
  const double w = v.size.width, h = v.size.height;
  const double x0 = v.world_x(0.0), x1 = v.world_x(w);
  const double y0 = v.world_y(h), y1 = v.world_y(0.0);
  for (double k = std::ceil(x0 / step); k * step <= x1; k += 1.0) {
    const double px = std::floor(v.px(k * step));
    b.rect(px, 0.0, px + 1.0, h, palette::kGrid);
  }
  for (double k = std::ceil(y0 / step); k * step <= y1; k += 1.0) {
    const double py = std::floor(v.py(k * step));
    b.rect(0.0, py, w, py + 1.0, palette::kGrid);
  }
}

void draw_ground(Builder& b, const View& v, const StrokeSizes& s, double ground_y_m) {
  const double py = v.py(ground_y_m);
  const double w = v.size.width, h = v.size.height;
  if (py < h) b.rect(0.0, std::max(0.0, py), w, h, palette::kEarth);
  b.stroke({{-1.0, py}, {w + 1.0, py}}, false, s.ground_px, palette::kGroundLine);
}

std::vector<P> polygon_px(const View& v, const PolygonShape& p) {
  std::vector<P> pts;
  pts.reserve(p.vertices_m.size());
  for (Vec2 w : p.vertices_m) pts.push_back(to_px(v, w));
  return pts;
}

void draw_circle(Builder& b, const View& v, const StrokeSizes& s, const CircleShape& c) {
  const RoleColours rc = role_colours(c.role);
  const P centre = to_px(v, c.centre_m);
  const double r = c.radius_m * v.pixels_per_m;
  b.disc(centre, r, rc.fill);
  b.stroke(Builder::circle_points(centre, r), true, s.outline_px, rc.outline);
  // World angle is counter-clockwise with y up; pixels have y down.
  const P rim = centre + P{std::cos(c.angle_rad), -std::sin(c.angle_rad)} * r;
  b.stroke({centre, rim}, false, s.outline_px, rc.outline);
}

// A zig-zag with straight leads at both ends; its amplitude follows the rest length (clamped to stay
// readable) so the coils visibly bunch up under compression.
void draw_spring(Builder& b, const View& v, const StrokeSizes& s, const SpringShape& sp) {
  const P a = to_px(v, sp.a_m), e = to_px(v, sp.b_m);
  const double length_px = norm(e - a);
  const double current_m = sp.current_length_m ? *sp.current_length_m
                                               : std::hypot(sp.b_m.x - sp.a_m.x, sp.b_m.y - sp.a_m.y);
  Rgba colour = sp.style == SpringStyle::rod    ? palette::kRod
                : sp.style == SpringStyle::link ? palette::kMouseLink
                                                : spring_colour(current_m, sp.rest_length_m);
  if (sp.ghost) colour = with_alpha(colour, palette::kGhostAlpha / 255.0);
  if (sp.style == SpringStyle::rod) {
    b.stroke({a, e}, false, 1.5 * s.spring_px, colour);
    return;
  }
  if (length_px < 4.0) {
    b.stroke({a, e}, false, s.spring_px, colour);
    return;
  }
  const double scale = v.size.height / 360.0;
  const double reference_m = sp.rest_length_m > 0.0 ? sp.rest_length_m : current_m;
  const double amplitude = std::clamp(0.07 * reference_m * v.pixels_per_m, 3.0 * scale, 10.0 * scale);
  const P dir = (e - a) * (1.0 / length_px), side = perp(dir);
  const double lead = 0.12 * length_px;
  constexpr int kZigs = 12;
  std::vector<P> pts{a, a + dir * lead};
  for (int i = 0; i < kZigs; ++i) {
    const double t = lead + (length_px - 2.0 * lead) * (i + 0.5) / kZigs;
    pts.push_back(a + dir * t + side * (i % 2 == 0 ? amplitude : -amplitude));
  }
  pts.push_back(e - dir * lead);
  pts.push_back(e);
  b.stroke(std::move(pts), false, s.spring_px, colour);
}

// A revolute pin is a ring around a light face (the two bodies turn about it); a weld is a square,
// which does not turn.
void draw_pin(Builder& b, const View& v, const StrokeSizes& s, const PinShape& pin) {
  const double alpha = pin.ghost ? palette::kGhostAlpha / 255.0 : 1.0;
  const P c = to_px(v, pin.at_m);
  const double r = 1.3 * s.anchor_radius_px;
  if (pin.weld) {
    b.fill_convex({{c.x - r, c.y - r}, {c.x + r, c.y - r}, {c.x + r, c.y + r}, {c.x - r, c.y + r}},
                  with_alpha(palette::kAnchor, alpha));
    const double f = 0.45 * r;
    b.fill_convex({{c.x - f, c.y - f}, {c.x + f, c.y - f}, {c.x + f, c.y + f}, {c.x - f, c.y + f}},
                  with_alpha(palette::kPinFace, alpha));
    return;
  }
  b.disc(c, r, with_alpha(palette::kAnchor, alpha));
  b.disc(c, 0.45 * r, with_alpha(palette::kPinFace, alpha));
}

// A cross-hair with a ring: where a mouse joint pulls its body.
void draw_target(Builder& b, const View& v, const StrokeSizes& s, const TargetShape& t) {
  const P c = to_px(v, t.at_m);
  const double r = 3.0 * s.anchor_radius_px, w = 0.75 * s.outline_px;
  b.stroke(Builder::circle_points(c, 0.6 * r), true, w, palette::kMouseLink);
  b.stroke({{c.x - r, c.y}, {c.x + r, c.y}}, false, w, palette::kMouseLink);
  b.stroke({{c.x, c.y - r}, {c.x, c.y + r}}, false, w, palette::kMouseLink);
}

// Segments that fade in from transparent at the oldest point to kTrail at the newest; a divergence trail
// in kDivergence, wider, with a dot at each step so the growing jumps read as steps.
void draw_trail(Builder& b, const View& v, const StrokeSizes& s, const Trail& t) {
  const std::size_t n = t.points_m.size();
  const Rgba colour = t.divergent ? palette::kDivergence : palette::kTrail;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double alpha = static_cast<double>(i + 1) / (n - 1);
    b.stroke({to_px(v, t.points_m[i]), to_px(v, t.points_m[i + 1])}, false, (t.divergent ? 1.0 : 0.75) * s.spring_px,
             with_alpha(colour, alpha));
    if (t.divergent) b.disc(to_px(v, t.points_m[i + 1]), 0.8 * s.anchor_radius_px, with_alpha(colour, alpha));
  }
}

// The debug layers (draw_model.h). Sizes in pixels, so the marks read at any zoom: Box2D's testbed
// draws contact normals 0.3 m long (testbed/test.cpp, Test::Step, k_axisScale) and points 10 px wide.
void draw_debug_marks(Builder& b, const View& v, const StrokeSizes& s, const DrawFrame& f) {
  const double r = s.anchor_radius_px, w = 0.6 * s.outline_px;
  for (const RestMark& m : f.rest_marks) {
    const P at = to_px(v, m.at_m), n = perp(unit(P{m.along.x, -m.along.y})) * (2.2 * r);
    b.stroke({at + n, at - n}, false, w + 1.5, palette::kHalo);
    b.stroke({at + n, at - n}, false, w, palette::kRestMark);
  }
  for (const AxisMark& a : f.axes) {
    const P p0 = to_px(v, a.from_m), p1 = to_px(v, a.to_m), rest = to_px(v, a.rest_m), now = to_px(v, a.now_m);
    // The axis dashed, its rest point ticked, the travel from rest to now drawn thick.
    const P d = p1 - p0;
    const double len = norm(d), dash = 4.0 * w + 2.0;
    for (double t = 0.0; t < len; t += 2.0 * dash) {
      b.stroke({p0 + unit(d) * t, p0 + unit(d) * std::min(len, t + dash)}, false, w, palette::kRestMark);
    }
    const P n = perp(unit(d)) * (1.6 * r);
    b.stroke({rest + n, rest - n}, false, w, palette::kRestMark);
    b.stroke({rest, now}, false, 2.0 * w, palette::kRestMark);
  }
  for (const AnchorPair& p : f.anchor_pairs) {
    const P a = to_px(v, p.a_m), pb = to_px(v, p.b_m);
    const P gap_end = a + (pb - a) * p.magnify;
    if (norm(gap_end - a) > 0.5) {
      b.stroke({a, gap_end}, false, w + 1.5, palette::kHalo);
      b.stroke({a, gap_end}, false, w, palette::kAnchorGap);
    }
    b.stroke(Builder::circle_points(a, 1.5 * r), true, w, palette::kAnchor);
    b.disc(pb, 0.6 * r, palette::kAnchorGap);
  }
  for (const MassCentre& m : f.mass_centres) {
    // The usual centre-of-mass sign: a disc quartered dark and light.
    const P c = to_px(v, m.at_m);
    const double rc = 1.1 * r;
    b.disc(c, rc + 1.0, palette::kHalo);
    for (int q = 0; q < 4; ++q) {
      std::vector<P> wedge{c};
      for (int k = 0; k <= 6; ++k) {
        const double ang = (q + k / 6.0) * 0.5 * std::numbers::pi;
        wedge.push_back({c.x + rc * std::cos(ang), c.y + rc * std::sin(ang)});
      }
      b.fill_convex(wedge, q % 2 == 0 ? palette::kContact : palette::kPinFace);
    }
  }
  for (const ContactMark& c : f.contacts) {
    const P at = to_px(v, c.at_m), tip = at + unit(P{c.normal.x, -c.normal.y}) * (4.0 * r);
    b.stroke({at, tip}, false, w + 1.5, palette::kHalo);
    b.stroke({at, tip}, false, w, palette::kContact);
    b.disc(at, 0.9 * r, palette::kHalo);
    b.disc(at, 0.6 * r, palette::kContact);
  }
}

// A ghost body wholly out of the view below the band (the camera frames the real run only): an arrow
// in the ghost's colour at the view's edge, pointing at it; one arrow where several would overlap.
void draw_ghost_arrows(Builder& b, const View& v, const StrokeSizes& s, const DrawFrame& f, double band_px) {
  const double w = v.size.width, h = v.size.height, r = 3.0 * s.anchor_radius_px;
  std::vector<P> drawn;
  const auto mark = [&](const std::vector<P>& pts) {
    if (pts.empty()) return;
    P lo = pts.front(), hi = pts.front();
    for (const P& p : pts) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    if (hi.x >= 0.0 && lo.x <= w && hi.y >= band_px && lo.y <= h) return;  // at least partly in view
    const P c = (lo + hi) * 0.5;
    const P at{std::clamp(c.x, 1.5 * r, w - 1.5 * r), std::clamp(c.y, band_px + 1.5 * r, h - 1.5 * r)};
    const P dir = unit(c - at);
    if (!(norm(dir) > 0.0) || !std::isfinite(at.x) || !std::isfinite(at.y)) return;
    for (const P& d : drawn) {
      if (norm(d - at) < 2.0 * r) return;
    }
    drawn.push_back(at);
    const P tip = at + dir * r, base = at - dir * (0.6 * r), side = perp(dir) * (0.75 * r);
    const RoleColours ghost = role_colours(Role::ghost);
    b.fill_convex({tip, base + side, base - side}, ghost.outline);
  };
  for (const PolygonShape& p : f.polygons) {
    if (p.role == Role::ghost) mark(polygon_px(v, p));
  }
  for (const CircleShape& c : f.circles) {
    if (c.role != Role::ghost) continue;
    const P o = to_px(v, c.centre_m);
    const double rp = c.radius_m * v.pixels_per_m;
    mark({{o.x - rp, o.y - rp}, {o.x + rp, o.y + rp}});
  }
}

// The probe inset: a panel, the probe's samples, its fit and the asked response as polylines (each
// broken where it has no value), and a vertical cursor at the frame's time.
void draw_inset(Builder& b, const StrokeSizes& s, const Inset& in, ImageSize size, int legend_lines) {
  if (in.t_s.size() < 2 || in.value.size() != in.t_s.size()) return;
  const InsetBox box = inset_box(size, in.corner, caption_band(size, legend_lines));
  b.rect(box.x, box.y, box.x + box.w, box.y + box.h, palette::kInsetPanel);
  b.stroke({{box.x, box.y}, {box.x + box.w, box.y}, {box.x + box.w, box.y + box.h}, {box.x, box.y + box.h}}, true,
           0.5 * s.outline_px, palette::kBandRule);
  // Plain names, not a structured binding: clang 14 (the sanitizer builds) cannot capture one in a lambda.
  const std::pair<double, double> range = inset_range(in);
  const double lo = range.first, hi = range.second;
  const double t0 = in.t_s.front(), t1 = in.t_s.back();
  const auto curve = [&](const std::vector<double>& v, Rgba colour, double width) {
    if (v.size() != in.t_s.size()) return;
    std::vector<P> run;
    const auto flush = [&] {
      if (run.size() >= 2) b.stroke(run, false, width, colour);
      run.clear();
    };
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!std::isfinite(v[i])) {
        flush();
        continue;
      }
      run.push_back({inset_x(box, in.t_s[i], t0, t1), inset_y(box, v[i], lo, hi)});
    }
    flush();
  };
  curve(in.asked, palette::kInsetAsked, 0.75 * s.spring_px);
  curve(in.value, palette::kInsetProbe, 0.6 * s.spring_px);
  curve(in.fitted, palette::kInsetFit, 0.6 * s.spring_px);
  const double cx = inset_x(box, std::clamp(in.cursor_s, t0, t1), t0, t1);
  b.stroke({{cx, box.plot_y}, {cx, box.plot_y + box.plot_h}}, false, 0.5 * s.spring_px, palette::kInsetCursor);
}

std::string grid_label(double step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "grid %g m", step);
  return buf;
}

// The title band's panel: a lighter strip with a rule under it, so the band reads as the frame's header.
void draw_band(Builder& b, const View& v, double band) {
  const double h = std::round(band * v.size.height);
  b.rect(0.0, 0.0, v.size.width, h, palette::kBand);
  b.rect(0.0, h - 1.0, v.size.width, h, palette::kBandRule);
}

}  // namespace

StrokeSizes stroke_sizes(ImageSize size) {
  const double s = std::max(0.5, size.height / 360.0);
  return {
      .outline_px = 2.0 * s,
      .spring_px = 2.0 * s,
      .ground_px = 2.0 * s,
      .anchor_radius_px = 3.5 * s,
      .text_px = std::max(8, static_cast<int>(std::lround(size.height * 0.036))),
      .grid_min_spacing_px = 36.0 * s,
  };
}

int min_legend_px(ImageSize size) {
  return std::max(7, static_cast<int>(std::lround(kMinLegendPxAt360 * size.height / 360.0)));
}

double caption_band(ImageSize size, int legend_lines) {
  // layout_text_overlay's rows: its margin on either side, one line per row, the last clear of the rule.
  const int margin = std::max(2, stroke_sizes(size).text_px / 2);
  const int need = 2 * margin + (1 + std::max(0, legend_lines)) * line_height_px(min_legend_px(size)) + 1;
  return std::clamp(static_cast<double>(need) / size.height, kCaptionBand, kMaxCaptionBand);
}

double grid_step_m(double pixels_per_m, double min_spacing_px) {
  if (!(pixels_per_m > 0.0)) return 1.0;
  const double want = min_spacing_px / pixels_per_m;
  double decade = std::pow(10.0, std::floor(std::log10(want)));
  for (;;) {
    for (double m : {1.0, 2.0, 5.0}) {
      if (m * decade >= want * (1.0 - 1e-12)) return m * decade;
    }
    decade *= 10.0;
  }
}

void tessellate(const DrawFrame& f, const View& v, bool fringe_aa, Mesh& out) {
  out.vertices.clear();
  Builder b(out, fringe_aa);
  const StrokeSizes s = stroke_sizes(v.size);
  const double step = grid_step_m(v.pixels_per_m, s.grid_min_spacing_px);
  draw_grid(b, v, step);
  if (f.ground_y_m) draw_ground(b, v, s, *f.ground_y_m);
  const double band = caption_band(v.size, static_cast<int>(f.legend.size()));
  draw_band(b, v, band);
  for (const Trail& t : f.trails) draw_trail(b, v, s, t);
  for (const PolygonShape& p : f.polygons) {
    const RoleColours rc = role_colours(p.role);
    std::vector<P> pts = polygon_px(v, p);
    b.fill_convex(pts, rc.fill);
    b.stroke(std::move(pts), true, s.outline_px, rc.outline);
  }
  for (const CircleShape& c : f.circles) draw_circle(b, v, s, c);
  for (const SpringShape& sp : f.springs) draw_spring(b, v, s, sp);
  for (const PinShape& p : f.pins) draw_pin(b, v, s, p);
  for (const TargetShape& t : f.targets) draw_target(b, v, s, t);
  for (const AnchorDot& a : f.anchors) {
    b.disc(to_px(v, a.at_m), s.anchor_radius_px,
           a.ghost ? with_alpha(palette::kAnchor, palette::kGhostAlpha / 255.0) : palette::kAnchor);
  }
  draw_debug_marks(b, v, s, f);
  draw_ghost_arrows(b, v, s, f, std::round(band * v.size.height));
  if (f.inset) draw_inset(b, s, *f.inset, v.size, static_cast<int>(f.legend.size()));
}

InsetBox inset_box(ImageSize size, Corner corner, double band) {
  InsetBox box;
  const double margin = std::max(2.0, 0.015 * size.height);
  box.w = std::round(kInsetWidth * size.width);
  box.h = std::round(kInsetHeight * size.height);
  const bool right = corner == Corner::bottom_right || corner == Corner::top_right;
  const bool bottom = corner == Corner::bottom_right || corner == Corner::bottom_left;
  box.x = right ? size.width - margin - box.w : margin;
  box.y = bottom ? size.height - margin - box.h : std::round(band * size.height) + margin;
  box.title_px = std::max(7, min_legend_px(size) - 2);
  const double title_h = 2.0 * line_height_px(box.title_px) + 2.0;  // two lines: the probe, then the curves
  const double pad = std::max(2.0, 0.02 * box.h);
  box.plot_x = box.x + pad;
  box.plot_w = box.w - 2.0 * pad;
  box.plot_y = box.y + title_h + pad;
  box.plot_h = std::max(4.0, box.h - title_h - 2.0 * pad);
  return box;
}

Corner quietest_corner(const std::vector<DrawFrame>& frames, const std::vector<Camera>& cameras, ImageSize size) {
  if (frames.empty() || cameras.size() != frames.size()) return Corner::bottom_right;
  const double band = caption_band(size, static_cast<int>(frames.front().legend.size()));
  const Corner corners[] = {Corner::bottom_right, Corner::bottom_left, Corner::top_right, Corner::top_left};
  double covered[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const View v = make_view(cameras[i], size);
    const DrawFrame& f = frames[i];
    std::vector<Bounds> boxes;  // px
    const auto px_box = [&v](const std::vector<Vec2>& pts) {
      Bounds b;
      for (Vec2 p : pts) b.add(Vec2{v.px(p.x), v.py(p.y)});
      return b;
    };
    for (const PolygonShape& p : f.polygons) {
      if (p.role != Role::static_body && p.role != Role::ghost) boxes.push_back(px_box(p.vertices_m));
    }
    for (const CircleShape& c : f.circles) {
      if (c.role == Role::static_body || c.role == Role::ghost) continue;
      boxes.push_back(px_box({{c.centre_m.x - c.radius_m, c.centre_m.y - c.radius_m}, {c.centre_m.x + c.radius_m, c.centre_m.y + c.radius_m}}));
    }
    for (const SpringShape& sp : f.springs) {
      if (!sp.ghost) boxes.push_back(px_box({sp.a_m, sp.b_m}));
    }
    for (const AnchorDot& a : f.anchors) {
      if (!a.ghost) boxes.push_back(px_box({a.at_m, a.at_m}));
    }
    for (int k = 0; k < 4; ++k) {
      const InsetBox in = inset_box(size, corners[k], band);
      for (const Bounds& b : boxes) {
        // A point or a line still covers a few pixels.
        const double w = std::max(0.0, std::min(b.hi.x + 2.0, in.x + in.w) - std::max(b.lo.x - 2.0, in.x));
        const double h = std::max(0.0, std::min(b.hi.y + 2.0, in.y + in.h) - std::max(b.lo.y - 2.0, in.y));
        covered[k] += w * h;
      }
    }
  }
  int best = 0;
  for (int k = 1; k < 4; ++k) {
    if (covered[k] < covered[best]) best = k;
  }
  return corners[best];
}

double inset_y(const InsetBox& box, double value, double lo, double hi) {
  return box.plot_y + box.plot_h * (hi - value) / (hi - lo);
}

double inset_x(const InsetBox& box, double t, double t0, double t1) {
  return box.plot_x + box.plot_w * (t1 > t0 ? (t - t0) / (t1 - t0) : 0.0);
}

std::pair<double, double> inset_range(const Inset& in) {
  double lo = INFINITY, hi = -INFINITY;
  for (const std::vector<double>* v : {&in.value, &in.fitted, &in.asked}) {
    for (double x : *v) {
      if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    }
  }
  if (!(lo <= hi)) return {-1.0, 1.0};
  const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(1e-9, 0.05 * std::abs(hi) + 1e-9);
  return {lo - pad, hi + pad};
}

std::vector<PlacedText> layout_text_overlay(const DrawFrame& f, const View& v) {
  const StrokeSizes s = stroke_sizes(v.size);
  const int width = v.size.width;
  const int band = static_cast<int>(std::lround(caption_band(v.size, static_cast<int>(f.legend.size())) * v.size.height));
  const int margin = std::max(2, s.text_px / 2);
  std::string settings = f.settings;
  settings += (settings.empty() ? "" : "  \u00b7  ") + grid_label(grid_step_m(v.pixels_per_m, s.grid_min_spacing_px));
  const std::string caption = f.caption;
  // Shrink the text until the first line (caption and settings side by side) and the legend (one
  // column if the band has the rows, else two) fit across and down the band.
  const auto layout = [&](int px, int columns, std::vector<PlacedText>& placed) {
    placed.clear();
    const int line = line_height_px(px);
    const int rows = std::max(1, (band - 2 * margin) / line);
    const TextBox cap = measure_text(caption, margin, margin, px);
    const TextBox set = measure_text(settings, 0, margin, px);
    const int caption_lines = 1 + static_cast<int>(std::count(caption.begin(), caption.end(), '\n'));
    bool fits = cap.right + 2 * margin + (set.right - set.left) <= width - margin && caption_lines <= rows;
    placed.push_back({caption, margin, margin, px, cap});
    const int sx = width - margin - (set.right - set.left);
    placed.push_back({settings, sx, margin, px, measure_text(settings, sx, margin, px)});
    const int legend_rows = rows - caption_lines, column = (width - 2 * margin) / columns;
    const int room = columns * std::max(0, legend_rows);
    const int n = static_cast<int>(f.legend.size());
    for (int k = 0; k < n && k < room; ++k) {
      std::string text = f.legend[k];
      if (k == room - 1 && n > room) text = "+" + std::to_string(n - room + 1) + " more";
      const int x = margin + (k % columns) * column, y = margin + (caption_lines + k / columns) * line;
      const TextBox box = measure_text(text, x, y, px);
      fits = fits && box.right <= x + column - margin;
      placed.push_back({text, x, y, px, box});
    }
    fits = fits && (n == 0 || room >= n);
    for (const PlacedText& t : placed) fits = fits && t.box.bottom <= band - 1;
    return fits;
  };
  std::vector<PlacedText> out;
  bool done = false;
  for (int px = s.text_px; px >= 7 && !done; --px) {
    for (int columns : {1, 2}) {
      if ((done = layout(px, columns, out))) break;
    }
  }
  if (!done) {
    // Too small for everything: keep what fits at the smallest size, whole lines only.
    layout(7, 2, out);
    std::erase_if(out, [&](const PlacedText& t) { return t.box.right > width || t.box.bottom > band || t.box.left < 0; });
  }
  if (f.inset && f.inset->t_s.size() >= 2) {
    const InsetBox box = inset_box(v.size, f.inset->corner, caption_band(v.size, static_cast<int>(f.legend.size())));
    const int x = static_cast<int>(box.x) + 3, y = static_cast<int>(box.y) + 1;
    int px = box.title_px;
    while (px > 7 && measure_text(f.inset->title, x, y, px).right > box.x + box.w - 3) --px;
    out.push_back({f.inset->title, x, y, px, measure_text(f.inset->title, x, y, px), false});
  }
  for (const Label& l : f.labels) {
    int x = static_cast<int>(std::lround(v.px(l.at_m.x)));
    const int y = static_cast<int>(std::lround(v.py(l.at_m.y))) - line_height_px(s.text_px);
    if (l.centred) x -= measure_text(l.text, 0, 0, s.text_px).right / 2;
    out.push_back({l.text, x, y, s.text_px, measure_text(l.text, x, y, s.text_px), false});
  }
  return out;
}

void draw_text_overlay(const DrawFrame& f, const View& v, std::span<std::uint8_t> rgba) {
  for (const PlacedText& t : layout_text_overlay(f, v)) blit_text(rgba, v.size, t.text, t.x, t.y, t.px, palette::kText);
}

}  // namespace softtune::render
