// The objective: what "E2" means in a result. One value holding the three
// choices that define it (the reference filter, the acuity table and the
// norm over angles), with names for the two that matter:
//   recommended: the study's conclusion (docs/study.md), the objective the
//                aapat catalog and sequences are optimized for, and the
//                default of every command and Python function;
//   laine-aila:  the papers' metric (Mitchell-Netravali, the four-angle
//                table, the maximum over angles), under which the published
//                tables are reproduced.
// Text form: a name, optionally followed by overrides, or overrides alone
// (starting from `recommended`):
//   "laine-aila", "recommended norm=4", "filter=lanczos:lobes=2 acuity=uniform:step=1 norm=2".
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/metric.h"
#include "aapat/core/spec.h"

namespace aapat {

struct Objective {
  std::string filter;  // a filter spec (core/filter_catalog.h), canonical
  std::string acuity;  // an acuity spec or CSV path (core/acuity.h), canonical
  double norm = 2;     // p of the L_p mean over angles; inf is the maximum

  // The registered name whose components these are, or "" for another objective.
  std::string name() const;
  // "filter=F acuity=A norm=P": every component, parseable by parse_objective.
  std::string components() const;
  // The name where there is one, else components(): what outputs print.
  std::string text() const;
  // The name, or "F,A,LP" without spaces: part of an optimized pattern's name.
  std::string tag() const;
  // "objective NAME (filter F, acuity A, norm P)": the line every text output opens with.
  std::string caption() const;
  Metric metric() const;
  bool operator==(const Objective&) const = default;
};

inline constexpr std::string_view kRecommendedObjective = "recommended";
inline constexpr std::string_view kPapersObjective = "laine-aila";
// FLIP's model on test charts (study/perceptual_objective.h): a spec of its
// own, not an E2 objective; its name is refused here with where it is taken.
inline constexpr std::string_view kPerceptualObjective = "perceptual";
// What every face evaluates under unless told otherwise.
inline constexpr std::string_view kDefaultObjective = kRecommendedObjective;

struct NamedObjective {
  SpecInfo info;  // name, summary, source (no parameters: overrides take their place)
  Objective objective;
};
// recommended and laine-aila, in that order.
const std::vector<NamedObjective>& objective_registry();
const Objective& named_objective(std::string_view name);
// Their entries, for `aapat list` and aapat.registry().
std::vector<SpecInfo> objective_infos();

// The objective a metric evaluates (its filter, acuity table and norm).
Objective objective_of(const Metric& metric);

// The objective a pattern was designed for, from its provenance (filter,
// acuity, norm, as optimize records them); none when it does not say or
// names a file that is gone.
std::optional<Objective> design_objective(const Pattern& pattern);

// Parses the text form; `what` names the input in errors ("--objective").
// Unknown names suggest the nearest; unknown keys name the keys known.
Objective parse_objective(std::string_view text, std::string_view what = "objective");

// Replaces the components that are given (the --filter/--acuity/--norm
// overrides, or Python's filter=/acuity=/norm=), canonicalized.
Objective override_objective(Objective base, const std::optional<std::string>& filter,
                             const std::optional<std::string>& acuity,
                             const std::optional<double>& norm);

}  // namespace aapat
