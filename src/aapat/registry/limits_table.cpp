#include "aapat/registry/limits_table.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "aapat/analyze/discrepancy.h"
#include "aapat/analyze/flip.h"
#include "aapat/analyze/flip_gradient.h"
#include "aapat/analyze/spectrum.h"
#include "aapat/core/acuity.h"
#include "aapat/core/filter.h"
#include "aapat/core/json_depth.h"
#include "aapat/core/metric.h"
#include "aapat/core/pattern.h"
#include "aapat/core/read_file.h"
#include "aapat/generate/maximal_poisson.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/gltf_prescan.h"
#include "aapat/io/mesh_file.h"
#include "aapat/io/png_image.h"
#include "aapat/io/point_set_file.h"
#include "aapat/io/scene_json.h"
#include "aapat/io/texture_file.h"
#include "aapat/optimize/settings.h"
#include "aapat/registry/page_limits.h"
#include "aapat/render/animation.h"
#include "aapat/render/mesh.h"
#include "aapat/render/motion.h"
#include "aapat/render/renderer.h"
#include "aapat/render/texture.h"
#include "aapat/study/point_set_study.h"
#include "aapat/temporal/engine/engine_comparison.h"
#include "aapat/temporal/engine/engine_taa.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/model/accumulation.h"
#include "aapat/temporal/model/pan_model.h"
#include "aapat/temporal/search/pan_objective.h"
#include "aapat/temporal/search/pan_search.h"
#include "aapat/temporal/search/still_search.h"
#include "aapat/temporal/sequence/render_scale.h"
#include "aapat/temporal/sequence/sequence.h"
#include "aapat/work/work_items.h"

