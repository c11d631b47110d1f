#include "aapat/render/texture.h"
#include "aapat/generate/portable_random.h"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <random>

namespace aapat {
namespace {

// A size x size texture whose texel (i, j) is f(i, j).
template <class F>
Texture raster(std::string name, int size, F f) {
  Texture t{std::move(name), size, size, std::vector<double>(static_cast<size_t>(size) * size)};
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) t.texels[static_cast<size_t>(j) * size + i] = f(i, j);
  return t;
}

// Rows of "words" of 3 x 5 glyphs on white, like a page of small print: the
// texture whose minification shows mipmapping's blur most plainly.
Texture text_noise(const std::string& name, int size, uint64_t seed) {
  Texture t = raster(name, size, [](int, int) { return 1.0; });
  std::mt19937_64 rng(seed);
  constexpr int kGlyphW = 4, kGlyphH = 8;  // a 3 x 5 glyph and its spacing
  for (int line = 0; line + kGlyphH <= size; line += kGlyphH) {
    int x = 1;
    while (x + kGlyphW <= size) {
      const int letters = static_cast<int>(uniform_int(rng, 1, 7));
      for (int l = 0; l < letters && x + kGlyphW <= size; ++l, x += kGlyphW)
        for (int gy = 0; gy < 5; ++gy)
          for (int gx = 0; gx < 3; ++gx)
            if (bernoulli(rng, 0.45))
              t.texels[static_cast<size_t>(line + 1 + gy) * size + x + gx] = 0.0;
      x += kGlyphW;  // the space between words
    }
  }
  return t;
}

}  // namespace

double Texture::at(int i, int j) const {
  i %= width;
  j %= height;
  if (i < 0) i += width;
  if (j < 0) j += height;
  return texels[static_cast<size_t>(j) * width + i];
}

double Texture::exact(double s, double t) const {
  // floor in doubles first: far coordinates (near a horizon) pass any int.
  const double i = std::floor(s) - width * std::floor(std::floor(s) / width);
  const double j = std::floor(t) - height * std::floor(std::floor(t) / height);
  if (!(i >= 0 && j >= 0)) return 0.0;  // NaN coordinates: no texel (callers check first)
  return texels[static_cast<size_t>(std::min(j, height - 1.0)) * width +
                static_cast<size_t>(std::min(i, width - 1.0))];
}

uint64_t Texture::content_hash() const {
  // A word at a time (a multiply and a shift each), not FNV's byte at a
  // time: a model's 2048 x 2048 texture is 4M texels a channel.
  uint64_t h = 1469598103934665603ull;
  auto mix = [&](uint64_t v) {
    h = (h ^ v) * 0x9E3779B97F4A7C15ull;
    h ^= h >> 29;
  };
  mix(static_cast<uint64_t>(width));
  mix(static_cast<uint64_t>(height));
  for (const double v : texels) {
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    mix(bits);
  }
  return h;
}

void validate(const Texture& t, std::string_view what) {
  if (t.width < 1 || t.height < 1 || t.width > kMaxTextureSide || t.height > kMaxTextureSide)
    throw Error(fmt::format("texture {}: {}x{} texels; each side must be 1 to {}", what, t.width,
                            t.height, kMaxTextureSide));
  if (t.texels.size() != static_cast<size_t>(t.width) * t.height)
    throw Error(
        fmt::format("texture {}: {} texels for {}x{}", what, t.texels.size(), t.width, t.height));
  for (size_t k = 0; k < t.texels.size(); ++k)
    if (!(t.texels[k] >= 0 && t.texels[k] <= 1))
      throw Error(fmt::format("texture {}: texel {} is {}, not a grey level in [0, 1]", what, k,
                              t.texels[k]));
}

const TextureRegistry& texture_registry() {
  static const TextureRegistry kRegistry(
      "texture",
      {{{"checker",
         "black and white squares, white at the origin",
         "CS4620 Lecture 23 (the textured checkerboard)",
         {{"cells", "8", "squares per side"}, {"size", "256", "texels per side"}}},
        [](const Spec& s) {
          const int cells = s.whole("cells", 1, 4096), size = s.whole("size", 1, kMaxTextureSide);
          return raster(s.canonical(), size, [&](int i, int j) {
            return (static_cast<int64_t>(i) * cells / size +
                    static_cast<int64_t>(j) * cells / size) %
                               2 ==
                           0
                       ? 1.0
                       : 0.0;
          });
        }},
       {{"stripes",
         "vertical black and white stripes, white first",
         "aapat: one direction of detail (anisotropy)",
         {{"cells", "16", "stripes per side"}, {"size", "256", "texels per side"}}},
        [](const Spec& s) {
          const int cells = s.whole("cells", 1, 4096), size = s.whole("size", 1, kMaxTextureSide);
          return raster(s.canonical(), size, [&](int i, int) {
            return static_cast<int64_t>(i) * cells / size % 2 == 0 ? 1.0 : 0.0;
          });
        }},
       {{"zoneplate",
         "0.5 + 0.5 cos(pi r^2 / size), r in texels from the centre: Nyquist at the edge",
         "aapat: every frequency at once",
         {{"size", "512", "texels per side"}}},
        [](const Spec& s) {
          const int size = s.whole("size", 1, kMaxTextureSide);
          return raster(s.canonical(), size, [&](int i, int j) {
            const double x = i + 0.5 - size / 2.0, y = j + 0.5 - size / 2.0;
            return 0.5 + 0.5 * std::cos(kPi * (x * x + y * y) / size);
          });
        }},
       {{"noise",
         "text-like: rows of words of random 3x5 glyphs, black on white",
         "aapat: fine print, the classic case of blur in the distance",
         {{"size", "256", "texels per side"}, {"seed", "1", "random seed"}}},
        [](const Spec& s) {
          return text_noise(s.canonical(), s.whole("size", 8, kMaxTextureSide),
                            static_cast<uint64_t>(s.whole("seed", 0, 1 << 30)));
        }}});
  return kRegistry;
}

Texture make_texture(std::string_view spec) {
  Texture t = texture_registry().make(spec);
  validate(t, t.name);
  return t;
}

}  // namespace aapat
