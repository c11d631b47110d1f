// The renderer: a scene sampled with a pattern or a per-pixel generator,
// images as (height, width) arrays, measured against the dense reference.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "aapat/analyze/flip.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/io/png_image.h"
#include "aapat/io/scene_json.h"
#include "aapat/render/animation.h"
#include "aapat/render/image_flip.h"
#include "aapat/study/study_json.h"
#include "aapat/temporal/engine/engine_json.h"
#include "aapat/temporal/engine/engine_taa.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "bindings.h"

namespace aapat::python {
namespace {

// Rows top-down, as images are shown (the renderer's row 0 is the bottom).
// Rows from the top; a colour rendering (a mesh scene) is (h, w, 3).
Array image_array(const Image& img) {
  if (img.channels == 1) {
    Array a({static_cast<py::ssize_t>(img.height), static_cast<py::ssize_t>(img.width)});
    auto w = a.mutable_unchecked<2>();
    for (int j = 0; j < img.height; ++j)
      for (int i = 0; i < img.width; ++i) w(img.height - 1 - j, i) = img.at(i, j);
    return a;
  }
  Array a({static_cast<py::ssize_t>(img.height), static_cast<py::ssize_t>(img.width),
           static_cast<py::ssize_t>(img.channels)});
  auto w = a.mutable_unchecked<3>();
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i)
      for (int c = 0; c < img.channels; ++c)
        w(img.height - 1 - j, i, c) =
            img.values[(static_cast<size_t>(j) * img.width + i) * img.channels + c];
  return a;
}

// An (h, w) grey or (h, w, 3) sRGB array in [0, 1] as a colour image. The
// shape and the pixel limit are checked on the array as given, before any
// conversion to doubles allocates a copy (`aapat diff`'s limit on a PNG).
ColorImage color_image(const py::array& given, const char* what) {
  if (!((given.ndim() == 2) || (given.ndim() == 3 && given.shape(2) == 3)) || given.size() == 0) {
    std::vector<py::ssize_t> shape(given.shape(), given.shape() + given.ndim());
    throw Error(
        fmt::format("diff: {} must be an (h, w) grey or (h, w, 3) RGB array, not of shape ({})",
                    what, fmt::join(shape, ", ")));
  }
  const auto pixels = static_cast<size_t>(given.shape(0)) * static_cast<size_t>(given.shape(1));
  if (pixels > kMaxColorImagePixels)
    throw Error(fmt::format("diff: {} has {}x{} pixels; at most {} (docs/limits.md)", what,
                            given.shape(1), given.shape(0), kMaxColorImagePixels));
  const Array a = Array::ensure(given);
  if (!a) throw Error(fmt::format("diff: {} is not an array of numbers", what));
  const int h = static_cast<int>(a.shape(0)), w = static_cast<int>(a.shape(1));
  ColorImage img{w, h, std::vector<float>(static_cast<size_t>(w) * h * 3)};
  const double* v = a.data();
  const int channels = a.ndim() == 3 ? 3 : 1;
  for (size_t p = 0; p < img.pixels(); ++p)
    for (int c = 0; c < 3; ++c) {
      const double x = v[p * channels + (channels == 3 ? c : 0)];
      // Quantized as render's FLIP and a PNG quantize (render/image_flip.h):
      // a filtered reference's small overshoot is clamped as render clamps it.
      if (!(x >= -kMaxOvershoot && x <= 1 + kMaxOvershoot))
        throw Error(fmt::format(
            "diff: {} holds {} at pixel {}; values must be in [0, 1] (an overshoot of up to {} "
            "past either end, a filtered image's, is clamped)",
            what, x, p, kMaxOvershoot));
      img.rgb[3 * p + c] = stored_value(x);
    }
  return img;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def(
      "read_image",
      [](const std::string& path) {
        const ColorImage img = read_png_color(path, "image").image;
        Array out({static_cast<py::ssize_t>(img.height), static_cast<py::ssize_t>(img.width),
                   py::ssize_t{3}});
        std::copy(img.rgb.begin(), img.rgb.end(), out.mutable_data());
        return out;
      },
      py::arg("path"),
      R"doc(A PNG file (grey or colour, 8 or 16 bits; alpha dropped, as `aapat diff`
reads it) as an (h, w, 3) array of sRGB values in [0, 1], top row first.)doc");