namespace aapat {

namespace {

// 1234567 -> "1,234,567": the table is read by people.
std::string grouped(uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// A limit as people write it: whole numbers grouped (1,000,000), others
// short (1e-9, 0.005).
std::string number(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15)
    return fmt::format("{}{}", v < 0 ? "-" : "", grouped(static_cast<uint64_t>(std::abs(v))));
  if (v != 0 && std::abs(v) < 1e-3) {
    const int exponent = static_cast<int>(std::floor(std::log10(std::abs(v))));
    return fmt::format("{}e{}", v / std::pow(10.0, exponent), exponent);
  }
  return fmt::format("{}", v);
}

std::string mib(size_t bytes) {
  return bytes >= (size_t{1} << 30) ? fmt::format("{} GiB", bytes >> 30)
                                    : fmt::format("{} MiB", bytes >> 20);
}

std::vector<Limit> make_table() {
  return {
      {"threads (`--threads`, `threads=`)", fmt::format("0 (every core) to {}", kMaxThreads),
       "`kMaxThreads`, `work/work_items.h`"},
      {"pattern tile side", fmt::format("1 to {} pixels", kMaxTileSide),
       "`kMaxTileSide`, `core/pattern.h`"},
      {"samples in one pixel's set", grouped(kMaxSamplesPerSet), "`kMaxSamplesPerSet`"},
      {"samples in a whole pattern", grouped(kMaxPatternSamples), "`kMaxPatternSamples`"},
      {"a kernel weight",
       fmt::format("finite, \\|w\\| ≤ {} (weights sum to 1 within 1e-6)",
                   number(kMaxWeightMagnitude)),
       "`kMaxWeightMagnitude`"},
      {"acuity table",
       fmt::format("1 to {} angles (a step of {}° or more), angles in [−360, 360], none "
                   "repeating modulo 180",
                   grouped(kMaxAcuityAngles), number(180.0 / kMaxAcuityAngles)),
       "`kMaxAcuityAngles`, `core/acuity.h`"},
      {"acuity weight",
       fmt::format("finite, in [0, {}], at least one positive", number(kMaxAcuityWeight)),
       "`kMaxAcuityWeight`"},
      {"acuity CSV file", "16 MiB", "`make_acuity`, `core/acuity.cpp`"},
      {"norm p of the L_p mean", fmt::format("1 to {}, or `inf`", number(Metric::kMaxFiniteNorm)),
       "`Metric::kMaxFiniteNorm`, `core/metric.h`"},
      {"filter sizes (box width, tent and Gaussian radius, sigma)", "0.001 to 16 pixels",
       "`core/filter_catalog.cpp`"},
      {"smooth filters",
       fmt::format("tabulated to {} of their peak with at most {} pieces, else refused as too "
                   "narrow",
                   number(Filter::kTabulationTolerance), Filter::kMaxSegments),
       "`Filter::kTabulationTolerance`, `kMaxSegments`"},
      {"generators: points", fmt::format("1 to {}", grouped(kMaxGeneratedPoints)),
       "`kMaxGeneratedPoints`, `generate/point_generators.h`"},
      {"generators: realizations (`--sets`)",
       fmt::format("1 to {}, with at most {} points in all", grouped(kMaxPointSets),
                   grouped(kMaxGeneratedPointsInAll)),
       "`kMaxPointSets`, `kMaxGeneratedPointsInAll`"},
      {"best candidate",
       fmt::format("q n² / 2 ≤ {} candidate queries (n ≤ 3162 at q = 10, about 7 s)",
                   number(kMaxBestCandidateQueries)),
       "`kMaxBestCandidateQueries`"},
      {"Poisson disk",
       fmt::format("at most {} points (about 8 s); radius in (0, 1] (`poisson-maximal`: "
                   "[{}, 1], about 0.7 / r² points, 700,000 in about 5 s); the default radius "
                   "shrinks by 5% steps until n points fit",
                   grouped(kMaxPoissonPoints), number(kMinMaximalPoissonRadius)),
       "`kMaxPoissonPoints`, `kMinMaximalPoissonRadius`"},
      {"N-queens",
       fmt::format("N ≤ {} (the lexicographic search takes 40 s at N = 32)", kMaxNQueens),
       "`kMaxNQueens`"},
      {"point-set CSV", fmt::format("{} points", grouped(kMaxPointSetSize)),
       "`kMaxPointSetSize`, `io/point_set_file.h`"},
      {"discrepancy (star, edge)", fmt::format("{} points", grouped(kMaxDiscrepancyPoints)),
       "`kMaxDiscrepancyPoints`, `analyze/discrepancy.h`"},
      {"discrepancy (the L2 kinds alone, e.g. `--measure l2-star,l2-centred`)",
       fmt::format("{} points (O(N log N)); point sets themselves hold at most {}",
                   grouped(kMaxL2StarPoints), grouped(kMaxPointSetSize)),
       "`kMaxL2StarPoints`"},
      {"spectrum",
       fmt::format("size {} to {}; points × size² × realizations ≤ 2^36 ({}); `--fast`: an "
                   "even size, any number of points",
                   kMinSpectrumSize, kMaxSpectrumSize, number(kMaxSpectrumTerms)),
       "`kMinSpectrumSize`, `kMaxSpectrumSize`, `analyze/spectrum.h`; `kMaxSpectrumTerms`, "
       "`study/point_set_study.h`"},
      {"line spectrum (`spectrum --1d`)",
       fmt::format("{} to {} frequencies up to a maximum in [{}, {}]", kMinLineFrequencies,
                   grouped(kMaxLineFrequencies), number(kMinLineMaxFrequency),
                   number(kMaxLineMaxFrequency)),
       "`kMaxLineFrequencies`, `study/point_set_study.h`"},
      {"scene file",
       fmt::format("{} shapes; {} vertices per polygon; {} vertices in all; coordinates within "
                   "±10^7 pixels",
                   grouped(kMaxSceneShapes), grouped(kMaxPolygonVertices),
                   grouped(kMaxSceneVertices)),
       "`kMaxSceneShapes`, `io/scene_json.h`"},
      {"textured polygon", "convex, with an area; `w` in [10⁻⁶, 10⁶]; `uv` within ±10⁷",
       "`io/scene_json.cpp`"},
      {"mesh scene camera",
       "`fov_deg` 1 to 170; `pitch_deg` within ±89.9; `yaw_deg` within ±3600; eye, target and "
       "up within ±10^12, the eye not at the target, up not along the line of sight; "
       "`light.ambient` in [0, 1]; `background` in [0, 1]",
       "`io/mesh_scene.cpp`"},
      {"any input file",
       fmt::format("{}, a regular file (FIFOs and devices refused)", mib(kMaxInputFileBytes)),
       "`kMaxInputFileBytes`, `core/read_file.h`"},
      {"image size (`--size`, `size=`)",
       fmt::format("1 to {} per side (`animate`, `engine_taa`, `table2`: {} to {})", kMaxImageSide,
                   kMinAnimationSize, kMaxAnimationSize),
       "`kMaxImageSide`, `render/renderer.h`; `kMaxAnimationSize`, `render/animation.h`"},
      {"animation work",
       fmt::format("width × height × frames (warm-up frames included) at most 2^30 ({}) "
                   "pixel-frames, e.g. 4096² × 64 or 256² × 16,384",
                   grouped(static_cast<uint64_t>(kMaxAnimationPixelFrames))),
       "`kMaxAnimationPixelFrames`, `render/animation.h`"},
      {"samples per pixel (`--samples`, `--reference-samples`)",
       fmt::format("1 to {}; the reference's a square number", grouped(kMaxSamplesPerPixel)),
       "`kMaxSamplesPerPixel`, `render/renderer.h`"},
      {"texture (`--texture`, a polygon's `texture`)",
       fmt::format("1 to {} texels per side (checked from the PNG header before decoding); a "
                   "file of at most {}",
                   kMaxTextureSide, mib(kMaxTextureFileBytes)),
       "`kMaxTextureSide`, `render/texture.h`; `io/texture_file.h`"},
      {"model file (a mesh scene's `mesh`)",
       fmt::format("{} per file assimp opens (the model, its `.bin` and `.mtl` files: each a "
                   "regular file, checked before it is read); its buffers, materials and "
                   "textures inside the model's folder (`AAPAT_TRUST_MODELS=1` lifts it for "
                   "trusted content); {} triangles; {} vertices; {} "
                   "materials; {} texels in all its textures, each at most {} a side (each "
                   "checked from its PNG or JPEG header); nodes nested at most {} deep; every "
                   "position, texture coordinate and colour finite. A glTF or GLB is read "
                   "first without recursion and refused before assimp runs when its JSON nests "
                   "past {}, its node graph has a cycle, nests past {} or expands to more than "
                   "{} nodes (a node listed twice as a child is copied), or an accessor holds "
                   "more than {} elements (its sparse part included). A PLY's vertex and face "
                   "counts are checked from its header, and an ASCII face's list against its "
                   "line, before assimp runs",
                   mib(kMaxModelFileBytes), grouped(kMaxMeshTriangles), grouped(kMaxMeshVertices),
                   grouped(kMaxMeshMaterials), grouped(kMaxMeshTextureTexels), kMaxTextureSide,
                   kMaxModelNodeDepth, kMaxJsonDepth, kMaxModelNodeDepth, grouped(kMaxModelNodes),
                   grouped(kMaxAccessorCount)),
       "`kMaxModelFileBytes`, `io/mesh_file.h`; `kMaxMeshTriangles` etc., `render/mesh.h`; "
       "`kMaxModelNodes` etc., `io/gltf_prescan.h`"},
      {"adaptive refinement",
       "1 to 5 initial samples per pixel; `--threshold` in [0, 1] ([0, 1/4] for variance); "
       "`--max-depth` 1 to 8; `--per-square` 1 to 16; `--max-samples` from the initial count "
       "to 4096",
       "`render/adaptive.h`"},
      {"`aapat diff` images",
       fmt::format("at most {} pixels each (8K UHD; checked from the PNG header before "
                   "decoding); a file of at most 1 GiB; pixels per degree {} to {}",
                   grouped(kMaxColorImagePixels), number(kMinPixelsPerDegree),
                   number(kMaxPixelsPerDegree)),
       "`kMaxColorImagePixels`, `io/png_image.h`; `kMaxPixelsPerDegree`, `analyze/flip.h`"},
      {"FLIP's gradient (the perceptual objective's weight gradient)",
       fmt::format("at most {} pixels an image (about 250 bytes each in its planes)",
                   grouped(kMaxFlipGradientPixels)),
       "`kMaxFlipGradientPixels`, `analyze/flip_gradient.h`"},
      {"optimizer",
       fmt::format("starts 1 to {}, iterations 1 to {}, lattice 1/{} to 1/{} pixel",
                   grouped(kMaxStarts), grouped(kMaxIterations), kMinLatticeSteps,
                   kMaxLatticeSteps),
       "`kMaxStarts`, `kMaxIterations`, `kMaxLatticeSteps`, `optimize/settings.h`"},
      {"seeds",
       fmt::format("whole numbers 0 to 2^64 − 1 ({}); larger ones are refused, not clamped",
                   grouped(std::numeric_limits<uint64_t>::max())),
       "every `--seed`, `seed=`"},
      {"sequences",
       fmt::format("1 to {} frames, every frame a valid pattern of the same tile and footprint; "
                   "`--alpha` in (0, 1]; `--window` 0 to 1024; `--resolve` filter radius up to "
                   "{} pixels; `--curve-frames` up to 4096",
                   kMaxSequenceFrames, number(kMaxResolveRadius)),
       "`kMaxSequenceFrames`, `temporal/sequence/sequence.h`; `kMaxResolveRadius`, "
       "`temporal/model/accumulation.h`"},
      {"`optimize --sequence`",
       fmt::format("1 to {} frames, 1 to 16 samples per frame, 1024 samples in all; "
                   "`--flicker-weight` 0 to 1000; `--jitter-bound` {} to 0.5 (with `--api`: at "
                   "least 1/16); `--jitter-radius` {} to {} (with `--api`: at least 1/16); no "
                   "`--resolve`; with `--ratio`: one "
                   "sample per frame, no `--api`, no `--jitter-radius`, at most 400 Subplex "
                   "evaluations per start",
                   kMaxSequenceFrames, number(kMinJitterBound), number(kMinJitterBound),
                   number(kMaxJitterRadius)),
       "`temporal/search/still_search.h`"},
      {"engine TAA (`animate --taa`, `engine_taa`)",
       fmt::format("ratio finite in [1, {}]; warm-up 0 to {} frames; 1 to {} frames; a "
                   "motion step moves no point of the image by {} of its smaller side or more; "
                   "`--taa-set` gamma 0 to 16, alpha 1e-4 to 1, alpha_min 0 to 1 (at most "
                   "alpha_max), count_step 1e-3 to 1000, count_max 0 to 1e6",
                   number(kMaxUpscaleRatio), kMaxWarmupFrames, grouped(kMaxEngineFrames),
                   number(kMaxMotionPerFrame)),
       "`kMaxUpscaleRatio`, `temporal/sequence/render_scale.h`; `kMaxWarmupFrames`, "
       "`kMaxEngineFrames`, `temporal/engine/engine_taa.h`; "
       "`kMaxMotionPerFrame`, `render/motion.h`"},
      {"`sequence pan` (`sequence_pan`)",
       fmt::format("ratio finite in [1, {}]; velocities finite, within {} pixels per frame per "
                   "axis; 1 to {} frames; at most {} samples in one pixel's kernel (a small "
                   "alpha under a blurring history)",
                   number(kMaxUpscaleRatio), number(kMaxPanSpeed), kMaxPanFrames,
                   grouped(static_cast<uint64_t>(kMaxPanKernelSamples))),
       "`kMaxPanSpeed`, `kMaxPanFrames`, `kMaxPanKernelSamples`, `temporal/model/pan_model.h`"},
      {"`optimize --sequence --taa` (`optimize_sequence_pan`)",
       fmt::format("as `sequence pan`; one sample per frame; `--step` in (0, 0.5], `--min-step` "
                   "in (0, step]; `--jitter-bound` {} to 0.5; the bins of every kernel at most "
                   "{} GiB; at most {} sweeps per step size",
                   number(kMinJitterBound), kMaxPanObjectiveBytes >> 30,
                   grouped(static_cast<uint64_t>(kMaxPanSweeps))),
       "`kMaxPanObjectiveBytes`, `temporal/search/pan_objective.h`; `kMaxPanSweeps`, "
       "`temporal/search/pan_search.h`"},
      {"`sequence compare` (`sequence_compare`)",
       fmt::format("at least two sequences; 1 to {} scenes; `--shapes` 1 to 4096; as engine "
                   "TAA for the size, frames and warm-up; `--resamples` 1 to 1,000,000",
                   kMaxComparisonScenes),
       "`kMaxComparisonScenes`, `temporal/engine/engine_comparison.h`"},
      {"JSON input (pattern, sequence and scene files, the page's links and requests)",
       fmt::format("arrays and objects nested at most {} deep, checked before the parser "
                   "(which recurses) reads it",
                   kMaxJsonDepth),
       "`kMaxJsonDepth`, `core/json_depth.h`"},
      {"the explorer page",
       fmt::format("view {} pixels a side, {} points, spectrum {} a side, {} starts, {} iterations "
                   "a start, {} reference samples, seeds 0 to {}; a link of at most {} characters "
                   "after '#' (a larger design is saved as a file)",
                   kMaxPageViewSize, grouped(kMaxPagePoints), kMaxPageSpectrumSize,
                   grouped(kMaxPageStarts), grouped(kMaxPageIterations),
                   grouped(kMaxPageReferenceSamples), grouped(kMaxPageSeed),
                   grouped(kMaxPageLinkBytes)),
       "`registry/page_limits.h`"},
      {"upscaler phases (`sequence phases --ratio`)", "ratio 1 to 16",
       "`upscaler_phase_count`, `temporal/sequence/render_scale.h`"},
  };
}

}  // namespace

const std::vector<Limit>& limits_table() {
  static const std::vector<Limit> table = make_table();
  return table;
}

JsonObject limits_json() {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const Limit& l : limits_table())
    rows.push_back({{"what", l.what}, {"limit", l.limit}, {"defined", l.defined}});
  JsonObject doc;
  doc["limits"] = rows;
  return doc;
}

std::string limits_markdown() {
  std::string out = "| what | limit | where it is defined |\n| --- | --- | --- |\n";
  for (const Limit& l : limits_table())
    out += fmt::format("| {} | {} | {} |\n", l.what, l.limit, l.defined);
  return out;
}

}  // namespace aapat
