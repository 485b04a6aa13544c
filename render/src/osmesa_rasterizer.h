#pragma once
// Triangles -> pixels on OSMesa (GL 3.3 core on llvmpipe). Used only inside the raster process
// (raster_main.cpp): the server and the CLI never load Mesa (process_renderer.cpp says why).

#include <cstdint>
#include <memory>
#include <span>

#include "softtune/render/tessellate.h"

namespace softtune::render {

class OsmesaRasterizer {
 public:
  /// msaa_samples 0: single sample (the mesh carries its own alpha fringes); 4: 4x multisampling.
  explicit OsmesaRasterizer(int msaa_samples);
  ~OsmesaRasterizer();
  OsmesaRasterizer(const OsmesaRasterizer&) = delete;
  OsmesaRasterizer& operator=(const OsmesaRasterizer&) = delete;

  /// Clears to the background colour, draws `vertices` (three per triangle, pixel space, y down) with
  /// "source over" blending and reads back straight RGBA, row 0 at the top, into `rgba`
  /// (size.width * size.height * 4 bytes). Creates the GL context on the first call.
  void rasterize(std::span<const Vertex> vertices, ImageSize size, std::span<std::uint8_t> rgba);

  bool has_context() const;

 private:
  struct Gl;
  std::unique_ptr<Gl> gl_;
  int msaa_samples_;
};

}  // namespace softtune::render
