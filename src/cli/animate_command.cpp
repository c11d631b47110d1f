// `aapat animate`: an animation rendered with a pattern against a dense
// reference (Hasselgren et al. Sec. 6.1): RMSE and max deviation over all
// frames; the frames as PNGs, a GIF or an MP4.
#include <fmt/format.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <ostream>

#include "aapat/core/filter_catalog.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/gif_animation.h"
#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/png_image.h"
#include "aapat/io/scene_json.h"
#include "aapat/temporal/engine/engine_json.h"
#include "aapat/temporal/engine/engine_taa.h"
#include "aapat/temporal/engine/taa_render.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "cli/animation_options.h"
#include "cli/commands.h"
#include "cli/option_modes.h"
#include "cli/progress.h"
#include "cli/sequence_options.h"

namespace aapat {
namespace {

// --mp4 needs ffmpeg: asked before any frame is rendered.
void check_ffmpeg(const std::string& path) {
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0)
    throw Error(
        fmt::format("--mp4 {}: needs ffmpeg on the PATH (apt-get install ffmpeg); --gif "
                    "needs nothing",
                    path));
}

// MP4 through ffmpeg, from the frames' PNGs in `dir`; written whole or not at all.
void write_mp4(const std::string& dir, const std::string& path, int fps, int frames) {
  const std::string tmp = path + ".tmp.mp4";
  const std::string command = fmt::format(
      "ffmpeg -y -loglevel error -framerate {} -i '{}/frame-%0{}d.png' -vf "
      "'scale=trunc(iw/2)*2:trunc(ih/2)*2:flags=neighbor' -pix_fmt yuv420p '{}'",
      fps, dir, frame_digits(frames), tmp);
  if (std::system(command.c_str()) != 0 || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error(fmt::format("--mp4 {}: ffmpeg failed ({})", path, command));
  }
}

// An earlier run's frames in `dir` that this run of `frames` frames does not
// write (a longer run's, or another digit count's): removed when it commits.
void stale_frames_removed_at_commit(const std::string& dir, int frames) {
  std::error_code e;
  for (const auto& entry : std::filesystem::directory_iterator(dir, e)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with("frame-") || !name.ends_with(".png")) continue;
    const std::string digits = name.substr(6, name.size() - 10);
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const bool ours = static_cast<int>(digits.size()) == frame_digits(frames) &&
                      digits.size() < 10 && std::stoi(digits) < frames;
    if (!ours) remove_file_at_commit(entry.path().string());
  }
}

struct AnimateOptions : AnimationOptions {
  std::string pattern, filter, frames_dir, histogram, gif, mp4;
  int fps = 12;
  bool json = false;
  // Temporal mode: a sequence accumulated by a model.
  std::string sequence, csv;
  ModelOptions model;
  bool cut = false, still = false;
  // Any scene and its motion; engine TAA (--taa) at a render scale.
  std::string motion, taa;
  std::vector<std::string> taa_set;
  double ratio = 1;
  int warmup = -1;
};

bool is_builtin_animation(const std::string& name) {
  return name == "circle" || name == "triangle";
}

// The scene of a scene spec or file and its motion (pan by default; --motion
// static: none). A built-in animation holds still only in temporal mode.
void resolve_moving_scene(AnimateOptions& o, AnimationSettings& a) {
  if (is_builtin_animation(a.animation) && o.still && o.sequence.empty())
    throw Error(
        fmt::format("--motion static: the {} animation holds still in temporal mode "
                    "(--sequence) only; give a scene to render it still",
                    a.animation));
  if (is_builtin_animation(a.animation) && (o.motion.empty() || o.still)) return;
  if (is_builtin_animation(a.animation))
    throw Error(
        fmt::format("--motion: the {} animation has its own motion; give a scene "
                    "(checkerboard, a scene file, ...) to move it",
                    a.animation));
  a.scene = resolve_scene(a.animation, a.width, a.height);
  for (const std::string& warning : scene_warnings(*a.scene))
    std::cerr << "aapat: warning: " << warning << "\n";
  a.motion =
      make_motion(o.still ? "static" : (o.motion.empty() ? "pan" : o.motion), a.width, a.height);
}

