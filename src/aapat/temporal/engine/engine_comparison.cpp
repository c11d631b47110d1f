#include "aapat/temporal/engine/engine_comparison.h"

#include <fmt/format.h>

#include <algorithm>

#include "aapat/io/scene_json.h"
#include "aapat/render/animation.h"
#include "aapat/render/motion.h"

namespace aapat {

std::vector<std::string> random_scene_specs(int count, int shapes, uint64_t seed) {
  if (count < 1 || count > kMaxComparisonScenes)
    throw ParameterError("random-scenes",
                         fmt::format(" {}: expected 1 to {} scenes", count, kMaxComparisonScenes));
  if (shapes < 1 || shapes > 4096)
    throw ParameterError("shapes", fmt::format(" {}: expected 1 to 4096 shapes a scene", shapes));
  std::vector<std::string> specs;
  for (int i = 0; i < count; ++i)
    specs.push_back(
        fmt::format("random-shapes:count={},seed={}", shapes, seed + static_cast<uint64_t>(i)));
  return specs;
}

std::vector<std::string> comparison_scenes(const std::vector<std::string>& given, int random_scenes,
                                           int shapes, uint64_t seed) {
  if (given.empty() == (random_scenes == 0))
    throw ParameterError("scene", ": give the scenes, or a count of random scenes, not both");
  return given.empty() ? random_scene_specs(random_scenes, shapes, seed) : given;
}

void validate(const EngineComparison& c, size_t sequences) {
  if (c.scenes.empty() || c.scenes.size() > static_cast<size_t>(kMaxComparisonScenes))
    throw ParameterError("scene", fmt::format(": {} scenes; expected 1 to {}", c.scenes.size(),
                                              kMaxComparisonScenes));
  if (sequences < 2)
    throw Error(
        fmt::format("a comparison takes at least two sequences (the first is the "
                    "baseline), not {}",
                    sequences));
  if (c.frames < 1 || c.frames > kMaxEngineFrames)
    throw ParameterError("frames",
                         fmt::format(" {}: expected 1 to {}", c.frames, kMaxEngineFrames));
  if (c.warmup < 0 || c.warmup > kMaxWarmupFrames)
    throw ParameterError("warmup",
                         fmt::format(" {}: expected 0 to {}", c.warmup, kMaxWarmupFrames));
  check_animation_work(c.width, c.height, c.frames + c.warmup);
  if (c.motion == "random-pan") {
    random_pan_velocities(static_cast<int>(c.scenes.size()), c.max_speed, c.seed);  // checks
  } else if (c.motion != "static" && c.motion != "cut") {
    make_motion(c.motion, c.width, c.height);  // names a bad spec before any work
  }
  check_paired_settings(c.resamples, c.confidence);
}

Sequence started_at(const Sequence& s, int phase) {
  Sequence out = s;
  const int n = s.period();
  for (int f = 0; f < n; ++f)
    out.frames[static_cast<size_t>(f)] = s.frames[static_cast<size_t>((f + phase) % n)];
  return out;
}

PreparedScenes::PreparedScenes(const EngineComparison& c, const ReferenceSource& references)
    : cut_(c.motion == "cut"),
      source_(references ? references : ReferenceSource(render_reference)),
      memo_(c.scenes.size()) {
  motions_.assign(c.scenes.size(), c.motion == "cut" ? "static" : c.motion);
  if (c.motion == "random-pan") {
    const std::vector<Vec2> v =
        random_pan_velocities(static_cast<int>(c.scenes.size()), c.max_speed, c.seed);
    for (size_t m = 0; m < motions_.size(); ++m)
      motions_[m] = fmt::format("pan:dx={:g},dy={:g}", v[m].x, v[m].y);
  }
  for (size_t m = 0; m < c.scenes.size(); ++m) {
    EngineRun run;
    run.scene = resolve_scene(c.scenes[m], c.width, c.height);
    run.motion = make_motion(motions_[m], c.width, c.height);
    run.width = c.width;
    run.height = c.height;
    run.frames = c.frames;
    run.warmup = c.motion == "cut" ? 0 : c.warmup;
    run.reference = c.reference;
    runs_.push_back(std::move(run));
  }
}

ComparisonMeasures PreparedScenes::render(size_t scene, const Sequence& s, const EngineTaa& taa,
                                          ComparisonMeasures* worst_phase) {
  std::map<uint64_t, Image>& memo = memo_[scene];
  const ReferenceSource remembered = [&](const Scene& sc, int w, int h,
                                         const ReferenceSettings& ref, double offset) {
    const auto it = memo.find(ref.seed);
    if (it != memo.end()) return it->second;
    return memo.emplace(ref.seed, source_(sc, w, h, ref, offset)).first->second;
  };
  // A cut falls on any phase: every start, each measure's mean over them
  // and its largest; otherwise the sequence as it is (one start).
  ComparisonMeasures mean{}, worst{};
  const int n = cut_ ? s.period() : 1;
  for (int phase = 0; phase < n; ++phase) {
    const EngineResult e =
        render_engine_taa(runs_[scene], started_at(s, phase), taa, {}, remembered);
    const ComparisonMeasures m{e.total.rmse, e.flicker, e.mean_flip};
    for (size_t q = 0; q < m.size(); ++q) {
      mean[q] += m[q] / n;
      worst[q] = phase == 0 ? m[q] : std::max(worst[q], m[q]);
    }
  }
  if (worst_phase) *worst_phase = worst;
  return mean;
}

EngineComparisonResult compare_under_engine(const std::vector<Sequence>& sequences,
                                            const EngineComparison& c,
                                            const ReferenceSource& references,
                                            const ItemsProgress& progress) {
  validate(c, sequences.size());
  PreparedScenes prepared(c, references);
  EngineComparisonResult r;
  for (const Sequence& s : sequences) r.sequences.push_back(s.name);
  const int renders = static_cast<int>(sequences.size() * c.scenes.size());
  int done = 0;
  for (size_t m = 0; m < c.scenes.size(); ++m) {
    ComparedScene scene{c.scenes[m], prepared.motion(m), {}, {}};
    for (const Sequence& s : sequences) {
      ComparisonMeasures worst{};
      scene.measures.push_back(prepared.render(m, s, c.taa, &worst));
      if (prepared.cut()) scene.worst_phase.push_back(worst);
      if (progress) progress(++done, renders, fmt::format("{} on {}", s.name, c.scenes[m]));
    }
    r.scenes.push_back(std::move(scene));
  }
  for (size_t k = 1; k < sequences.size(); ++k) {
    std::array<PairedComparison, kComparisonMeasures.size()> per;
    for (size_t q = 0; q < kComparisonMeasures.size(); ++q) {
      std::vector<double> ours, theirs;
      for (const ComparedScene& s : r.scenes) {
        ours.push_back(s.measures[k][q]);
        theirs.push_back(s.measures[0][q]);
      }
      per[q] = compare_paired(ours, theirs, c.resamples, c.confidence, c.seed);
    }
    r.against_first.push_back(per);
  }
  return r;
}

JsonObject comparison_settings_json(const EngineComparison& c) {
  return JsonObject{{"taa", c.taa.preset},
                    {"taa_settings", engine_taa_text(c.taa)},
                    {"ratio", c.taa.upscale.ratio},
                    {"motion", c.motion},
                    {"width", c.width},
                    {"height", c.height},
                    {"frames", c.frames},
                    {"warmup", c.motion == "cut" ? 0 : c.warmup},
                    {"reference", describe_reference(c.reference)},
                    {"seed", c.seed}};
}

JsonObject engine_comparison_json(const EngineComparison& c, const EngineComparisonResult& r) {
  JsonObject doc = json_report("sequence compare");
  JsonObject::array_t scenes;
  for (const ComparedScene& s : r.scenes) {
    JsonObject::array_t rows;
    for (size_t k = 0; k < r.sequences.size(); ++k) {
      JsonObject row{{"sequence", r.sequences[k]}};
      for (size_t q = 0; q < kComparisonMeasures.size(); ++q)
        row[kComparisonMeasures[q]] = s.measures[k][q];
      if (!s.worst_phase.empty()) {
        JsonObject worst;
        for (size_t q = 0; q < kComparisonMeasures.size(); ++q)
          worst[kComparisonMeasures[q]] = s.worst_phase[k][q];
        row["worst_phase"] = worst;
      }
      rows.push_back(row);
    }
    scenes.push_back(JsonObject{{"scene", s.scene}, {"motion", s.motion}, {"rows", rows}});
  }
  JsonObject::array_t against;
  for (size_t k = 1; k < r.sequences.size(); ++k) {
    JsonObject entry{{"sequence", r.sequences[k]}, {"against", r.sequences[0]}};
    for (size_t q = 0; q < kComparisonMeasures.size(); ++q) {
      const PairedComparison& p = r.against_first[k - 1][q];
      entry[kComparisonMeasures[q]] = paired_comparison_json(p);
    }
    against.push_back(entry);
  }
  JsonObject::array_t measures;
  for (const char* m : kComparisonMeasures) measures.push_back(m);
  doc.update(comparison_settings_json(c));
  doc.update(JsonObject{{"resamples", c.resamples},
                        {"confidence", c.confidence},
                        {"measures", measures},
                        {"sequences", r.sequences},
                        {"scenes", scenes},
                        {"against_first", against}});
  return doc;
}

}  // namespace aapat
