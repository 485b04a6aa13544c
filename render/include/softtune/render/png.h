#pragma once
// PNG encoding with libpng. Frames are opaque, so the alpha byte is dropped (RGB, 25 % less to deflate).
// Defaults: zlib level 1 with the UP filter, measured in bench/render_bench.cpp (docs/benchmarks.md,
// "Preview frames").

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "softtune/render/view.h"

namespace softtune::render {

enum class PngFilter { none, sub, up, average, paeth, all };

struct PngOptions {
  int level = 1;                  ///< zlib level 0..9
  PngFilter filter = PngFilter::up;
};

/// Encodes straight RGBA pixels (row 0 at the top) as an 8-bit RGB PNG; the bytes are returned in a
/// string. Throws std::runtime_error if libpng fails.
std::string encode_png(std::span<const std::uint8_t> rgba, ImageSize size, PngOptions options = {});

/// Decodes a PNG into straight RGBA (row 0 at the top) and its size: a clip is made from the cached
/// frames. Throws std::runtime_error when `png` is not a PNG.
std::vector<std::uint8_t> decode_png(std::string_view png, ImageSize& size);

}  // namespace softtune::render
