#include "aapat/io/png_image.h"

#include "aapat/render/image_error.h"

#include <fmt/format.h>
#include <png.h>

#include <algorithm>
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

std::string png_bytes(int width, int height, int channels, const std::vector<uint8_t>& pixels) {
  const size_t row = static_cast<size_t>(width) * static_cast<size_t>(channels);
  if (width <= 0 || height <= 0 || (channels != 1 && channels != 3) ||
      pixels.size() != row * static_cast<size_t>(height))
    throw Error(fmt::format("PNG: a {}x{} image of {} channels needs {} bytes, got {}", width,
                            height, channels, row * static_cast<size_t>(std::max(height, 0)),
                            pixels.size()));
  std::string encoded;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error("PNG encoding failed");
  }
  png_set_write_fn(png, &encoded, append, nullptr);
  // Colour images here are error maps of whole frames: zlib's fastest level
  // writes them several times faster for a few per cent more bytes.
  if (channels == 3) png_set_compression_level(png, 1);
  png_set_IHDR(png, info, width, height, 8,
               channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(&pixels[static_cast<size_t>(y) * row]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return encoded;
}

std::string png_gray_bytes(int width, int height, const std::vector<uint8_t>& pixels) {
  return png_bytes(width, height, 1, pixels);
}

namespace {

// Encode in memory, then write the file atomically.
void write_png(const std::string& path, int width, int height, int channels,
               const std::vector<uint8_t>& pixels) {
  std::string encoded;
  try {
    encoded = png_bytes(width, height, channels, pixels);
  } catch (const Error& e) {
    throw Error(fmt::format("cannot write '{}': {}", path, e.what()));
  }
  write_file_atomically(path, encoded);
}

}  // namespace

void write_png_gray(const std::string& path, int width, int height,
                    const std::vector<uint8_t>& pixels) {
  write_png(path, width, height, 1, pixels);
}

void write_png_rgb(const std::string& path, int width, int height,
                   const std::vector<uint8_t>& pixels) {
  write_png(path, width, height, 3, pixels);
}

void write_png_image(const std::string& path, const Image& image) {
  write_png(path, image.width, image.height, image.channels, level_pixels(image));
}

PngColor read_png_color(const std::string& path, const std::string& what) {
  // A PNG of kMaxColorImagePixels compresses to far less than this; the
  // header's size is checked before anything is decoded.
  return decode_png_color(read_file(path, what, size_t{1} << 30), path, what);
}

PngColor decode_png_color(std::string_view bytes, const std::string& path,
                          const std::string& what) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
    throw Error(fmt::format("{} '{}': not a PNG image ({})", what, path, image.message));
  struct Release {
    png_image* image;
    ~Release() { png_image_free(image); }
  } release{&image};
  const size_t pixels = static_cast<size_t>(image.width) * image.height;
  if (image.width < 1 || image.height < 1 || pixels > kMaxColorImagePixels)
    throw Error(fmt::format("{} '{}': {}x{} pixels; at most {} pixels (docs/limits.md)", what, path,
                            image.width, image.height, kMaxColorImagePixels));
  PngColor out;
  out.had_alpha = (image.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  image.format = PNG_FORMAT_RGBA;  // 8-bit sRGB, alpha kept apart (not premultiplied)
  std::vector<uint8_t> rgba(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgba.data(), 0, nullptr))
    throw Error(fmt::format("{} '{}': cannot decode it ({})", what, path, image.message));
  out.image = {static_cast<int>(image.width), static_cast<int>(image.height),
               std::vector<float>(3 * pixels)};
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c) out.image.rgb[3 * p + c] = rgba[4 * p + c] / 255.0f;
  return out;
}

}  // namespace aapat
