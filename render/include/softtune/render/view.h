#pragma once
// World (metres, y up) -> image pixels (x right, y down, origin at the top-left corner).

#include <cstddef>

#include "softtune/render/draw_model.h"

namespace softtune::render {

/// Image size in pixels.
struct ImageSize {
  int width = 640;
  int height = 360;
  bool operator==(const ImageSize&) const = default;
};

/// Bytes of a straight RGBA image of `size` (4 per pixel).
inline std::size_t rgba_bytes(ImageSize size) {
  return static_cast<std::size_t>(size.width) * static_cast<std::size_t>(size.height) * 4;
}

/// Whether `bytes` hold exactly one RGBA image of `size`, and the size is positive.
inline bool is_rgba_of(ImageSize size, std::size_t bytes) {
  return size.width > 0 && size.height > 0 && bytes == rgba_bytes(size);
}

/// Fraction of the image height kept free at the top for the caption and legend (the title band) when a
/// camera is fitted: four lines of text at 360 px.
inline constexpr double kCaptionBand = 0.2;

/// The tallest title band (fraction of the image height) a long legend may grow it to.
inline constexpr double kMaxCaptionBand = 0.45;

/// A fixed camera that shows `bounds` with `margin` (fraction of the larger side) on every side and
/// the caption band (`band`, a fraction of the height) free above, at the image's aspect ratio; at least
/// `min_width_m` wide so a point does not blow up.
Camera fit_camera(const Bounds& bounds, double aspect, double margin = 0.06, double min_width_m = 0.5,
                  double band = kCaptionBand);

/// The pixel mapping of a fixed camera for an image size:
///   px = W/2 + (x - cx) s,  py = H/2 - (y - cy) s,  s = W / width_m (pixels per metre).
struct View {
  ImageSize size;
  Vec2 centre_m;
  double pixels_per_m = 64.0;

  double px(double x_m) const { return 0.5 * size.width + (x_m - centre_m.x) * pixels_per_m; }
  double py(double y_m) const { return 0.5 * size.height - (y_m - centre_m.y) * pixels_per_m; }
  /// World y of pixel row py (the inverse of py()).
  double world_y(double py_px) const { return centre_m.y + (0.5 * size.height - py_px) / pixels_per_m; }
  double world_x(double px_px) const { return centre_m.x + (px_px - 0.5 * size.width) / pixels_per_m; }
};

/// The fixed camera a frame is drawn with: `camera` itself, or fitted to the frame's bounds.
Camera resolve_camera(const Camera& camera, const DrawFrame& frame, ImageSize size);

/// `camera` must be fixed (auto_fit false).
View make_view(const Camera& camera, ImageSize size);

}  // namespace softtune::render
