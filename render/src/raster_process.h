#pragma once
// One raster process (softtune-raster, raster_main.cpp) and the socket to it. Private to render/ and
// its tests; callers use make_osmesa_renderer() (renderer.h).

#include <sys/types.h>

#include <cstdint>
#include <span>
#include <string>

#include "softtune/render/renderer.h"
#include "softtune/render/tessellate.h"

namespace softtune::render {

struct RasterProcessOptions {
  int msaa_samples = 0;
  int llvmpipe_threads = 0;
  /// ms a frame may take before the process is killed and the frame fails.
  int frame_timeout_ms = kFrameTimeoutMs;
};

class RasterProcess {
 public:
  /// Starts the process; throws std::runtime_error naming what it tried when it cannot.
  explicit RasterProcess(const RasterProcessOptions& options);
  /// Closes the socket and reaps the process (killed if it has not exited within 2 s).
  ~RasterProcess();
  RasterProcess(const RasterProcess&) = delete;
  RasterProcess& operator=(const RasterProcess&) = delete;

  /// Pixels for `vertices` into `rgba`. Throws std::runtime_error when the frame fails: the process
  /// reported an error (it stays usable), or it died, hung past the frame timeout or broke the protocol
  /// (it is then killed, and alive() is false).
  void rasterize(std::span<const Vertex> vertices, ImageSize size, std::span<std::uint8_t> rgba);

  bool alive() const { return pid_ > 0; }
  pid_t pid() const { return pid_; }
  /// CPU time (user and system) the process has used so far, s (/proc/PID/stat, 10 ms ticks); 0 when
  /// it is not running or cannot be read.
  double cpu_seconds() const;
  /// Closes the socket, waits for the exit and returns the wait status (tests: a clean exit is 0).
  int close_and_wait();

 private:
  [[noreturn]] void fail(const std::string& what);
  int reap(int grace_ms);

  RasterProcessOptions options_;
  pid_t pid_ = -1;
  int socket_ = -1;
};

}  // namespace softtune::render