std::string engine_csv(const EngineResult& r) {
  std::string csv = "frame,rmse,max_deviation,flip,flicker,ghosting,sharpness\n";
  for (size_t f = 0; f < r.frames.size(); ++f)
    csv += fmt::format("{},{:.6f},{},{:.6f},{:.6f},{:.6f},{:.6f}\n", f, r.frames[f].rmse,
                       r.frames[f].max_deviation, r.frames[f].flip, r.frames[f].flicker,
                       r.frames[f].ghosting, r.frames[f].sharpness);
  return csv;
}

std::string taa_csv(const TaaResult& r) {
  std::string csv = "frame,rmse,max_deviation,ssim,flip,flicker\n";
  for (size_t f = 0; f < r.frames.size(); ++f)
    csv += fmt::format("{},{:.6f},{},{},{:.6f},{:.6f}\n", f, r.frames[f].rmse,
                       r.frames[f].max_deviation,
                       r.frames[f].ssim ? fmt::format("{:.6f}", *r.frames[f].ssim) : "",
                       r.frames[f].flip, r.frames[f].flicker);
  return csv;
}

// A GIF frame is grey: a colour frame's luma (Rec. 601, as the GIF viewer's eye).
std::vector<uint8_t> grey_of(const std::vector<uint8_t>& levels, int channels) {
  if (channels == 1) return levels;
  std::vector<uint8_t> grey(levels.size() / 3);
  for (size_t i = 0; i < grey.size(); ++i)
    grey[i] = static_cast<uint8_t>(
        std::lround(0.299 * levels[3 * i] + 0.587 * levels[3 * i + 1] + 0.114 * levels[3 * i + 2]));
  return grey;
}

// animate's modes: a pattern, a sequence accumulated by a model, an engine's
// TAA. What each takes, and what to give instead of what it does not.
OptionModes animate_option_modes() {
  const std::string add_sequence = "add --sequence S for temporal accumulation";
  const std::string add_taa = "add --taa PRESET (" + engine_preset_names() + ") for engine TAA";
  const std::string taa_set =
      "the preset's own setting is changed with --taa-set KEY=VALUE (aapat list: taa presets)";
  OptionModes t;
  t.command = "animate";
  t.selectors = {"taa", "sequence"};
  t.shared = {"motion", "size",     "frames", "reference-samples", "reference-filter",
              "cache",  "no-cache", "seed",   "frames-dir",        "gif",
              "mp4",    "fps",      "json"};
  t.modes = {
      {"the pattern mode (--pattern)",
       {"pattern", "filter", "histogram"},
       {{"model", add_sequence},
        {"alpha", add_sequence},
        {"window", add_sequence},
        {"resolve", add_sequence},
        {"cut", add_sequence},
        {"csv", add_sequence},
        {"taa-set", add_taa},
        {"ratio", add_taa},
        {"warmup", add_taa}},
       {"circle", "--pattern", "rgss"}},
      {"the temporal mode (--sequence)",
       {"sequence", "model", "alpha", "window", "resolve", "cut", "csv", "histogram"},
       {{"filter", "a sequence's frames reconstruct with their own weights, or --resolve F"},
        {"pattern", "give --pattern or --sequence, not both"},
        {"taa-set", add_taa},
        {"ratio", add_taa},
        {"warmup", add_taa}},
       {"circle", "--sequence", "halton:frames=4"}},
      {"the engine TAA mode (--taa)",
       {"taa", "taa-set", "ratio", "warmup", "sequence", "cut", "csv"},
       {{"alpha",
         "the preset's blend is --taa-set alpha=A (alpha_min=, alpha_max= where the "
         "preset has them)"},
        {"model", taa_set},
        {"window", taa_set},
        {"resolve", "the preset reconstructs with --taa-set reconstruct=F"},
        {"filter", "the preset reconstructs with --taa-set reconstruct=F"},
        {"pattern", "an engine renders a jitter sequence: --sequence, or the preset's own"},
        {"histogram", "use --csv"}},
       {"checkerboard", "--taa", "ue4", "--motion", "static"}},
  };
  return t;
}

