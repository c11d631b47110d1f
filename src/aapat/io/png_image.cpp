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
  return decode_png_color(read_file(path, what, kMaxPngFileBytes), path, what, kColorImageLimits);
}

std::optional<std::pair<uint32_t, uint32_t>> png_dimensions(std::string_view bytes) {
  // The signature, then the IHDR chunk: length, "IHDR", width, height (big-endian).
  if (bytes.size() < 24 ||
      png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0 ||
      bytes.substr(12, 4) != "IHDR")
    return std::nullopt;
  const auto be32 = [&](size_t at) {
    uint32_t v = 0;
    for (size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
    return v;
  };
  return std::pair{be32(16), be32(20)};
}

namespace {

// What the decoder fills in; it lives outside decode() so that nothing
// decode() changes after its setjmp is a local that a longjmp could leave
// indeterminate.
struct PngDecoding {
  std::string_view bytes;
  size_t at = 0;
  std::string message;
  png_uint_32 width = 0, height = 0;
  bool too_large = false, had_alpha = false;
  int channels = 0;
  std::vector<uint8_t> pixels;
  std::vector<png_bytep> rows;
};

void read_bytes(png_structp png, png_bytep out, png_size_t n) {
  auto* d = static_cast<PngDecoding*>(png_get_io_ptr(png));
  if (n > d->bytes.size() - d->at) png_error(png, "the file ends early");
  std::copy_n(d->bytes.data() + d->at, n, reinterpret_cast<char*>(out));
  d->at += n;
}
[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  static_cast<PngDecoding*>(png_get_error_ptr(png))->message = message;
  png_longjmp(png, 1);
}
void on_png_warning(png_structp, png_const_charp) {}

// False on a libpng error (its message in d->message).
bool decode(png_structp png, png_infop info, PngDecoding* d, const ImageLimits& limits) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, d, read_bytes);
  png_read_info(png, info);
  d->width = png_get_image_width(png, info);
  d->height = png_get_image_height(png, info);
  if (d->width < 1 || d->height < 1 || d->width > limits.max_side || d->height > limits.max_side ||
      size_t{d->width} * d->height > limits.max_pixels) {
    d->too_large = true;
    return true;
  }
  const int type = png_get_color_type(png, info);
  d->had_alpha = (type & PNG_COLOR_MASK_ALPHA) != 0 || png_get_valid(png, info, PNG_INFO_tRNS);
  // Values as stored: palettes and low bit depths expanded, 16 bits reduced to
  // their high byte (as FLIP's reference tool reads them), grey copied to
  // R, G and B, and no gamma conversion whatever gAMA, sRGB, cHRM or iCCP say.
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  d->channels = png_get_channels(png, info);
  const size_t row = png_get_rowbytes(png, info);
  d->pixels.resize(row * d->height);
  d->rows.resize(d->height);
  for (png_uint_32 y = 0; y < d->height; ++y) d->rows[y] = &d->pixels[row * y];
  png_read_image(png, d->rows.data());
  png_read_end(png, nullptr);
  return true;
}

}  // namespace

PngColor decode_png_color(std::string_view bytes, const std::string& path, const std::string& what,
                          const ImageLimits& limits) {
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0)
    throw Error(fmt::format("{} '{}': not a PNG image", what, path));
  PngDecoding d;
  d.bytes = bytes;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &d, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool decoded = png && info && decode(png, info, &d, limits);
  png_destroy_read_struct(&png, &info, nullptr);
  if (!decoded)
    throw Error(fmt::format("{} '{}': cannot decode it ({})", what, path,
                            d.message.empty() ? "out of memory" : d.message));
  if (d.too_large)
    throw Error(
        fmt::format("{} '{}': {}x{} pixels; at most {} per side and {} in all "
                    "(docs/limits.md)",
                    what, path, d.width, d.height, limits.max_side, limits.max_pixels));
  const size_t pixels = size_t{d.width} * d.height;
  PngColor out;
  out.had_alpha = d.had_alpha;
  out.image = {static_cast<int>(d.width), static_cast<int>(d.height),
               std::vector<float>(3 * pixels)};
  for (size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c)
      out.image.rgb[3 * p + c] = d.pixels[static_cast<size_t>(d.channels) * p + c] / 255.0f;
  return out;
}

}  // namespace aapat
