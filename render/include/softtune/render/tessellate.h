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

/// The smallest legend text, px at a 360 px tall image (scaled with the height): rather than shrink
/// below it, the title band grows (caption_band).
inline constexpr double kMinLegendPxAt360 = 11.0;
int min_legend_px(ImageSize size);

/// The title band's height as a fraction of the image: kCaptionBand, or taller (up to kMaxCaptionBand)
/// when the caption and `legend_lines` lines, one per row at min_legend_px, would not fit in it. Fixed
/// by the line count alone, so every frame of a run has the same band as its camera (run_cameras).
double caption_band(ImageSize size, int legend_lines);

/// Where the probe inset's plot goes (px, top-left and size) in an image of `size`: `corner` (a top one
/// just under a title band of `band`, a fraction of the height), kInsetWidth x kInsetHeight of the
/// image, its title (two lines) above the plot.
inline constexpr double kInsetWidth = 0.32, kInsetHeight = 0.24;
struct InsetBox {
  double x = 0, y = 0, w = 0, h = 0;  ///< the whole panel
  double plot_x = 0, plot_y = 0, plot_w = 0, plot_h = 0;
  int title_px = 8;
};
InsetBox inset_box(ImageSize size, Corner corner = Corner::bottom_right, double band = kCaptionBand);

/// The corner whose inset box the run's moving shapes (every body but static ones and ghosts, every
/// spring and anchor) cover least, summed over the frames as each camera shows them; ties go to
/// bottom right, then bottom left, top right, top left. So the inset never sits on the stiff preset's
/// soft block or the bridge's deck end when another corner is free.
Corner quietest_corner(const std::vector<DrawFrame>& frames, const std::vector<Camera>& cameras, ImageSize size);

/// Pixel y of `value` in the inset's plot, for a plot spanning [lo, hi] (the samples' range, widened to
/// hold every curve): the plot's bottom at lo, its top at hi.
double inset_y(const InsetBox& box, double value, double lo, double hi);
/// Pixel x of time t in the inset's plot spanning [t0, t1].
double inset_x(const InsetBox& box, double t, double t0, double t1);
/// The value range the inset plots: every finite value of the three curves (a flat series widened).
std::pair<double, double> inset_range(const Inset& inset);

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
/// band is the top caption_band of the image.
std::vector<PlacedText> layout_text_overlay(const DrawFrame& frame, const View& view);

/// The frame's text (layout_text_overlay), drawn last on the read-back pixels: FreeType glyphs cost a
/// few thousand pixel writes on the CPU, where as triangles they would cost llvmpipe more than the scene.
void draw_text_overlay(const DrawFrame& frame, const View& view, std::span<std::uint8_t> rgba);

}  // namespace softtune::render
