#pragma once
// The conversation between a renderer (process_renderer.cpp) and its raster process (raster_main.cpp)
// over a Unix stream socket: one request, one reply, in order. Both ends are built together from this
// header on one machine, so the structs go over the socket as they are.
//
//   request: RasterRequest, then vertex_count Vertex (tessellate.h)
//   reply:   RasterReply, then width * height * 4 bytes of RGBA when ok, else message_bytes of text

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "softtune/render/tessellate.h"

namespace softtune::render::raster {

inline constexpr std::uint32_t kRequestMagic = 0x52535452;  // "RTSR"
inline constexpr std::uint32_t kReplyMagic = 0x50545352;    // "RSTP"
/// The socket is fd 3 in the raster process.
inline constexpr int kSocketFd = 3;
/// What a raster process accepts; the frame pipeline's own caps (1920 x 1080) are far below.
inline constexpr std::uint32_t kMaxSide = 8192;
inline constexpr std::uint64_t kMaxVertices = std::uint64_t{1} << 26;
inline constexpr std::uint32_t kMaxMessageBytes = 4096;

struct RasterRequest {
  std::uint32_t magic = kRequestMagic;
  std::uint32_t width = 0;   ///< px
  std::uint32_t height = 0;  ///< px
  std::uint32_t reserved = 0;
  std::uint64_t vertex_count = 0;
};

struct RasterReply {
  std::uint32_t magic = kReplyMagic;
  std::uint32_t ok = 0;
  std::uint32_t context_created = 0;  ///< 1 when this frame created the process's GL context
  std::uint32_t message_bytes = 0;
};

static_assert(std::is_trivially_copyable_v<RasterRequest> && std::is_trivially_copyable_v<RasterReply>);
static_assert(std::is_trivially_copyable_v<Vertex> && sizeof(Vertex) == 12, "vertices go over the socket raw");

enum class Io { ok, eof, timeout, error };

/// Sends all `bytes` (no SIGPIPE when the peer is gone).
Io send_all(int fd, const void* data, std::size_t bytes);
/// Receives exactly `bytes`, waiting at most `timeout_ms` for each part (-1: forever). eof when the
/// peer closed before the first byte or in the middle.
Io receive_exact(int fd, void* data, std::size_t bytes, int timeout_ms);

}  // namespace softtune::render::raster
