#include "aapat/render/reference.h"

#include <fmt/format.h>

#include <algorithm>

#include "aapat/core/filter_catalog.h"
#include "aapat/render/color_render.h"
#include "aapat/work/byte_codec.h"

namespace aapat {

Image render_reference(const Scene& scene, int width, int height, const ReferenceSettings& r,
                       double offset) {
  return render_reference_reporting(scene, width, height, r, offset, {});
}

Image render_reference_reporting(const Scene& scene, int width, int height,
                                 const ReferenceSettings& r, double offset,
                                 const ItemsProgress& progress) {
  if (r.samples < 1 || r.samples > kMaxSamplesPerPixel)
    throw ParameterError("reference-samples", fmt::format(" {}: expected 1 to {} per pixel",
                                                          r.samples, kMaxSamplesPerPixel));
  Sampling s;
  s.generator = "jittered";
  s.samples = r.samples;
  s.seed = r.seed;
  const Filter filter = make_filter(r.filter);
  if (width < 1 || height < 1) return render(scene, width, height, s, filter, nullptr, offset);
  // Each block of rows is a work item (work/work_items.h): a reference may be
  // rendered by many processes, the same bits as by one.
  // Bands of 32 rows: each draws its filter's reach of rows above and below
  // it as well, so taller bands draw fewer twice.
  constexpr int kBandRows = 4 * kRenderBlockRows;
  const int bands = (height + kBandRows - 1) / kBandRows;
  const std::vector<std::string> rows = run_work_items(
      bands,
      [&](int band) {
        const int j0 = band * kBandRows;
        const Image part = render_rows(scene, width, height, s, filter, offset, j0,
                                       std::min(height, j0 + kBandRows));
        ByteWriter w;
        w.put_all(part.values);
        return w.take();
      },
      progress);
  Image img{width, height, offset, {}, scene_channels(scene)};
  img.values.reserve(static_cast<size_t>(width) * height * static_cast<size_t>(img.channels));
  for (const std::string& band : rows) {
    ByteReader reader(band);
    const std::vector<double> values = reader.get_all<double>();
    img.values.insert(img.values.end(), values.begin(), values.end());
  }
  return img;
}

std::string describe_reference(const ReferenceSettings& settings) {
  return fmt::format("{} jittered samples per pixel, {}", settings.samples,
                     make_filter(settings.filter).name());
}

uint64_t reference_seed(uint64_t render_seed) {
  return render_seed + 1000003;
}

uint64_t frame_reference_seed(uint64_t reference_seed, int frame) {
  return reference_seed + 7919 * static_cast<uint64_t>(static_cast<int64_t>(frame) + 1);
}

}  // namespace aapat