void run_engine(const AnimateOptions& o, const AnimationSettings& a, const Sequence& sequence,
                const EngineTaa& taa, const std::function<void(int, const Image&)>& on_frame,
                const std::string& frames_dir, const GreyFrames& gif, std::ostream& out) {
  // Refused before anything is rendered.
  if (!a.scene)
    throw Error(
        fmt::format("--taa: give a scene to move (checkerboard, a scene file, ...) with "
                    "--motion; the {} animation moves by its own rule",
                    a.animation));
  EngineRun run;
  run.scene = *a.scene;
  run.motion = a.motion;
  run.width = a.width;
  run.height = a.height;
  run.frames = a.frames;
  run.warmup = o.cut ? 0 : (o.warmup >= 0 ? o.warmup : EngineRun{}.warmup);
  run.reference = a.reference;
  const EngineResult r = render_engine_taa(run, sequence, taa, on_frame, o.reference.source());
  if (!o.csv.empty()) write_output(o.csv, engine_csv(r), out);
  if (!o.gif.empty()) write_gif(o.gif, gif);
  if (!o.mp4.empty()) write_mp4(frames_dir, o.mp4, o.fps, a.frames);
  if (o.json) {
    out << json_text(engine_taa_json(a.animation, run, sequence, taa, r));
    return;
  }
  out << fmt::format(
      "{} ({}), {} frames of {}x{} after {} warm-up, {} under {}: RMSE {:.3f}, max deviation {}, "
      "mean FLIP {:.4f}, flicker {:.3f}, ghosting {:.3f}, sharpness {:.3f}\n",
      a.animation, a.motion.spec, a.frames, a.width, a.height, run.warmup, sequence.name,
      engine_taa_text(taa), r.total.rmse, r.total.max_deviation, r.mean_flip, r.flicker, r.ghosting,
      r.sharpness);
}

