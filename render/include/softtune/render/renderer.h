#pragma once
// The renderer interface: a frame (draw model) + camera + size -> RGBA pixels. Callers never see GL:
// the OSMesa backend (osmesa_rasterizer.cpp, the one file that includes GL headers, run in a process of
// its own) can be replaced by an EGL surfaceless one (Mesa 25.1 removed OSMesa) without touching them.

#include <cstdint>
#include <memory>
#include <span>

#include "softtune/render/draw_model.h"
#include "softtune/render/view.h"

namespace softtune::render {

/// ms one frame may take in its raster process before the process is killed and the frame fails.
inline constexpr int kFrameTimeoutMs = 60'000;

struct RendererOptions {
  /// 0: one-pixel alpha fringes on every edge (analytic anti-aliasing, single sample);
  /// 4: 4x multisampling with hard edges. docs/benchmarks.md "Preview frames" gives the measured costs.
  int msaa_samples = 0;
  /// llvmpipe rasterizer threads (LP_NUM_THREADS) when the environment does not set it: 0 rasterizes on
  /// the calling thread, fastest with one render worker per core (docs/benchmarks.md, "Preview frames").
  int llvmpipe_threads = 0;
};

/// Not thread-safe: one renderer per worker thread. The GL context (in the renderer's raster process,
/// about 80 MB with Mesa and LLVM) is created on the first render() and kept for the renderer's life.
class Renderer {
 public:
  virtual ~Renderer() = default;
  /// Draws `frame` through `camera` (fitted to this frame's bounds when auto_fit) into `rgba`, which
  /// holds size.width * size.height * 4 bytes: straight RGBA, row 0 at the top, alpha 255.
  virtual void render(const DrawFrame& frame, const Camera& camera, ImageSize size, std::span<std::uint8_t> rgba) = 0;
  /// CPU time spent drawing outside the calling thread so far (a raster process's, summed over every
  /// process this renderer has had), s: with the caller's own thread CPU time, what its frames cost.
  virtual double raster_cpu_seconds() const { return 0.0; }
};

/// The OSMesa (llvmpipe) backend. Draws in a raster process of its own (softtune-raster, from the
/// executable's folder or the build tree), started on the first render(), so the calling process never
/// loads Mesa or LLVM. A frame that fails there (a GL error, a crash, over 60 s) throws
/// std::runtime_error and the next frame starts a new process.
std::unique_ptr<Renderer> make_osmesa_renderer(RendererOptions options = {});

/// GL contexts this process's renderers have had created so far: a request without frames must leave
/// it unchanged.
int gl_contexts_created();

/// Raster processes this process has started so far.
int raster_processes_started();

}  // namespace softtune::render
