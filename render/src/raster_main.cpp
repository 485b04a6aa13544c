// softtune-raster: the raster process. A renderer (process_renderer.cpp) starts one, sends it
// triangles over the socket on fd 3 and reads the pixels back (raster_protocol.h). It holds the GL
// context and with it Mesa and LLVM, so the server and the CLI never load them, a fault in the GL stack
// ends this process and not the server, and the memory goes back when it exits.
//
//   softtune-raster --msaa N --llvmpipe-threads N
//
// It exits with status 0 when the socket closes (its renderer is gone: destroyed, idle, or its process
// ended), and with status 2 on a request it cannot read (the stream is then out of step).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "osmesa_rasterizer.h"
#include "raster_protocol.h"

namespace {

using namespace softtune::render;
using namespace softtune::render::raster;

struct Args {
  int msaa = 0;
  int llvmpipe_threads = 0;
};

bool parse_int(const char* text, int lo, int hi, int& out) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < lo || v > hi) return false;
  out = static_cast<int>(v);
  return true;
}

bool parse_args(int argc, char** argv, Args& args) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const bool ok = flag == "--msaa"               ? parse_int(argv[i + 1], 0, 16, args.msaa)
                    : flag == "--llvmpipe-threads" ? parse_int(argv[i + 1], 0, 64, args.llvmpipe_threads)
                                                   : false;
    if (!ok) return false;
  }
  return argc % 2 == 1;
}

bool reply_error(const std::string& message) {
  RasterReply reply;
  reply.message_bytes = static_cast<std::uint32_t>(std::min<std::size_t>(message.size(), kMaxMessageBytes));
  return send_all(kSocketFd, &reply, sizeof reply) == Io::ok &&
         send_all(kSocketFd, message.data(), reply.message_bytes) == Io::ok;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  if (!parse_args(argc, argv, args)) {
    std::fprintf(stderr, "softtune-raster: usage: --msaa N --llvmpipe-threads N\n");
    return 2;
  }
  // llvmpipe reads LP_NUM_THREADS when it starts; a value in the environment wins.
  setenv("LP_NUM_THREADS", std::to_string(args.llvmpipe_threads).c_str(), 0);

  OsmesaRasterizer rasterizer(args.msaa);
  std::vector<Vertex> vertices;
  std::vector<std::uint8_t> rgba;
  for (;;) {
    RasterRequest request;
    switch (receive_exact(kSocketFd, &request, sizeof request, -1)) {
      case Io::ok: break;
      case Io::eof: return 0;
      case Io::timeout:
      case Io::error: return 2;
    }
    if (request.magic != kRequestMagic || request.width == 0 || request.width > kMaxSide || request.height == 0 ||
        request.height > kMaxSide || request.vertex_count > kMaxVertices) {
      reply_error("raster: malformed request");
      return 2;
    }
    vertices.resize(request.vertex_count);
    if (receive_exact(kSocketFd, vertices.data(), vertices.size() * sizeof(Vertex), -1) != Io::ok) return 2;

    const ImageSize size{static_cast<int>(request.width), static_cast<int>(request.height)};
    rgba.resize(rgba_bytes(size));
    RasterReply reply;
    try {
      reply.context_created = rasterizer.has_context() ? 0 : 1;  // a frame that throws creates none
      rasterizer.rasterize(vertices, size, rgba);
      reply.ok = 1;
    } catch (const std::exception& e) {
      if (!reply_error(e.what())) return 0;
      continue;
    }
    if (send_all(kSocketFd, &reply, sizeof reply) != Io::ok || send_all(kSocketFd, rgba.data(), rgba.size()) != Io::ok) {
      return 0;  // the renderer is gone
    }
  }
}
