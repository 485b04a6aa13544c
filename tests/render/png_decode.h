#pragma once
// Test helper: decodes a PNG (libpng) to straight RGBA so tests can read pixels back.

#include <cstdint>
#include <string>
#include <vector>

namespace softtune::render::test {

struct Decoded {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
  const std::uint8_t* at(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

/// Throws std::runtime_error when `png` is not a PNG.
Decoded decode_png(const std::string& png);

}  // namespace softtune::render::test
