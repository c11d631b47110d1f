// A jitter searched on rendered error (`aapat sequence search`, Python
// sequence_search): the compass search (optimize/compass_search.h) whose
// objective renders the sequence through an engine preset's full nonlinear
// pipeline, clamping included, on a comparison's scenes and motions
// (engine/engine_comparison.h), against a baseline rendered once. Per scene,
// a = log(rmse / the baseline's), c = log(flip / the baseline's) and
// b = log(flicker / the baseline's); the objective is the mean over the
// scenes of
//     a + c + loss (max(0, a) + max(0, c)) + (1 + loss) max(0, b),
// so a scene lost costs more than one won gains (loss 0: the plain mean log
// ratio of the errors), and flicker counts only where it rises: a jitter
// that collapses its samples flickers less and errs more, and a reward for
// less flicker let an earlier form of this search find exactly that (RMSE
// 1.65 times Bevy's own on unseen still scenes). With `worst`, each scene's
// measures are its worst phase after a cut or its worst resonant velocity.
// The start's value is never exceeded; the renders are deterministic,
// so the result is the same at any thread count. The objective is what a
// user sees on these scenes, so a result should be judged on others
// (`aapat sequence compare` on unseen seeds).
#pragma once

#include <string>
#include <vector>

#include "aapat/io/json_report.h"
#include "aapat/temporal/engine/engine_comparison.h"
#include "aapat/temporal/sequence/sequence.h"
#include "aapat/work/work_items.h"

namespace aapat {

struct RenderedSearch {
  EngineComparison comparison;  // the preset, scenes, motion, size, frames, references
  Sequence start, baseline;     // one-sample one-pixel frames
  double step = 1.0 / 16, min_step = 1.0 / 128;
  double loss = 0.5;
  double jitter_bound = 0.5;  // every coordinate within +-bound (below 1/2: inside the pixel)
  int max_tries = 0;          // 0: until the smallest step keeps nothing
  bool worst = false;         // each scene's worst phase or velocity (cut, resonant)
  // XeSS's rule: the frames' mean jitter is (0, 0). Every trial (the start
  // too) is rendered centred: its mean subtracted, a coordinate the
  // centring pushes past the bound refused.
  bool unbiased = false;
  // Further motions searched at once: the objective is the mean over the
  // comparison's motion and these of each one's objective.
  std::vector<std::string> also_motions;
};

struct RenderedSearchResult {
  Sequence best;
  double start_value = 0, value = 0;
  int tries = 0, kept = 0;
  std::vector<std::string> warnings;  // an upscale's jitter shorter than the upscaler's rule
};

// Throws Error (ParameterError naming the setting) before any render: the
// comparison's settings, a start or baseline that is not one-sample frames,
// steps out of range, a loss outside [0, 100], a bound outside
// [kMinJitterBound, 1/2], `worst` where no motion renders a scene several
// ways, an also-motion the comparison cannot make.
void validate(const RenderedSearch& s);

// progress: (step sizes done, step sizes, "J ...") as the compass search
// reports it. Throws Error when the baseline's rmse or flicker is 0 on a
// scene (no ratio to take: a still scene under a still motion).
RenderedSearchResult search_rendered(const RenderedSearch& s,
                                     const ReferenceSource& references = {},
                                     const ItemsProgress& progress = {});

// `aapat sequence search --json` and Python's sequence_search: the
// comparison's settings, against, from, step, min_step, loss, jitter_bound,
// worst, motions (every motion searched), start_value, value, tries, kept, and the result as a
// sequence file's object.
JsonObject rendered_search_json(const RenderedSearch& s, const RenderedSearchResult& r);

}  // namespace aapat
