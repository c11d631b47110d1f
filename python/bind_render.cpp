// The renderer: a scene sampled with a pattern or a per-pixel generator,
// images as (height, width) arrays, measured against the dense reference.
#include <fmt/format.h>

#include "aapat/core/filter_catalog.h"
#include "aapat/io/scene_json.h"
#include "aapat/study/study_json.h"
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
        const std::string pattern_name = pattern.is_none() ? ""
                                         : py::isinstance<py::str>(pattern)
                                             ? pattern.cast<std::string>()
                                             : s.sampling.pattern->name;
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
        // The values of `aapat render --json`, with the images as arrays.
        py::dict d = values_of(render_json(scene, texture, pattern_name, s, r));
        d["image"] = image_array(r.image);
        if (r.adaptive) {
          Array map({static_cast<py::ssize_t>(h), static_cast<py::ssize_t>(w)});
          for (int j = 0; j < h; ++j)  // top row first, as the image
            for (int i = 0; i < w; ++i)
              map.mutable_at(j, i) = r.adaptive->samples[static_cast<size_t>(h - 1 - j) * w + i];
          d["refinement_map"] = map;
        }
        if (r.reference) d["reference_image"] = image_array(*r.reference);
        return d;
      },
      py::arg("scene"), py::kw_only(), py::arg("pattern") = py::none(), py::arg("generator") = "",
      // The defaults are the library's (default-constructed settings).
      py::arg("samples") = Sampling{}.samples, py::arg("filter") = py::none(),
      py::arg("size") = std::pair<int, int>{RenderSettings{}.width, RenderSettings{}.height},
      py::arg("seed") = Sampling{}.seed, py::arg("reference") = RenderSettings{}.measure,
      py::arg("reference_samples") = ReferenceSettings{}.samples,
      py::arg("reference_filter") = ReferenceSettings{}.filter, py::arg("texture") = "",
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
Returns the values of `aapat render --json` (scene, width, height, filter,
samples_per_pixel, mode, lookups_per_pixel, shadings_per_pixel, ...; with
adaptive refinement its "adaptive" dict; with reference: reference (what it
is), rmse, max_deviation, ssim) and the images as arrays: image ((height,
width), top row first, values in [0, 1]), reference_image, refinement_map
(samples per pixel).)doc");
}

}  // namespace aapat::python
