#include "aapat/core/objective.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/nearest_name.h"

namespace aapat {

namespace {

std::string canonical_filter(std::string_view spec) {
  return make_filter(spec).name();
}
std::string canonical_acuity(std::string_view spec) {
  return make_acuity(spec).name;
}

Objective make(std::string_view filter, std::string_view acuity, double norm) {
  return {canonical_filter(filter), canonical_acuity(acuity), norm};
}

std::vector<std::string_view> words(std::string_view text) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    const size_t start = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i > start) out.push_back(text.substr(start, i - start));
  }
  return out;
}

}  // namespace

const std::vector<NamedObjective>& objective_registry() {
  static const std::vector<NamedObjective> kObjectives = {
      {{std::string(kRecommendedObjective),
        "the study's conclusion, the default: Mitchell-Netravali, every degree weighted "
        "equally, the L2 mean over angles; the aapat catalog and sequences are optimized for it",
        "docs/study.md",
        {}},
       make("mitchell", "uniform:step=1", 2)},
      {{std::string(kPapersObjective),
        "the papers' metric: Mitchell-Netravali, the four-angle acuity table, the maximum "
        "over angles; reproduces their published E2",
        "Laine & Aila 2006, Eq. 5; Hasselgren et al. 2006 (docs/metric.md)",
        {}},
       make("mitchell", "laine-aila", Metric::kMaxNorm)},
  };
  return kObjectives;
}

const Objective& named_objective(std::string_view name) {
  std::vector<std::string> names;
  for (const NamedObjective& o : objective_registry()) {
    if (o.info.name == name) return o.objective;
    names.push_back(o.info.name);
  }
  throw Error(
      fmt::format("unknown objective '{}'{}: known objectives are {}, or overrides "
                  "'filter=F acuity=A norm=P'",
                  name, did_you_mean(name, names), fmt::join(names, ", ")));
}

std::vector<SpecInfo> objective_infos() {
  std::vector<SpecInfo> out;
  for (const NamedObjective& o : objective_registry()) {
    SpecInfo info = o.info;
    info.summary += fmt::format(" [{}]", o.objective.components());
    out.push_back(std::move(info));
  }
  return out;
}

std::string Objective::name() const {
  for (const NamedObjective& o : objective_registry())
    if (o.objective == *this) return o.info.name;
  return "";
}

std::string Objective::components() const {
  return fmt::format("filter={} acuity={} norm={}", filter, acuity, format_norm(norm));
}

std::string Objective::text() const {
  std::string n = name();
  return n.empty() ? components() : n;
}

std::string Objective::tag() const {
  const std::string n = name();
  return n.empty() ? fmt::format("{},{},L{}", filter, acuity, format_norm(norm)) : n;
}

std::string Objective::caption() const {
  const std::string n = name();
  return fmt::format("objective {}(filter {}, acuity {}, norm {})", n.empty() ? "" : n + " ",
                     filter, acuity, format_norm(norm));
}

Metric Objective::metric() const {
  return Metric(make_filter(filter), make_acuity(acuity), norm);
}

Objective objective_of(const Metric& metric) {
  return {metric.filter().name(), metric.acuity().name, metric.norm()};
}

std::optional<Objective> design_objective(const Pattern& pattern) {
  const auto value = [&](std::string_view key) -> std::optional<std::string> {
    for (const auto& [k, v] : pattern.provenance)
      if (k == key) return v;
    return std::nullopt;
  };
  const auto filter = value("filter"), acuity = value("acuity"), norm = value("norm");
  if (!filter || !acuity || !norm) return std::nullopt;
  try {
    return make(*filter, *acuity, parse_norm(*norm, "provenance: norm"));
  } catch (const Error&) {
    return std::nullopt;
  }
}

Objective parse_objective(std::string_view text, std::string_view what) {
  const std::vector<std::string_view> items = words(text);
  if (items.empty())
    throw Error(fmt::format("{}: empty; give a name ({}, {}) or 'filter=F acuity=A norm=P'", what,
                            kRecommendedObjective, kPapersObjective));
  size_t first = 0;
  Objective base = named_objective(kRecommendedObjective);
  if (split_spec(items[0]).first == kPerceptualObjective)
    throw Error(fmt::format(
        "{}: the perceptual objective is not E2's: `aapat eval --objective {}` evaluates it, "
        "`aapat refine` searches under it and `aapat study --perceptual` studies it",
        what, items[0]));
  if (items[0].find('=') == std::string_view::npos) {
    try {
      base = named_objective(items[0]);
    } catch (const Error& e) {
      throw Error(fmt::format("{}: {}", what, e.what()));
    }
    first = 1;
  }
  std::optional<std::string> filter, acuity;
  std::optional<double> norm;
  for (size_t i = first; i < items.size(); ++i) {
    const auto eq = items[i].find('=');
    const std::string_view key = items[i].substr(0, eq);
    const std::string_view value =
        eq == std::string_view::npos ? std::string_view{} : items[i].substr(eq + 1);
    if (eq == std::string_view::npos || value.empty())
      throw Error(
          fmt::format("{}: '{}' is not KEY=VALUE (keys: filter, acuity, norm)", what, items[i]));
    const auto once = [&](const auto& slot) {
      if (slot) throw Error(fmt::format("{}: '{}' is given twice", what, key));
    };
    if (key == "filter") {
      once(filter);
      filter = std::string(value);
    } else if (key == "acuity") {
      once(acuity);
      acuity = std::string(value);
    } else if (key == "norm") {
      once(norm);
      norm = parse_norm(value, fmt::format("{}: norm", what));
    } else {
      throw Error(fmt::format("{}: unknown key '{}'{} (keys: filter, acuity, norm)", what, key,
                              did_you_mean(key, {"filter", "acuity", "norm"})));
    }
  }
  return override_objective(std::move(base), filter, acuity, norm);
}

Objective override_objective(Objective base, const std::optional<std::string>& filter,
                             const std::optional<std::string>& acuity,
                             const std::optional<double>& norm) {
  if (filter) base.filter = canonical_filter(*filter);
  if (acuity) base.acuity = canonical_acuity(*acuity);
  if (norm) {
    check_norm(*norm);
    base.norm = *norm;
  }
  return base;
}

}  // namespace aapat
