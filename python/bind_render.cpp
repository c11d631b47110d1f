// The renderer: a scene sampled with a pattern or a per-pixel generator,
// images as (height, width) arrays, measured against the dense reference.
#include <fmt/format.h>

#include "aapat/core/filter_catalog.h"
#include "aapat/io/scene_json.h"
#include "aapat/study/render_study.h"
#include "bindings.h"

namespace aapat::python {
namespace {

// Rows top-down, as images are shown (the renderer's row 0 is the bottom).
Array image_array(const Image& img) {
  Array a({static_cast<py::ssize_t>(img.height), static_cast<py::ssize_t>(img.width)});
  auto w = a.mutable_unchecked<2>();
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) w(img.height - 1 - j, i) = img.at(i, j);
  return a;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def(
      "render",
      [](const std::string& scene, const py::object& pattern, const std::string& generator,
         int samples, const py::object& filter, std::pair<int, int> size, uint64_t seed,
         bool reference, int reference_samples, const std::string& reference_filter,
         const std::string& texture, const py::dict& options) {
        const auto [w, h] = size;
        if (!(w >= 1 && h >= 1 && w <= 16384 && h <= 16384))
          throw Error(fmt::format("render: size {}x{} is out of range 1..16384", w, h));
        RenderSettings s;
        s.width = w;
        s.height = h;
        if (pattern.is_none() == generator.empty())
          throw Error("render: give either pattern= or generator=");
        if (!pattern.is_none()) s.sampling.pattern = to_pattern(pattern);
        s.sampling.generator = generator;
        s.sampling.samples = samples;
        s.sampling.seed = seed;
        if (!filter.is_none())
          s.filter = py::isinstance<Filter>(filter) ? filter.cast<Filter>()
                                                    : make_filter(filter.cast<std::string>());
        // The sheet rows' +KEY=VALUE options, as keyword arguments.
        RenderOptions o;
        for (const auto& [key, value] : options)
          o.set(key.cast<std::string>(), py::str(value).cast<std::string>(), "render options");
        s.sampling.shading = o.shading();
        s.adaptive = o.adaptive_settings(s.sampling);
        s.measure = reference;
        s.reference = {reference_samples, reference_filter, reference_seed(seed)};
        const Scene sc = resolve_scene(scene, w, h, texture);
        RenderResult r;
        {
          py::gil_scoped_release release;
          r = render_study(sc, s);
        }
        py::dict d(py::arg("image") = image_array(r.image),
                   py::arg("samples_per_pixel") = r.stats.samples_per_pixel,
                   py::arg("lookups_per_pixel") = r.stats.lookups_per_pixel,
                   py::arg("shadings_per_pixel") = r.stats.shadings_per_pixel);
        if (r.adaptive) {
          Array map({static_cast<py::ssize_t>(h), static_cast<py::ssize_t>(w)});
          for (int j = 0; j < h; ++j)  // top row first, as the image
            for (int i = 0; i < w; ++i)
              map.mutable_at(j, i) = r.adaptive->samples[static_cast<size_t>(h - 1 - j) * w + i];
          d["refinement_map"] = map;
          d["evaluations"] = r.adaptive->evaluations;
          d["refined_fraction"] = r.adaptive->refined_fraction;
        }
        if (r.figures) {
          d["reference"] = image_array(*r.reference);
          d["rmse"] = r.figures->error.rmse;
          d["max_deviation"] = r.figures->error.max_deviation;
          d["ssim"] =
              r.figures->ssim ? py::object(py::float_(*r.figures->ssim)) : py::object(py::none());
        }
        return d;
      },
      py::arg("scene"), py::kw_only(), py::arg("pattern") = py::none(), py::arg("generator") = "",
      py::arg("samples") = 16, py::arg("filter") = py::none(),
      py::arg("size") = std::pair<int, int>{256, 256}, py::arg("seed") = 1,
      py::arg("reference") = false, py::arg("reference_samples") = 1024,
      py::arg("reference_filter") = "mitchell", py::arg("texture") = "",
      py::arg("options") = py::dict(),
      R"doc(Render a test scene, as `aapat render` does (the same pixels for the same arguments).

    scene: "checkerboard", "circles", "sliver", "spiral", "zoneplate", "disc",
        "halfplane" with :key=value parameters, or a .json scene file.
    pattern: a pattern tiled over the image (catalog name, file or aapat.Pattern),
        or generator: a per-pixel generator spec with `samples` points per pixel.
    filter: reconstruct with this filter (default: the pattern's own weights).
    size: (width, height). seed: random seed.
    reference: also render the dense reference (reference_samples jittered
        samples per pixel, a square, with reference_filter) and measure.
    texture: a .png file or a procedural texture (checker, stripes, zoneplate,
        noise) on the checkerboard's ground or a scene file's polygons with uv.
    options: the command's shading and refinement options by name, e.g.
        {"mode": "multisample", "texture-filter": "trilinear"} or
        {"adaptive": "contrast", "threshold": 0.1, "max-samples": 32}.
Returns a dict: image ((height, width), top row first, values in [0, 1]),
samples_per_pixel, lookups_per_pixel, shadings_per_pixel, with adaptive
refinement: refinement_map (samples per pixel), evaluations, refined_fraction;
with reference: reference, rmse, max_deviation, ssim.)doc");
}

}  // namespace aapat::python