void run_animate(AnimateOptions& o, std::ostream& out, bool ratio_given) {
  AnimationSettings a = o.settings();
  const bool engine = !o.taa.empty();
  // Which options apply in which mode: the option table (add_animate_command).
  o.still = o.motion == "static";
  if (engine) check_ratio(o.ratio);
  resolve_moving_scene(o, a);
  for (const auto& [path, ext] : {std::pair{o.gif, ".gif"}, std::pair{o.mp4, ".mp4"}})
    if (!path.empty() && !path.ends_with(ext))
      throw Error(fmt::format("'{}' must end in {}", path, ext));
  if (!o.mp4.empty()) check_ffmpeg(o.mp4);
  if (!o.frames_dir.empty()) check_directory_target(o.frames_dir, "--frames-dir");
  // ffmpeg reads PNG frames from a temporary folder of their own. The
  // --frames-dir folder gets its frames all at once when the command
  // succeeds (staged like every output), and loses an earlier run's frames
  // that this run does not have; a failed run leaves it as it was.
  const bool temporary_frames = !o.mp4.empty();
  const std::string frames_dir =
      temporary_frames ? (std::filesystem::temp_directory_path() /
                          fmt::format("aapat-frames-{}", static_cast<long>(::getpid())))
                             .string()
                       : "";
  struct Cleanup {  // the temporary frames, whatever happens
    std::string dir;
    ~Cleanup() {
      std::error_code ec;
      if (!dir.empty()) std::filesystem::remove_all(dir, ec);
    }
  } cleanup{frames_dir};
  if (!engine && o.pattern.empty() == o.sequence.empty())
    throw Error("animate: give either --pattern or --sequence (temporal accumulation)");
  Sampling s;
  std::optional<Sequence> sequence;
  std::optional<Accumulation> model;
  std::optional<EngineTaa> taa;
  if (engine) {
    taa = make_engine_taa(o.taa, o.ratio, parse_taa_overrides(o.taa_set));
    std::string warning;
    sequence = resolve_sequence_for_ratio(o.sequence.empty() ? taa->jitter : o.sequence, o.ratio,
                                          ratio_given ? &warning : nullptr);
    if (!warning.empty()) std::cerr << "aapat: warning: " << warning << "\n";
    for (const std::string& w : engine_sequence_warnings(*sequence, *taa))
      std::cerr << "aapat: warning: " << w << "\n";
  } else if (o.sequence.empty()) {
    s.pattern = resolve_pattern(o.pattern);
  } else {
    sequence = resolve_sequence(o.sequence);
    model = o.model.make();
  }
  std::optional<Filter> filter;
  if (!o.filter.empty()) filter = make_filter(o.filter);
  if (!frames_dir.empty()) ensure_directory(frames_dir, "ffmpeg's frames");
  if (!o.frames_dir.empty()) {
    ensure_directory(o.frames_dir, "--frames-dir");
    stale_frames_removed_at_commit(o.frames_dir, a.frames);
  }
  Progress bar("animate");
  GreyFrames gif{a.width, a.height, std::max(2, 100 / o.fps), {}};
  const auto on_frame = [&](int f, const Image& img) {
    const std::string name = fmt::format("frame-{:0{}d}.png", f, frame_digits(a.frames));
    const std::vector<uint8_t> levels = level_pixels(img);
    const std::string png = png_bytes(img.width, img.height, img.channels, levels);
    if (!frames_dir.empty()) write_file_now(frames_dir + "/" + name, png);  // ffmpeg's, now
    if (!o.frames_dir.empty()) write_file_atomically(o.frames_dir + "/" + name, png);
    if (!o.gif.empty()) gif.frames.push_back(grey_of(levels, img.channels));
    bar.update(f + 1, a.frames, "");
  };
  if (taa) {
    run_engine(o, a, *sequence, *taa, on_frame, frames_dir, gif, out);
    return;
  }
  std::optional<TaaResult> linear;
  std::optional<AnimationResult> plain;
  if (sequence)
    linear = render_taa(a, *sequence, *model, !o.cut, o.still, on_frame, o.reference.source());
  else
    plain = animate(a, s, filter, on_frame, o.reference.source());
  const ImageError e = linear ? linear->total : plain->total;
  if (linear && !o.csv.empty()) write_output(o.csv, taa_csv(*linear), out);
  if (!o.gif.empty()) write_gif(o.gif, gif);
  if (!o.mp4.empty()) write_mp4(frames_dir, o.mp4, o.fps, a.frames);
  if (!o.histogram.empty()) {
    std::string csv = "deviation,count,contribution\n";
    for (int i = 0; i < 256; ++i)
      csv += fmt::format("{},{},{:.6g}\n", i, e.count[i], e.contribution[i]);
    write_output(o.histogram, csv, out);
  }
  if (o.json) {
    JsonObject doc = json_report("animate");
    doc.update(JsonObject{{"animation", a.animation},
                          {"pattern", sequence ? sequence->name : o.pattern},
                          {"filter", filter ? filter->name() : "pattern weights"},
                          {"frames", a.frames},
                          {"width", a.width},
                          {"height", a.height},
                          {"reference", describe_reference(a.reference)},
                          {"rmse", e.rmse},
                          {"max_deviation", e.max_deviation}});
    if (linear) {
      doc["model"] = o.model.text();
      doc["steady"] = !o.cut;
      doc["static"] = o.still;
      doc["mean_ssim"] = linear->mean_ssim ? JsonObject(*linear->mean_ssim) : nullptr;
      doc["mean_flip"] = linear->mean_flip;
      doc["flicker"] = linear->flicker;
      JsonObject::array_t rows;
      for (const TaaFrame& f : linear->frames)
        rows.push_back(JsonObject{{"rmse", f.rmse},
                                  {"max_deviation", f.max_deviation},
                                  {"ssim", f.ssim ? JsonObject(*f.ssim) : nullptr},
                                  {"flip", f.flip},
                                  {"flicker", f.flicker}});
      doc["rows"] = rows;
    } else {
      doc["mean_flip"] = plain->mean_flip;
      JsonObject::array_t rows;
      for (const AnimationFrame& f : plain->frames)
        rows.push_back(
            JsonObject{{"rmse", f.rmse}, {"max_deviation", f.max_deviation}, {"flip", f.flip}});
      doc["rows"] = rows;
    }
    out << json_text(doc);
    return;
  }
  if (linear) {
    out << fmt::format(
        "{} animation{}, {} frames of {}x{}, {} under {}{} against {}: RMSE {:.3f}, max "
        "deviation {}, mean SSIM {}, mean FLIP {:.4f}, flicker {:.3f} levels per pixel and "
        "frame\n",
        a.animation, o.still ? " (static)" : "", a.frames, a.width, a.height, sequence->name,
        o.model.text(), o.cut ? " from a cut" : " in steady state", describe_reference(a.reference),
        e.rmse, e.max_deviation,
        linear->mean_ssim ? fmt::format("{:.4f}", *linear->mean_ssim) : "-", linear->mean_flip,
        linear->flicker);
    return;
  }
  out << fmt::format(
      "{} animation, {} frames of {}x{}, {} against {}: RMSE {:.3f}, max deviation {}, mean FLIP "
      "{:.4f}\n",
      a.animation, a.frames, a.width, a.height, o.pattern, describe_reference(a.reference), e.rmse,
      e.max_deviation, plain->mean_flip);
}

}  // namespace

