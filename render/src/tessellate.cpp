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

// Segments that fade in from transparent at the oldest point to kTrail at the newest.
void draw_trail(Builder& b, const View& v, const StrokeSizes& s, const Trail& t) {
  const std::size_t n = t.points_m.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double alpha = static_cast<double>(i + 1) / (n - 1);
    b.stroke({to_px(v, t.points_m[i]), to_px(v, t.points_m[i + 1])}, false, 0.75 * s.spring_px,
             with_alpha(palette::kTrail, alpha));
  }
}

std::string grid_label(double step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "grid %g m", step);
  return buf;
}

// The title band's panel: a lighter strip with a rule under it, so the band reads as the frame's header.
void draw_band(Builder& b, const View& v) {
  const double h = std::round(kCaptionBand * v.size.height);
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
  draw_band(b, v);
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
}

std::vector<PlacedText> layout_text_overlay(const DrawFrame& f, const View& v) {
  const StrokeSizes s = stroke_sizes(v.size);
  const int width = v.size.width, band = static_cast<int>(std::lround(kCaptionBand * v.size.height));
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
