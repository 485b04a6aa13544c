// The renderer behind make_osmesa_renderer(): tessellates and writes the text overlay here, and has a
// raster process of its own (raster_process.h) turn the triangles into pixels. Mesa's libOSMesa pulls
// in libLLVM, which costs any process that maps it about 50 MB of RSS and 20-30 ms at start; with GL in a
// separate process, a server or a `softtune tune` never pays that, a fault in the GL stack fails one
// frame instead of ending the server, a hung frame is killed, and a renderer destroyed when idle (the
// frame pipeline does so) gives its memory back.
#include <algorithm>
#include <optional>
#include <stdexcept>

#include "raster_process.h"
#include "softtune/render/renderer.h"
#include "softtune/render/tessellate.h"

namespace softtune::render {
namespace {

class ProcessRenderer final : public Renderer {
 public:
  explicit ProcessRenderer(RendererOptions options)
      : options_{.msaa_samples = options.msaa_samples, .llvmpipe_threads = options.llvmpipe_threads} {}

  void render(const DrawFrame& frame, const Camera& camera, ImageSize size, std::span<std::uint8_t> rgba) override {
    if (!is_rgba_of(size, rgba.size())) {
      throw std::invalid_argument("render: the pixel buffer does not match the image size");
    }
    const View view = make_view(resolve_camera(camera, frame, size), size);
    tessellate(frame, view, options_.msaa_samples == 0, mesh_);
    // A process that died with an earlier frame is replaced.
    if (!process_ || !process_->alive()) process_.emplace(options_);
    const double before = process_->cpu_seconds();
    try {
      process_->rasterize(mesh_.vertices, size, rgba);
    } catch (...) {
      raster_cpu_ += std::max(0.0, process_->cpu_seconds() - before);
      throw;
    }
    raster_cpu_ += std::max(0.0, process_->cpu_seconds() - before);
    draw_text_overlay(frame, view, rgba);
  }

  double raster_cpu_seconds() const override { return raster_cpu_; }

 private:
  RasterProcessOptions options_;
  std::optional<RasterProcess> process_;
  Mesh mesh_;
  double raster_cpu_ = 0.0;  ///< s, summed over frames and processes
};

}  // namespace

std::unique_ptr<Renderer> make_osmesa_renderer(RendererOptions options) {
  return std::make_unique<ProcessRenderer>(options);
}

}  // namespace softtune::render
