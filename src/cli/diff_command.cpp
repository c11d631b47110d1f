// `aapat diff REFERENCE TEST`: how a test image differs from its reference,
// by RMSE, PSNR and SSIM and by FLIP, the perceived difference (mean,
// weighted quartiles and extremes); optionally the FLIP map as a PNG.
#include <fmt/format.h>
#include <tbb/parallel_invoke.h>

#include <exception>
#include <memory>
#include <ostream>

#include "aapat/core/read_file.h"
#include "aapat/io/flip_map.h"
#include "aapat/io/png_image.h"
#include "aapat/study/study_json.h"
#include "cli/app.h"
#include "cli/commands.h"

namespace aapat {
namespace {

struct DiffOptions {
  std::string reference, test, map;
  double ppd = default_pixels_per_degree();
  bool json = false;
};

// A missing value (equal images have no PSNR) prints as "-".
std::string number(const JsonObject& v, const char* format) {
  return v.is_null() ? "-" : fmt::format(fmt::runtime(format), v.get<double>());
}

void run_diff(const DiffOptions& o, std::ostream& out) {
  if (!o.map.empty() && !o.map.ends_with(".png"))
    throw Error(fmt::format("--map: '{}' must end in .png", o.map));
  // Both headers first: images of two sizes are refused, naming both files,
  // before either is decoded.
  const std::string reference_bytes = read_file(o.reference, "reference image", kMaxPngFileBytes);
  const std::string test_bytes = read_file(o.test, "test image", kMaxPngFileBytes);
  const auto rs = png_dimensions(reference_bytes), ts = png_dimensions(test_bytes);
  if (rs && ts && *rs != *ts)
    throw Error(fmt::format(
        "the reference image '{}' is {}x{} pixels and the test image '{}' is {}x{}: they must "
        "be the same size",
        o.reference, rs->first, rs->second, o.test, ts->first, ts->second));
  // Decoded side by side (inflate is a large part of a diff); a failure of
  // the reference is reported before one of the test, whichever came first.
  PngColor reference, test;
  std::exception_ptr reference_error, test_error;
  const auto decode = [](const std::string& bytes, const std::string& path, const char* what,
                         PngColor& image, std::exception_ptr& error) {
    try {
      image = decode_png_color(bytes, path, what);
    } catch (...) {
      error = std::current_exception();
    }
  };
  tbb::parallel_invoke(
      [&] { decode(reference_bytes, o.reference, "reference image", reference, reference_error); },
      [&] { decode(test_bytes, o.test, "test image", test, test_error); });
  if (reference_error) std::rethrow_exception(reference_error);
  if (test_error) std::rethrow_exception(test_error);
  auto note_alpha = [](const PngColor& image, const std::string& path) {
    if (image.had_alpha)
      warnings() << fmt::format(
          "aapat: warning: '{}' has an alpha channel; it is ignored and the colour stored is "
          "compared (as FLIP's reference tool does)\n",
          path);
  };
  note_alpha(reference, o.reference);
  note_alpha(test, o.test);
  const ImageDiff d = image_diff(reference.image, test.image, o.ppd);
  if (!o.map.empty()) {
    const RgbRaster r = flip_map_with_scale(d.flip.map, d.flip.width, d.flip.height);
    write_png_rgb(o.map, r.width, r.height, r.pixels);
  }
  // The document is the result; the text is printed from it.
  const JsonObject doc = diff_json(o.reference, o.test, d);
  if (o.json) {
    out << json_text(doc);
    return;
  }
  out << fmt::format("{} against {}, {}x{}, {:.1f} pixels per degree\n", o.test, o.reference,
                     doc["width"].get<int>(), doc["height"].get<int>(), doc["ppd"].get<double>());
  out << fmt::format("  RMSE {:.3f} levels, PSNR {} dB, SSIM {}\n", doc["rmse"].get<double>(),
                     number(doc["psnr"], "{:.2f}"), number(doc["ssim"], "{:.4f}"));
  out << fmt::format(
      "  FLIP mean {:.6f}; weighted quartiles {:.4f} {:.4f} {:.4f}; min {:.4f}, max {:.4f}\n",
      doc["flip"].get<double>(), doc["flip_weighted_q1"].get<double>(),
      doc["flip_weighted_median"].get<double>(), doc["flip_weighted_q3"].get<double>(),
      doc["flip_min"].get<double>(), doc["flip_max"].get<double>());
  if (!o.map.empty()) out << "wrote " << o.map << "\n";
}

}  // namespace

Action add_diff_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "diff", "how a test image differs from its reference: RMSE, PSNR, SSIM and FLIP");
  auto o = std::make_shared<DiffOptions>();
  cmd->add_option("reference", o->reference, "the reference image (PNG)")->required();
  cmd->add_option("test", o->test, "the test image (PNG, the same size)")->required();
  cmd->add_option("--ppd", o->ppd,
                  "the observer's pixels per degree (default: 0.7 m from a 0.7 m wide 3840-pixel "
                  "screen)")
      ->capture_default_str();
  cmd->add_option("--map", o->map, "write the FLIP map with its colour scale (.png)");
  cmd->add_flag("--json", o->json, "print JSON (docs/json.md)");
  return [o](std::ostream& out) { run_diff(*o, out); };
}

}  // namespace aapat
