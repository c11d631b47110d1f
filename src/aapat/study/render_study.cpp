#include "aapat/study/render_study.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "aapat/core/filter_catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/pattern_json.h"
#include "aapat/render/image_flip.h"
#include "aapat/render/ssim.h"
#include "aapat/render/texture_filter.h"

namespace aapat {

Scene view_scene(Scene scene, int width, int height, double rotate_deg, double scale,
                 Vec2 translation) {
  if (!std::isfinite(rotate_deg) || !(scale > 1e-6 && scale < 1e6))
    throw Error(
        fmt::format("view: rotate {} / scale {}: need a finite angle and a scale in (1e-6, 1e6)",
                    rotate_deg, scale));
  if (!(std::abs(translation.x) <= 1e7 && std::abs(translation.y) <= 1e7))
    throw ParameterError("translate", fmt::format(" {},{}: each offset must be within 1e7 pixels",
                                                  translation.x, translation.y));
  scene.view.pivot = {(width - 1) / 2.0, (height - 1) / 2.0};
  scene.view.rotation_deg = rotate_deg;
  scene.view.scale = scale;
  scene.view.translation = translation;
  return scene;
}

RenderFigures measure(const Image& image, const Image& reference) {
  RenderFigures f{compare(image, reference), std::nullopt, flip_mean(image, reference)};
  if (image.width >= kSsimWindow && image.height >= kSsimWindow) f.ssim = ssim(image, reference);
  return f;
}

Sampling parse_sampling(const std::string& row, uint64_t seed) {
  Sampling s;
  s.seed = seed;
  if (const auto at = row.rfind('@'); at != std::string::npos) {
    s.generator = row.substr(0, at);
    const double n = parse_number(row.substr(at + 1), fmt::format("rows {}", row));
    if (!(n >= 1 && n <= 65536) || n != std::floor(n))
      throw ParameterError(
          "rows", fmt::format(" {}: the sample count must be a whole number in [1, 65536]", row));
    s.samples = static_cast<int>(n);
  } else {
    s.pattern = resolve_pattern(row);
  }
  return s;
}

void RenderOptions::set(const std::string& key, const std::string& value,
                        const std::string& where) {
  auto number = [&] { return parse_number(value, fmt::format("{} {}", where, key)); };
  auto whole = [&] {
    const double v = number();
    if (v != std::floor(v) || std::abs(v) > 1e9)
      throw Error(fmt::format("{}: {}={} is not a whole number", where, key, value));
    return static_cast<int>(v);
  };
  if (key == "mode") {
    parse_shading_mode(value);
    mode = value;
  } else if (key == "shading-point") {
    parse_shading_point(value);
    shading_point = value;
  } else if (key == "texture-filter") {
    texture_filter_registry().make(value);
    texture_filter = value;
  } else if (key == "lod") {
    parse_lod_formula(value);
    lod = value;
  } else if (key == "mipmap") {
    parse_mipmap_kind(value);
    mipmap = value;
  } else if (key == "adaptive") {
    parse_refinement_criterion(value);
    adaptive = value;
  } else if (key == "threshold") {
    threshold = number();
  } else if (key == "max-depth") {
    max_depth = whole();
  } else if (key == "max-samples") {
    max_samples = whole();
  } else if (key == "per-square") {
    per_square = whole();
  } else if (key == "label") {
    label = value;
  } else if (key == "show") {
    if (value != "image" && value != "map")
      throw Error(fmt::format("{}: show={}: use image or map", where, value));
    show_map = value == "map";
  } else {
    throw Error(
        fmt::format("{}: unknown option '{}' (mode, shading-point, texture-filter, lod, "
                    "mipmap, adaptive, threshold, max-depth, max-samples, per-square, show, label)",
                    where, key));
  }
}

Shading RenderOptions::shading() const {
  Shading s;
  s.mode = parse_shading_mode(mode);
  s.point = parse_shading_point(shading_point);
  s.texture =
      make_texture_filter(texture_filter, parse_lod_formula(lod), parse_mipmap_kind(mipmap));
  return s;
}

std::optional<AdaptiveSettings> RenderOptions::adaptive_settings(const Sampling& initial) const {
  if (adaptive.empty()) return std::nullopt;
  AdaptiveSettings a;
  a.initial = initial;
  a.criterion = parse_refinement_criterion(adaptive);
  a.threshold = threshold;
  a.max_depth = max_depth;
  a.max_samples = max_samples;
  a.per_square = per_square;
  validate(a);
  return a;
}

std::string split_options(const std::string& text, RenderOptions& options) {
  const size_t plus = text.find('+');
  if (plus == std::string::npos) return text;
  size_t at = plus;
  while (at < text.size()) {
    const size_t next = std::min(text.find('+', at + 1), text.size());
    const std::string item = text.substr(at + 1, next - at - 1);
    const size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error(fmt::format("{}: '+{}' is not KEY=VALUE", text, item));
    options.set(item.substr(0, eq), item.substr(eq + 1), text);
    at = next;
  }
  return text.substr(0, plus);
}

namespace {

// The rendering of one sampling: refined when asked, else the renderer's.
void render_one(const Scene& scene, int width, int height, const Sampling& sampling,
                const std::optional<Filter>& filter,
                const std::optional<AdaptiveSettings>& adaptive, Image& image, RenderStats& stats,
                std::optional<AdaptiveImage>& refined) {
  if (!adaptive) {
    image = render(scene, width, height, sampling, filter, &stats);
    return;
  }
  refined = render_adaptive(scene, width, height, *adaptive, filter);
  image = refined->image;
  stats.samples_per_pixel = refined->average_samples;
  stats.shadings_per_pixel = double(refined->evaluations) / (double(width) * height);
}

}  // namespace

void validate(const RenderSettings& s) {
  if (s.width < 1 || s.height < 1 || s.width > kMaxImageSide || s.height > kMaxImageSide)
    throw ParameterError("size", fmt::format(" {}x{}: each side must be 1 to {} pixels", s.width,
                                             s.height, kMaxImageSide));
  if (s.sampling.pattern.has_value() == !s.sampling.generator.empty())
    throw Error("render: give either a pattern or a per-pixel generator, not both");
  if (!s.sampling.generator.empty()) {
    make_point_generator(s.sampling.generator);  // an unknown generator is named first
    if (!s.filter)
      throw ParameterError("generator",
                           fmt::format(" {}: per-pixel points have no weights of their own; give "
                                       "a filter",
                                       s.sampling.generator));
  }
}

RenderResult render_study(const Scene& scene, const RenderSettings& s,
                          const ReferenceSource& references) {
  validate(s);
  RenderResult r;
  render_one(scene, s.width, s.height, s.sampling, s.filter, s.adaptive, r.image, r.stats,
             r.adaptive);
  if (s.measure) {
    r.reference = references(scene, s.width, s.height, s.reference, r.image.offset);
    r.figures = measure(r.image, *r.reference);
  }
  return r;
}

std::vector<RenderGridCell> render_grid(const Scene& scene, const RenderGridSettings& s,
                                        const ReferenceSource& references,
                                        const StudyProgress& progress) {
  std::map<double, Image> reference_at;  // by offset: even footprints shift the image
  std::vector<RenderGridCell> cells;
  const int total = static_cast<int>(s.rows.size() * s.columns.size());
  for (const std::string& row : s.rows) {
    RenderOptions row_options;
    const std::string row_base = split_options(row, row_options);
    for (const std::string& column : s.columns) {
      RenderOptions options = row_options;
      const std::string column_base = split_options(column, options);
      Sampling sampling = parse_sampling(row_base, s.seed);
      sampling.shading = options.shading();
      std::optional<Filter> filter;
      if (column_base != "weights") filter = make_filter(column_base);
      if (!filter && !sampling.pattern)
        throw ParameterError(
            "columns",
            fmt::format(" weights: row '{}' is a generator, which has no weights of its own", row));
      const std::optional<AdaptiveSettings> adaptive = options.adaptive_settings(sampling);
      RenderGridCell cell{row, column, sampling, {}, {}, {}, {}, options.show_map};
      render_one(scene, s.width, s.height, sampling, filter, adaptive, cell.image, cell.stats,
                 cell.adaptive);
      auto it = reference_at.find(cell.image.offset);
      if (it == reference_at.end())
        it = reference_at
                 .emplace(cell.image.offset,
                          references(scene, s.width, s.height, s.reference, cell.image.offset))
                 .first;
      cell.figures = measure(cell.image, it->second);
      cells.push_back(std::move(cell));
      if (progress)
        progress(static_cast<int>(cells.size()), total, fmt::format("{} {}", row, column));
    }
  }
  return cells;
}

}  // namespace aapat
