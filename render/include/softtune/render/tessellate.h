#pragma once
// Draw model -> triangles in pixel space. No GL here: any backend (OSMesa today, EGL later) draws the
// same mesh, and tests can check geometry without a context.

#include <cstdint>
#include <span>
#include <vector>

#include "softtune/render/draw_model.h"
#include "softtune/render/palette.h"
#include "softtune/render/view.h"

namespace softtune::render {

/// One vertex: pixel position (x right, y down, 0..width, 0..height) and a straight-alpha colour.
struct Vertex {
  float x = 0.0f;
  float y = 0.0f;
  Rgba colour;
};

/// Triangles, three vertices each, in drawing order (blend "source over").
struct Mesh {
  std::vector<Vertex> vertices;
};

/// How a frame of a given size draws: line widths and text size grow with the image height so a frame
/// reads the same at 640x360 and at 1920x1080.
struct StrokeSizes {
  double outline_px;
  double spring_px;
  double ground_px;
  double anchor_radius_px;
  int text_dot_px;  ///< one font dot, whole pixels so glyphs stay crisp
  double grid_min_spacing_px;
};
StrokeSizes stroke_sizes(ImageSize size);

/// Grid step in metres: the smallest 1, 2, 5 x 10^k at least `min_spacing_px` apart on screen.
double grid_step_m(double pixels_per_m, double min_spacing_px);

/// Tessellates `frame` seen through `view`, all but its text. With `fringe_aa` every edge gets a
/// one-pixel alpha ramp (anti-aliasing without multisampling); without it edges are hard (for a
/// multisampled target).
void tessellate(const DrawFrame& frame, const View& view, bool fringe_aa, Mesh& out);

/// The frame's text (labels, caption, grid step), drawn last on the read-back pixels: bitmap text costs
/// a few thousand pixel writes on the CPU but two triangles per font dot on llvmpipe.
void draw_text_overlay(const DrawFrame& frame, const View& view, std::span<std::uint8_t> rgba);

}  // namespace softtune::render
