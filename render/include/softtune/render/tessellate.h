#pragma once
// Draw model -> triangles in pixel space. No GL here: any backend (OSMesa today, EGL later) draws the
// same mesh, and tests can check geometry without a context.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "softtune/render/draw_model.h"
#include "softtune/render/palette.h"
#include "softtune/render/text.h"
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
  int text_px;      ///< em size of the band's text
  double grid_min_spacing_px;
};
StrokeSizes stroke_sizes(ImageSize size);

/// Grid step in metres: the smallest 1, 2, 5 x 10^k at least `min_spacing_px` apart on screen.
double grid_step_m(double pixels_per_m, double min_spacing_px);

/// Tessellates `frame` seen through `view`, all but its text. With `fringe_aa` every edge gets a
/// one-pixel alpha ramp (anti-aliasing without multisampling); without it edges are hard (for a
/// multisampled target).
void tessellate(const DrawFrame& frame, const View& view, bool fringe_aa, Mesh& out);

/// One text of the overlay, where it goes.
struct PlacedText {
  std::string text;
  int x = 0, y = 0;  ///< px, top-left
  int px = 12;       ///< em size
  TextBox box;       ///< what it covers
  bool in_band = true;  ///< false for labels placed in the world
};

/// Where the frame's text goes: the caption at the band's top-left, the settings and grid step at its
/// top-right, the legend under the caption in two columns (entries beyond the band's room summed up as
/// "+N more"), all shrunk until they fit the band's width; labels at their world positions. The title
/// band is the top kCaptionBand of the image.
std::vector<PlacedText> layout_text_overlay(const DrawFrame& frame, const View& view);

/// The frame's text (layout_text_overlay), drawn last on the read-back pixels: FreeType glyphs cost a
/// few thousand pixel writes on the CPU, where as triangles they would cost llvmpipe more than the scene.
void draw_text_overlay(const DrawFrame& frame, const View& view, std::span<std::uint8_t> rgba);

}  // namespace softtune::render
