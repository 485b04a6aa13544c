#include "softtune/render/view.h"

#include <algorithm>

namespace softtune::render {

Camera fit_camera(const Bounds& bounds, double aspect, double margin, double min_width_m, double band) {
  Camera c;
  c.auto_fit = false;
  if (bounds.empty()) {
    c.width_m = 10.0;
    return c;
  }
  const double w = bounds.hi.x - bounds.lo.x, h = bounds.hi.y - bounds.lo.y;
  c.centre_m = {0.5 * (bounds.lo.x + bounds.hi.x), 0.5 * (bounds.lo.y + bounds.hi.y)};
  // The view is width_m x width_m / aspect: wide enough for the box, and tall enough for it below
  // the caption band; the box is centred in the part under the band.
  const double pad = 2.0 * margin * std::max(w, h);
  c.width_m = std::max({w + pad, (h + pad) / (1.0 - band) * aspect, min_width_m});
  c.centre_m.y += 0.5 * band * c.width_m / aspect;
  return c;
}

Camera resolve_camera(const Camera& camera, const DrawFrame& frame, ImageSize size) {
  if (!camera.auto_fit) return camera;
  return fit_camera(bounds_of(frame), static_cast<double>(size.width) / size.height);
}

View make_view(const Camera& camera, ImageSize size) {
  View v;
  v.size = size;
  v.centre_m = camera.centre_m;
  v.pixels_per_m = size.width / camera.width_m;
  return v;
}

}  // namespace softtune::render
