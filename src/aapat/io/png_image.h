// PNG files through libpng: grey and colour images written whole or not at
// all, and any PNG read as a colour image.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "aapat/analyze/color_image.h"
#include "aapat/render/renderer.h"

namespace aapat {

// `pixels` is width x height x channels bytes (1: grey, 3: RGB), row by row
// from the top.
std::string png_bytes(int width, int height, int channels, const std::vector<uint8_t>& pixels);
std::string png_gray_bytes(int width, int height, const std::vector<uint8_t>& pixels);
void write_png_gray(const std::string& path, int width, int height,
                    const std::vector<uint8_t>& pixels);
void write_png_rgb(const std::string& path, int width, int height,
                   const std::vector<uint8_t>& pixels);
// A rendering's 8-bit levels: grey, or RGB for a colour image.
void write_png_image(const std::string& path, const Image& image);

// The largest image read_png_color takes (docs/limits.md): 2^25 pixels (8K
// UHD), checked from the header before any pixel is decoded.
inline constexpr size_t kMaxColorImagePixels = size_t{1} << 25;

// The size an image read may have, checked from its header before any pixel
// is decoded.
struct ImageLimits {
  uint32_t max_side;
  size_t max_pixels;
};
inline constexpr ImageLimits kColorImageLimits{uint32_t{1} << 20, kMaxColorImagePixels};

struct PngColor {
  ColorImage image;  // sRGB values in [0, 1]; grey files give R = G = B
  bool had_alpha = false;
};
// Any PNG: grey or colour, with or without alpha, 1 to 16 bits, palette or
// not, interlaced or not. The values are taken as stored: 16-bit values are
// reduced to their high byte, as FLIP's reference tool reads them, and no
// gamma conversion is made whatever the colour chunks (gAMA, sRGB, cHRM,
// iCCP) say, so the same content at 8 and 16 bits reads the same. Alpha is
// dropped: the colour compared is the colour stored. Throws
// Error naming the file (`what` says what it is): missing, not a PNG,
// truncated, or too large.
PngColor read_png_color(const std::string& path, const std::string& what);
// The same from the file's bytes (a texture embedded in a model); `path`
// names them in errors.
// A PNG's width and height from its header, without decoding; none when the
// bytes do not start as a PNG does.
std::optional<std::pair<uint32_t, uint32_t>> png_dimensions(std::string_view bytes);
// The largest PNG file read_png_color reads (a PNG of kMaxColorImagePixels
// compresses to far less).
inline constexpr size_t kMaxPngFileBytes = size_t{1} << 30;
// `limits` the size it may have (a model's texture: kMaxTextureSide).
PngColor decode_png_color(std::string_view bytes, const std::string& path, const std::string& what,
                          const ImageLimits& limits = kColorImageLimits);

}  // namespace aapat
