#include "aapat/study/render_study.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "aapat/core/filter_catalog.h"
#include "aapat/io/pattern_json.h"
#include "aapat/render/ssim.h"

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
  RenderFigures f{compare(image, reference), std::nullopt};
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

RenderResult render_study(const Scene& scene, const RenderSettings& s,
                          const ReferenceSource& references) {
  RenderResult r;
  r.image = render(scene, s.width, s.height, s.sampling, s.filter, &r.stats);
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
    const Sampling sampling = parse_sampling(row, s.seed);
    for (const std::string& column : s.columns) {
      std::optional<Filter> filter;
      if (column != "weights") filter = make_filter(column);
      if (!filter && !sampling.pattern)
        throw ParameterError(
            "columns",
            fmt::format(" weights: row '{}' is a generator, which has no weights of its own", row));
      RenderGridCell cell{row, column, sampling, {}, {}, {}};
      cell.image = render(scene, s.width, s.height, sampling, filter, &cell.stats);
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