Action add_animate_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("animate", "render an animation with a pattern against a reference");
  auto o = std::make_shared<AnimateOptions>();
  cmd->add_option("animation", o->a.animation,
                  "circle (translating) or triangle (rotating), or any scene render takes (a "
                  "built-in spec, a scene file, a mesh scene) moved by --motion")
      ->required();
  cmd->add_option("--motion", o->motion,
                  "a scene's motion: pan:dx=DX,dy=DY (display pixels per frame; the default, "
                  "0.5 and 0.25), rotate:deg=D,cx=X,cy=Y, static");
  cmd->add_option("--taa", o->taa,
                  "engine TAA: a preset, " + engine_preset_names() +
                      " (docs/temporal.md, Engine presets); the sequence defaults to the "
                      "preset's own jitter");
  cmd->add_option(
      "--taa-set", o->taa_set,
      "override one engine TAA setting, KEY=VALUE (" + engine_setting_names() + "); repeatable");
  auto* ratio = cmd->add_option("--ratio", o->ratio,
                                "engine TAA render scale: display / render resolution (>= 1); a "
                                "generator without frames= takes int(8 R^2) phases");
  cmd->add_option("--warmup", o->warmup,
                  "engine TAA: frames rendered before the measured ones (default 64; --cut: 0)");
  cmd->add_option("--pattern", o->pattern, "catalog pattern or pattern file");
  cmd->add_option("--sequence", o->sequence,
                  "temporal mode: a sequence file or generator spec (halton:frames=8, ...), each "
                  "frame sampled with its phase and accumulated by --model (docs/temporal.md)");
  o->model.add_to(cmd);
  cmd->add_flag("--cut", o->cut, "temporal mode: start from a camera cut (default: steady state)");
  cmd->add_option("--csv", o->csv, "temporal mode: per frame RMSE, max deviation, SSIM, flicker");
  cmd->add_option("--filter", o->filter,
                  "reconstruct with this filter (default: the pattern's weights)");
  add_animation_options(cmd, *o);
  cmd->add_option("--frames-dir", o->frames_dir, "write every frame as frame-NNNN.png here");
  cmd->add_option("--gif", o->gif, "the frames as a looping animated GIF");
  cmd->add_option("--mp4", o->mp4, "the frames as an MP4 video (needs ffmpeg)");
  cmd->add_option("--fps", o->fps, "frames per second of --gif and --mp4")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxFramesPerSecond));
  cmd->add_option("--histogram", o->histogram, "squared-error histogram of all frames (.csv)");
  cmd->add_flag("--json", o->json, "print JSON");
  enforce_option_modes(cmd, animate_option_modes(), [cmd] {
    return cmd->get_option("--taa")->count() > 0        ? size_t{2}
           : cmd->get_option("--sequence")->count() > 0 ? size_t{1}
                                                        : size_t{0};
  });
  return [o, ratio](std::ostream& out) { run_animate(*o, out, ratio->count() > 0); };
}

}  // namespace aapat