  m.def(
      "diff",
      [](const py::array& reference, const py::array& test, double ppd) {
        const ColorImage ref = color_image(reference, "reference"), tst = color_image(test, "test");
        const auto d = interruptible([&] { return image_diff(ref, tst, ppd); });
        py::dict out = values_of(diff_json("", "", d));
        Array map(
            {static_cast<py::ssize_t>(d.flip.height), static_cast<py::ssize_t>(d.flip.width)});
        std::copy(d.flip.map.begin(), d.flip.map.end(), map.mutable_data());
        out["map"] = map;
        return out;
      },
      py::arg("reference"), py::arg("test"), py::kw_only(),
      py::arg("ppd") = default_pixels_per_degree(),
      R"doc(How `test` differs from `reference`, as `aapat diff` measures it.

Both are (h, w) grey or (h, w, 3) sRGB arrays with values in [0, 1], the same
size. Returns the values of `aapat diff --json`: width, height, ppd, rmse
and psnr (over the channels, on the 8-bit scale), ssim, and FLIP (Andersson
et al. 2020): flip (the mean), flip_min, flip_max, flip_weighted_q1,
flip_weighted_median, flip_weighted_q3, flip_histogram; and map, the per-pixel
FLIP as an (h, w) array.

    ppd: the observer's pixels per degree (default 67.02: 0.7 m from a 0.7 m
        wide 3840-pixel screen).)doc");

  m.def(
      "render",
      [](const std::string& scene, const py::object& pattern, const std::string& generator,
         int samples, const py::object& filter, std::pair<int, int> size, uint64_t seed,
         bool reference, int reference_samples, const std::string& reference_filter,
         const std::string& texture, const py::dict& options) {
        const auto [w, h] = size;
        RenderSettings s;
        s.width = w;
        s.height = h;
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
        validate(s);  // the library's one check, before the scene is read
        const Scene sc = resolve_scene(scene, w, h, texture);
        const auto r = interruptible([&] { return render_study(sc, s); });
        // The values of `aapat render --json`, with the images as arrays.
        py::dict d = values_of(render_json(scene, sc, texture, pattern_name, s, r));
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

  m.def(
      "engine_taa",
      [](const std::string& scene, const std::string& taa, double ratio, const std::string& motion,
         const py::object& sequence, const py::dict& settings, std::pair<int, int> size, int frames,
         int warmup, bool cut, int reference_samples, const std::string& reference_filter,
         uint64_t seed, bool images) {
        const auto [w, h] = size;
        check_animation_work(w, h, frames + std::max(warmup, 0));  // the library's one check
        const EngineTaa t = make_engine_taa(taa, ratio, taa_overrides_of(settings));
        const Sequence s =
            sequence.is_none() ? resolve_sequence(t.jitter)
            : py::isinstance<Sequence>(sequence)
                ? sequence.cast<Sequence>()
                : resolve_sequence_for_ratio(sequence.cast<std::string>(), ratio, nullptr);
        EngineRun run;
        run.scene = resolve_scene(scene, w, h);
        run.motion = make_motion(motion, w, h);
        run.width = w;
        run.height = h;
        run.frames = frames;
        run.warmup = cut ? 0 : warmup;
        run.reference = {reference_samples, reference_filter, seed};
        std::vector<Image> shown;
        const auto r = interruptible([&] {
          return render_engine_taa(run, s, t, [&](int, const Image& img) {
            if (images) shown.push_back(img);
          });
        });
        py::dict d = values_of(engine_taa_json(scene, run, s, t, r));
        if (images) {
          py::list list;
          for (const Image& img : shown) list.append(image_array(img));
          d["images"] = list;
        }
        return d;
      },
      py::arg("scene"), py::kw_only(), py::arg("taa") = "fsr2", py::arg("ratio") = 1.0,
      py::arg("motion") = "pan", py::arg("sequence") = py::none(), py::arg("settings") = py::dict(),
      py::arg("size") = std::pair<int, int>{EngineRun{}.width, EngineRun{}.height},
      py::arg("frames") = EngineRun{}.frames, py::arg("warmup") = EngineRun{}.warmup,
      py::arg("cut") = false, py::arg("reference_samples") = AnimationSettings{}.reference.samples,
      py::arg("reference_filter") = AnimationSettings{}.reference.filter,
      py::arg("seed") = AnimationSettings{}.reference.seed, py::arg("images") = false,
      R"doc(Engine TAA, as `aapat animate SCENE --taa PRESET` renders it (docs/temporal.md).

    scene: any scene render takes. taa: ue4, fsr2, godot, bevy or custom.
    ratio: display / render resolution (>= 1). motion: pan:dx=,dy=, rotate:deg=, static.
    sequence: a spec, name, file or aapat.Sequence (default: the preset's jitter;
        a generator without frames= takes int(8 ratio^2) phases).
    settings: overrides by key, e.g. {"history": "catmull-rom-9", "gamma": 1.25}.
    warmup: frames before the measured ones (cut=True: none).
Returns the values of `aapat animate --taa --json` (rmse, flicker, ghosting,
sharpness, mean_flip, rows, ...), and with images=True the frames as arrays.)doc");
}

}  // namespace aapat::python
