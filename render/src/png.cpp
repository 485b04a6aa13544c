#include "softtune/render/png.h"

#include <png.h>

#include <stdexcept>
#include <vector>

namespace softtune::render {
namespace {

int filter_flags(PngFilter f) {
  switch (f) {
    case PngFilter::none: return PNG_FILTER_NONE;
    case PngFilter::sub: return PNG_FILTER_SUB;
    case PngFilter::up: return PNG_FILTER_UP;
    case PngFilter::average: return PNG_FILTER_AVG;
    case PngFilter::paeth: return PNG_FILTER_PAETH;
    case PngFilter::all: return PNG_ALL_FILTERS;
  }
  return PNG_FILTER_UP;
}

void append(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

void flush(png_structp) {}

// libpng's error path is setjmp/longjmp; the message is kept for the exception thrown afterwards.
void fail(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message;
  png_longjmp(png, 1);
}

void warn(png_structp, png_const_charp) {}

// Only trivially destructible locals live between setjmp and a possible longjmp.
bool write(png_structp png, png_infop info, ImageSize size, int level, int filters, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, size.width, size.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, level);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, filters);
  png_write_info(png, info);
  png_set_filler(png, 0, PNG_FILLER_AFTER);  // input rows carry a fourth byte to drop
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::string encode_png(std::span<const std::uint8_t> rgba, ImageSize size, PngOptions options) {
  if (!is_rgba_of(size, rgba.size())) {
    throw std::invalid_argument("png: the pixel buffer does not match the image size");
  }
  std::string out, error;
  out.reserve(rgba.size() / 8);
  std::vector<png_bytep> rows(size.height);
  for (int y = 0; y < size.height; ++y) {
    rows[y] = const_cast<png_bytep>(rgba.data() + static_cast<std::size_t>(y) * size.width * 4);
  }
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, fail, warn);
  if (!png) throw std::runtime_error("png: cannot create a write struct");
  png_infop info = png_create_info_struct(png);
  png_set_write_fn(png, &out, append, flush);
  const bool ok = info && write(png, info, size, options.level, filter_flags(options.filter), rows.data());
  png_destroy_write_struct(&png, &info);
  if (!ok) throw std::runtime_error("png: " + (error.empty() ? std::string("cannot create an info struct") : error));
  // The guess above is 2-8 times what a frame compresses to, and cached frames live for long: without
  // this a preview cache bounded at 256 MiB of PNG bytes held up to 2 GiB of capacity.
  out.shrink_to_fit();
  return out;
}

std::vector<std::uint8_t> decode_png(std::string_view png, ImageSize& size) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, png.data(), png.size())) {
    throw std::runtime_error(std::string("not a PNG: ") + image.message);
  }
  image.format = PNG_FORMAT_RGBA;
  std::vector<std::uint8_t> rgba(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgba.data(), 0, nullptr)) {
    throw std::runtime_error(std::string("PNG decode failed: ") + image.message);
  }
  size = {static_cast<int>(image.width), static_cast<int>(image.height)};
  return rgba;
}

}  // namespace softtune::render
