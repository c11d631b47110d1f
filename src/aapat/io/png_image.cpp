#include "aapat/io/png_image.h"

#include <fmt/format.h>
#include <png.h>

#include <cstdio>

#include "aapat/core/geometry.h"
#include "aapat/io/atomic_file.h"

namespace aapat {
namespace {

void append(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}

}  // namespace

std::string png_gray_bytes(int width, int height, const std::vector<uint8_t>& pixels) {
  if (width <= 0 || height <= 0 || pixels.size() != static_cast<size_t>(width) * height)
    throw Error(fmt::format("PNG: a {}x{} image needs {} pixels, got {}", width, height,
                            static_cast<size_t>(width) * height, pixels.size()));
  std::string encoded;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error("PNG encoding failed");
  }
  png_set_write_fn(png, &encoded, append, nullptr);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(&pixels[static_cast<size_t>(y) * width]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return encoded;
}

void write_png_gray(const std::string& path, int width, int height,
                    const std::vector<uint8_t>& pixels) {
  // Encode in memory, then write the file atomically.
  std::string encoded;
  try {
    encoded = png_gray_bytes(width, height, pixels);
  } catch (const Error& e) {
    throw Error(fmt::format("cannot write '{}': {}", path, e.what()));
  }
  write_file_atomically(path, encoded);
}

}  // namespace aapat
