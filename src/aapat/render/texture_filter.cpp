#include "aapat/render/texture_filter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace aapat {
namespace {

// s in level-0 texels to the same place in level `level` (whose size is
// rounded up at every halving, so the ratio is exact, not a power of 2).
double to_level(double s, const Texture& level0, const Texture& level, bool horizontal) {
  return horizontal ? s * level.width / level0.width : s * level.height / level0.height;
}

// Wrapped into [0, n): far coordinates (near a horizon) stay exact enough
// and never reach an integer conversion.
double wrap(double x, int n) {
  return x - n * std::floor(x / n);
}

Texture halve_box(const Texture& fine) {
  const int w = (fine.width + 1) / 2, h = (fine.height + 1) / 2;
  Texture coarse{fine.name, w, h, std::vector<double>(static_cast<size_t>(w) * h)};
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      double sum = 0;
      int count = 0;
      for (int dj = 0; dj < 2; ++dj)
        for (int di = 0; di < 2; ++di)
          if (2 * i + di < fine.width && 2 * j + dj < fine.height) {
            sum += fine.texels[static_cast<size_t>(2 * j + dj) * fine.width + 2 * i + di];
            ++count;
          }
      coarse.texels[static_cast<size_t>(j) * w + i] = sum / count;
    }
  return coarse;
}

// The binomial [1 3 3 1] / 8 centred between children 2i and 2i + 1, along x
// then along y, wrapping (the texture repeats).
Texture halve_gaussian(const Texture& fine) {
  const int w = (fine.width + 1) / 2, h = (fine.height + 1) / 2;
  constexpr double kTaps[4] = {1.0 / 8, 3.0 / 8, 3.0 / 8, 1.0 / 8};
  std::vector<double> rows(static_cast<size_t>(w) * fine.height);
  for (int j = 0; j < fine.height; ++j)
    for (int i = 0; i < w; ++i) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += kTaps[k] * fine.at(2 * i - 1 + k, j);
      rows[static_cast<size_t>(j) * w + i] = sum;
    }
  Texture coarse{fine.name, w, h, std::vector<double>(static_cast<size_t>(w) * h)};
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) {
        int r = (2 * j - 1 + k) % fine.height;
        if (r < 0) r += fine.height;
        sum += kTaps[k] * rows[static_cast<size_t>(r) * w + i];
      }
      coarse.texels[static_cast<size_t>(j) * w + i] = sum;
    }
  return coarse;
}

int nearest_level(double lod, int last) {
  return static_cast<int>(std::clamp(std::floor(lod + 0.5), 0.0, double(last)));
}

}  // namespace

Mipmap build_mipmap(const Texture& texture, MipmapKind kind) {
  Mipmap m;
  m.levels.push_back(texture);
  while (m.levels.back().width > 1 || m.levels.back().height > 1)
    m.levels.push_back(kind == MipmapKind::box ? halve_box(m.levels.back())
                                               : halve_gaussian(m.levels.back()));
  return m;
}

double level_of_detail(const TextureJacobian& j, LodFormula formula) {
  const double size =
      formula == LodFormula::max
          ? std::max({std::abs(j.dsdx), std::abs(j.dtdx), std::abs(j.dsdy), std::abs(j.dtdy)})
          : std::sqrt(j.dsdx * j.dsdx + j.dtdx * j.dtdx + j.dsdy * j.dsdy + j.dtdy * j.dtdy);
  return std::log2(size);
}

double bilinear(const Mipmap& m, int level, double s, double t) {
  const Texture& tex = m.levels[static_cast<size_t>(level)];
  const double x = wrap(to_level(s, m.levels[0], tex, true) - 0.5, tex.width);
  const double y = wrap(to_level(t, m.levels[0], tex, false) - 0.5, tex.height);
  const double fx = std::floor(x), fy = std::floor(y);
  const int i = static_cast<int>(fx), j = static_cast<int>(fy);
  const double a = x - fx, b = y - fy;
  return (1 - b) * ((1 - a) * tex.at(i, j) + a * tex.at(i + 1, j)) +
         b * ((1 - a) * tex.at(i, j + 1) + a * tex.at(i + 1, j + 1));
}

double trilinear(const Mipmap& m, double level, double s, double t) {
  const int last = static_cast<int>(m.levels.size()) - 1;
  const double l = std::clamp(std::isnan(level) ? 0.0 : level, 0.0, double(last));
  const int l0 = static_cast<int>(std::floor(l));
  const double f = l - l0;
  if (l0 >= last || f == 0) return bilinear(m, l0, s, t);
  return (1 - f) * bilinear(m, l0, s, t) + f * bilinear(m, l0 + 1, s, t);
}

TexturedSurface::TexturedSurface(Texture t)
    : texture(std::move(t)), box(build_mipmap(texture, MipmapKind::box)) {}

const Mipmap& TexturedSurface::pyramid(MipmapKind kind) const {
  if (kind == MipmapKind::box) return box;
  std::call_once(gaussian_built_, [&] { gaussian_ = build_mipmap(texture, MipmapKind::gaussian); });
  return gaussian_;
}

