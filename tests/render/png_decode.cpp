#include "png_decode.h"

#include "softtune/render/png.h"

namespace softtune::render::test {

Decoded decode_png(const std::string& png) {
  Decoded d;
  ImageSize size;
  d.rgba = render::decode_png(png, size);
  d.width = size.width;
  d.height = size.height;
  return d;
}

}  // namespace softtune::render::test
