// The sequence file: JSON that round-trips byte for byte (docs/temporal.md).
//   {"format": "aapat-sequence", "version": 1, "name": ..., "description": ...,
//    "jitter": [[x, y], ...]            every frame one sample of weight 1, or
//    "frames": [{pattern}, ...]         every frame a pattern object as in a
//                                       pattern file (docs/pattern-format.md),
//    "provenance": {...}}
// The writer uses "jitter" whenever every frame is one sample of one pixel.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/spec.h"

#include "aapat/temporal/sequence/sequence.h"

namespace aapat {

std::string sequence_to_json(const Sequence& s);
// `source` names the text in errors. Validates (validate(Sequence)).
Sequence sequence_from_json(std::string_view text, std::string_view source);

Sequence load_sequence_file(const std::string& path);
// Written atomically: a failed write leaves no file.
void save_sequence_file(const Sequence& s, const std::string& path);

// The optimized sequences committed under data/sequences/ (made by
// scripts/make-sequences.sh, embedded in the binary), by name: aapat-taa-8,
// aapat-taa-16, with a line each saying what they are.
std::vector<SpecInfo> sequence_catalog();

// A sequence file (a path ending in .json or naming a file), a name of the
// sequence catalog, or a generator spec (temporal/sequence/sequence_generators.h),
// with `pattern` for the generators that take one apart.
Sequence resolve_sequence(const std::string& spec_or_path,
                          const std::optional<Pattern>& pattern = {});

// The same for an upscale by `ratio`: a generator without frames= takes the
// upscaler's phase count, int(8 ratio^2) (upscaler_phase_count). A sequence
// shorter than that rule gets a warning line naming the rule in `warning`.
Sequence resolve_sequence_for_ratio(const std::string& spec_or_path, double ratio,
                                    std::string* warning);

}  // namespace aapat
