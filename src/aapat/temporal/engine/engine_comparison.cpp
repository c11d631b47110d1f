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

std::string comparison_motion_help() {
  std::string out;
  for (const ComparisonMotion& m : kComparisonMotions)
    out += fmt::format("{}{} ({})", out.empty() ? "" : ", ", m.name, m.summary);
  return out + ", or a motion spec for every scene";
}

bool renders_several_ways(const std::string& motion) {
  return motion == "cut" || motion == "resonant";
}

namespace {

bool named_motion(const std::string& motion) {
  return std::any_of(kComparisonMotions.begin(), kComparisonMotions.end(),
                     [&](const ComparisonMotion& m) { return motion == m.name; });
}

// A pan of v render pixels per frame on the display, in a spec that parses
// back to the same doubles (the resonances are exact: 1/3 px, not 0.333333).
std::string display_pan(Vec2 v, double ratio) {
  return fmt::format("pan:dx={},dy={}", v.x * ratio, v.y * ratio);
}

}  // namespace

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
  } else if (!named_motion(c.motion)) {
    // A comparison takes its own motions besides the render's: an unknown
    // name lists both.
    if (!motion_registry().contains(c.motion)) {
      std::string named;
      for (const ComparisonMotion& m : kComparisonMotions) named += std::string(m.name) + ", ";
      throw ParameterError(
          "motion", fmt::format(" '{}': a comparison takes {}or a motion spec ({})",
                                split_spec(c.motion).first, named, motion_registry().names()));
    }
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
      resonant_(c.motion == "resonant"),
      source_(references ? references : ReferenceSource(render_reference)) {
  motions_.assign(c.scenes.size(), cut_ ? "static" : c.motion);
  if (c.motion == "random-pan") {
    const std::vector<Vec2> v =
        random_pan_velocities(static_cast<int>(c.scenes.size()), c.max_speed, c.seed);
    for (size_t m = 0; m < motions_.size(); ++m)
      motions_[m] = fmt::format("pan:dx={:g},dy={:g}", v[m].x, v[m].y);
  }
  std::vector<std::string> ways;
  if (resonant_)
    for (const Vec2 v : resonant_velocities()) ways.push_back(display_pan(v, c.taa.upscale.ratio));
  for (size_t m = 0; m < c.scenes.size(); ++m) {
    EngineRun run;
    run.scene = resolve_scene(c.scenes[m], c.width, c.height);
    run.width = c.width;
    run.height = c.height;
    run.frames = c.frames;
    run.warmup = cut_ ? 0 : c.warmup;
    run.reference = c.reference;
    std::vector<Way>& scene = scenes_.emplace_back();
    for (const std::string& motion : resonant_ ? ways : std::vector<std::string>{motions_[m]}) {
      run.motion = make_motion(motion, c.width, c.height);
      scene.push_back(Way{run, {}});
    }
  }
}

ComparisonMeasures PreparedScenes::render(size_t scene, const Sequence& s, const EngineTaa& taa,
                                          MeasureSpread* spread) {
  // A cut falls on any phase: every start; the resonances: every velocity;
  // otherwise the sequence as it is (one start, one motion).
  const int phases = cut_ ? s.period() : 1;
  MeasureSpread all;
  for (Way& way : scenes_[scene]) {
    const ReferenceSource remembered = [&](const Scene& sc, int w, int h,
                                           const ReferenceSettings& ref, double offset) {
      const auto it = way.memo.find(ref.seed);
      if (it != way.memo.end()) return it->second;
      return way.memo.emplace(ref.seed, source_(sc, w, h, ref, offset)).first->second;
    };
    for (int phase = 0; phase < phases; ++phase) {
      const EngineResult e = render_engine_taa(way.run, started_at(s, phase), taa, {}, remembered);
      all.each.push_back({e.total.rmse, e.flicker, e.mean_flip});
    }
  }
  ComparisonMeasures mean{};
  const double n = static_cast<double>(all.each.size());
  for (size_t i = 0; i < all.each.size(); ++i)
    for (size_t q = 0; q < mean.size(); ++q) {
      mean[q] += all.each[i][q] / n;
      if (i == 0 || all.each[i][q] > all.worst[q]) {
        all.worst[q] = all.each[i][q];
        all.worst_at[q] = static_cast<int>(i);
      }
    }
  if (spread) *spread = std::move(all);
  return mean;
}

void PreparedScenes::forget(size_t scene) {
  for (Way& way : scenes_[scene]) way.memo.clear();
}

EngineComparisonResult compare_under_engine(const std::vector<Sequence>& sequences,
                                            const EngineComparison& c,
                                            const ReferenceSource& references,
                                            const ItemsProgress& progress) {
  validate(c, sequences.size());
  PreparedScenes prepared(c, references);
  EngineComparisonResult r;
  for (const Sequence& s : sequences) {
    r.sequences.push_back(s.name);
    for (std::string& w : engine_sequence_warnings(s, c.taa)) r.warnings.push_back(std::move(w));
  }
  if (c.motion == "resonant") r.velocities = resonant_velocities();
  const int renders = static_cast<int>(sequences.size() * c.scenes.size());
  int done = 0;
  for (size_t m = 0; m < c.scenes.size(); ++m) {
    ComparedScene scene{c.scenes[m], prepared.motion(m), {}, {}};
    for (const Sequence& s : sequences) {
      MeasureSpread spread;
      scene.measures.push_back(prepared.render(m, s, c.taa, &spread));
      if (prepared.spread()) scene.spread.push_back(std::move(spread));
      if (progress) progress(++done, renders, fmt::format("{} on {}", s.name, c.scenes[m]));
    }
    prepared.forget(m);  // each scene's references serve its sequences only
    r.scenes.push_back(std::move(scene));
  }
  // Sequence k against the first on one per-scene value of each measure.
  const auto against = [&](size_t k, const auto& value) {
    SequencePairs per;
    for (size_t q = 0; q < kComparisonMeasures.size(); ++q) {
      std::vector<double> ours, theirs;
      for (const ComparedScene& s : r.scenes) {
        ours.push_back(value(s, k)[q]);
        theirs.push_back(value(s, 0)[q]);
      }
      per[q] = compare_paired(ours, theirs, c.resamples, c.confidence, c.seed);
    }
    return per;
  };
  for (size_t k = 1; k < sequences.size(); ++k) {
    r.against_first.push_back(
        against(k, [](const ComparedScene& s, size_t i) { return s.measures[i]; }));
    if (prepared.spread())
      r.against_first_worst.push_back(
          against(k, [](const ComparedScene& s, size_t i) { return s.spread[i].worst; }));
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
      if (!s.spread.empty()) {
        const MeasureSpread& spread = s.spread[k];
        const bool resonant = !r.velocities.empty();
        JsonObject worst, at;
        for (size_t q = 0; q < kComparisonMeasures.size(); ++q) {
          worst[kComparisonMeasures[q]] = spread.worst[q];
          const auto i = static_cast<size_t>(spread.worst_at[q]);
          if (resonant)
            at[kComparisonMeasures[q]] = {r.velocities[i].x, r.velocities[i].y};
          else
            at[kComparisonMeasures[q]] = i;
        }
        row[resonant ? "worst_velocity" : "worst_phase"] = worst;
        row[resonant ? "worst_velocity_at" : "worst_phase_at"] = at;
        if (resonant) {
          JsonObject::array_t each;
          for (const ComparisonMeasures& m : spread.each) {
            JsonObject one;
            for (size_t q = 0; q < kComparisonMeasures.size(); ++q)
              one[kComparisonMeasures[q]] = m[q];
            each.push_back(one);
          }
          row["per_velocity"] = each;
        }
      }
      rows.push_back(row);
    }
    scenes.push_back(JsonObject{{"scene", s.scene}, {"motion", s.motion}, {"rows", rows}});
  }
  const auto against = [&](const std::vector<SequencePairs>& comparisons) {
    JsonObject::array_t out;
    for (size_t k = 1; k <= comparisons.size(); ++k) {
      JsonObject entry{{"sequence", r.sequences[k]}, {"against", r.sequences[0]}};
      for (size_t q = 0; q < kComparisonMeasures.size(); ++q)
        entry[kComparisonMeasures[q]] = paired_comparison_json(comparisons[k - 1][q]);
      out.push_back(entry);
    }
    return out;
  };
  JsonObject::array_t measures;
  for (const char* m : kComparisonMeasures) measures.push_back(m);
  doc.update(comparison_settings_json(c));
  doc.update(JsonObject{{"resamples", c.resamples},
                        {"confidence", c.confidence},
                        {"measures", measures},
                        {"sequences", r.sequences}});
  if (!r.velocities.empty()) {
    JsonObject::array_t velocities;
    for (const Vec2 v : r.velocities) velocities.push_back({v.x, v.y});
    doc["velocities"] = velocities;
  }
  doc["scenes"] = scenes;
  doc["against_first"] = against(r.against_first);
  if (!r.against_first_worst.empty()) doc["against_first_worst"] = against(r.against_first_worst);
  if (!r.warnings.empty()) doc["warnings"] = r.warnings;
  return doc;
}

}  // namespace aapat