double filtered_value(const TexturedSurface& surface, const TextureFilter& filter, double s,
                      double t, const TextureJacobian& j, int* probes) {
  if (!std::isfinite(s) || !std::isfinite(t)) return 0.0;  // scene files refuse these first
  const Mipmap& m = surface.pyramid(filter.mipmap);
  const int last = static_cast<int>(m.levels.size()) - 1;
  int lookups = 1;
  double value = 0;
  switch (filter.lookup) {
    case TextureLookup::nearest:
      value = surface.texture.exact(s, t);
      break;
    case TextureLookup::bilinear:
      value = bilinear(m, 0, s, t);
      break;
    case TextureLookup::mip_nearest: {
      const int level = nearest_level(level_of_detail(j, filter.lod), last);
      const Texture& tex = m.levels[static_cast<size_t>(level)];
      value = tex.exact(to_level(s, m.levels[0], tex, true), to_level(t, m.levels[0], tex, false));
      break;
    }
    case TextureLookup::mip_bilinear:
      value = bilinear(m, nearest_level(level_of_detail(j, filter.lod), last), s, t);
      break;
    case TextureLookup::trilinear:
      value = trilinear(m, level_of_detail(j, filter.lod), s, t);
      break;
    case TextureLookup::aniso: {
      // The footprint's axes; the level from the major axis divided among
      // the probes, which lie evenly along it.
      const double x_len = std::hypot(j.dsdx, j.dtdx), y_len = std::hypot(j.dsdy, j.dtdy);
      const bool x_major = x_len >= y_len;
      const double major = std::max(x_len, y_len), minor = std::min(x_len, y_len);
      const double ds = x_major ? j.dsdx : j.dsdy, dt = x_major ? j.dtdx : j.dtdy;
      const double ratio = minor > 0 ? major / minor : (major > 0 ? filter.probes : 1.0);
      lookups = static_cast<int>(std::clamp(std::ceil(ratio), 1.0, double(filter.probes)));
      const double level = std::log2(major / lookups);
      for (int k = 0; k < lookups; ++k) {
        const double offset = (k + 0.5) / lookups - 0.5;
        value += trilinear(m, level, s + offset * ds, t + offset * dt);
      }
      value /= lookups;
      break;
    }
  }
  if (probes) *probes += lookups;
  return value;
}

const TextureFilterRegistry& texture_filter_registry() {
  auto simple = [](TextureLookup lookup, const char* name) {
    return [lookup, name](const Spec&) {
      TextureFilter f;
      f.lookup = lookup;
      f.name = name;
      return f;
    };
  };
  static const TextureFilterRegistry kRegistry(
      "texture filter",
      {{{"nearest",
         "the texel holding the point: the exact, unfiltered value",
         "CS4620 Lecture 23",
         {}},
        simple(TextureLookup::nearest, "nearest")},
       {{"bilinear",
         "bilinear between the 4 nearest texels of the finest level",
         "CS4620 Lecture 23",
         {}},
        simple(TextureLookup::bilinear, "bilinear")},
       {{"mip-nearest",
         "the nearest texel of the nearest level (mipmapped point sampling)",
         "CS4620 Lecture 23 ('point sampling (but still better)')",
         {}},
        simple(TextureLookup::mip_nearest, "mip-nearest")},
       {{"mip-bilinear", "bilinear in the nearest level", "CS4620 Lecture 23", {}},
        simple(TextureLookup::mip_bilinear, "mip-bilinear")},
       {{"trilinear",
         "bilinear in the two levels around the level of detail, blended linearly",
         "CS4620 Lecture 23 (Williams 1983)",
         {}},
        simple(TextureLookup::trilinear, "trilinear")},
       {{"aniso",
         "trilinear probes along the footprint's major axis, the level from the major axis over "
         "the probes",
         "hardware anisotropic filtering (EXT_texture_filter_anisotropic)",
         {{"probes", "8", "the most probes (the largest anisotropy served)"}}},
        [](const Spec& s) {
          TextureFilter f;
          f.lookup = TextureLookup::aniso;
          f.probes = s.whole("probes", 1, 64);
          f.name = s.canonical();
          return f;
        }}});
  return kRegistry;
}

TextureFilter make_texture_filter(std::string_view spec, LodFormula lod, MipmapKind mipmap) {
  TextureFilter f = texture_filter_registry().make(spec);
  f.lod = lod;
  f.mipmap = mipmap;
  return f;
}

LodFormula parse_lod_formula(std::string_view text) {
  if (text == "max") return LodFormula::max;
  if (text == "root-sum-squares") return LodFormula::root_sum_squares;
  throw ParameterError("lod", fmt::format(" '{}': use max or root-sum-squares", text));
}

MipmapKind parse_mipmap_kind(std::string_view text) {
  if (text == "box") return MipmapKind::box;
  if (text == "gaussian") return MipmapKind::gaussian;
  throw ParameterError("mipmap", fmt::format(" '{}': use box or gaussian", text));
}

}  // namespace aapat
