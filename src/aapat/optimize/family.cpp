#include "aapat/optimize/family.h"
#include "aapat/generate/portable_random.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/text.h"

namespace aapat {
namespace {

constexpr double kEdgeMargin = 1e-3;  // seeds keep this far from corners and borders

struct SiteInfo {
  Site site;
  const char* text;
  double cost;
  Vec2 fixed;  // +-0.5 on the bordered axes, 0 on the free ones
};

constexpr SiteInfo kSites[] = {
    {Site::kInside, "inside", 1.0, {0, 0}},
    {Site::kLeft, "left", 0.5, {-0.5, 0}},
    {Site::kRight, "right", 0.5, {0.5, 0}},
    {Site::kBottom, "bottom", 0.5, {0, -0.5}},
    {Site::kTop, "top", 0.5, {0, 0.5}},
    {Site::kBottomLeft, "bottom-left", 0.25, {-0.5, -0.5}},
    {Site::kBottomRight, "bottom-right", 0.25, {0.5, -0.5}},
    {Site::kTopLeft, "top-left", 0.25, {-0.5, 0.5}},
    {Site::kTopRight, "top-right", 0.25, {0.5, 0.5}},
};

const SiteInfo& info(Site s) {
  return kSites[static_cast<int>(s)];
}

Site parse_site(std::string_view text) {
  for (const auto& s : kSites)
    if (text == s.text) return s.site;
  throw ParameterError(
      "placement",
      fmt::format(": unknown site '{}' (sites are inside, left, right, bottom, top, bottom-left, "
                  "bottom-right, top-left, top-right)",
                  text));
}

uint64_t splitmix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

std::string site_text(Site s) {
  return info(s).text;
}
double site_cost(Site s) {
  return info(s).cost;
}

std::string FamilySpec::text() const {
  return fmt::format("P({},{},{})", s,
                     footprint.pixels() == 1
                         ? (footprint.plus ? "1+" : "1")
                         : fmt::format("{}{}", footprint.pixels(), footprint.plus ? "+" : ""),
                     format_cost(n));
}

FamilySpec family_shape(std::string_view family) {
  FamilySpec spec;
  const std::string_view f = trim(family);
  if (!f.starts_with("P(") || !f.ends_with(")"))
    throw ParameterError("family",
                         fmt::format(": '{}' is not of the form P(s,r,n), e.g. P(4,1+,2)", family));
  const std::string_view body = f.substr(2, f.size() - 3);
  const auto c1 = body.find(','), c2 = body.rfind(',');
  if (c1 == std::string_view::npos || c1 == c2)
    throw ParameterError("family",
                         fmt::format(": '{}' is not of the form P(s,r,n), e.g. P(4,1+,2)", family));
  const double s = parse_number(body.substr(0, c1), "family: s");
  spec.footprint = parse_footprint(trim(body.substr(c1 + 1, c2 - c1 - 1)));
  spec.n = parse_number(body.substr(c2 + 1), "family: n");
  // The range first: the square root of a huge s must not overflow an int.
  const int side = s >= 1 && s <= 64 ? static_cast<int>(std::lround(std::sqrt(s))) : 0;
  if (side < 1 || side * side != s)
    throw ParameterError("family",
                         fmt::format(" {}: s = {} must be a square number of sets 1, 4, 9, ... 64 "
                                     "(a square tile)",
                                     family, s));
  spec.s = static_cast<int>(s);
  if (!(spec.n > 0) || spec.n > 256)
    throw ParameterError("family",
                         fmt::format(" {}: n = {} is out of range (0, 256]", family, spec.n));

  spec.mirrored = spec.s == 4 && spec.footprint == Footprint{1, true};
  return spec;
}

FamilySpec parse_family(std::string_view family, std::string_view placement) {
  FamilySpec spec = family_shape(family);
  if (placement.empty()) {
    if (spec.n != std::floor(spec.n))
      throw ParameterError("family",
                           fmt::format(" {}: n = {} is not a whole number of inside samples; give "
                                       "a placement with border sites (corner 1/4, edge 1/2)",
                                       family, spec.n));
    spec.sites.assign(static_cast<size_t>(spec.n), Site::kInside);
  } else {
    for (std::string_view site : split(placement)) spec.sites.push_back(parse_site(trim(site)));
  }
  const bool on_border =
      std::any_of(spec.sites.begin(), spec.sites.end(), [](Site x) { return x != Site::kInside; });
  spec.mirrored = spec.s == 4 && spec.footprint == Footprint{1, true};
  if (on_border && !spec.footprint.plus)
    throw ParameterError("family",
                         fmt::format(" {}: border sites are shared with the neighbours, which only "
                                     "a sharing footprint (r with +) reads",
                                     family));
  if (on_border && !spec.mirrored && !(spec.s == 1 && spec.footprint.size == 1))
    throw ParameterError("family",
                         fmt::format(" {}: border sites are supported for P(1,1+,n) and the "
                                     "mirrored P(4,1+,n)",
                                     family));
  for (Site site : {Site::kBottomLeft, Site::kBottomRight, Site::kTopLeft, Site::kTopRight})
    if (std::count(spec.sites.begin(), spec.sites.end(), site) > 1)
      throw ParameterError(
          "placement", fmt::format(": the {} corner holds one sample at most", site_text(site)));
  if (spec.s == 1 && spec.footprint.plus) {
    // In a 1x1 tile a pixel's left-edge sample is its neighbour's right-edge
    // sample, which this pixel also reads: such sites come in pairs.
    auto count = [&](Site x) { return std::count(spec.sites.begin(), spec.sites.end(), x); };
    if (count(Site::kLeft) != count(Site::kRight) || count(Site::kTop) != count(Site::kBottom))
      throw ParameterError(
          "placement",
          fmt::format(": in {} every pixel repeats the same set, so a left-edge sample is also the "
                      "right-edge sample of the pixel to the left: list left and right (and top "
                      "and bottom) "
                      "in pairs",
                      family));
    const auto corners = count(Site::kBottomLeft) + count(Site::kBottomRight) +
                         count(Site::kTopLeft) + count(Site::kTopRight);
    if (corners != 0 && corners != 4)
      throw ParameterError("placement",
                           fmt::format(": in {} a corner sample is every corner's sample: list "
                                       "all four corners or none",
                                       family));
  }
  // n from the sites: each physical sample once (in a 1x1 1+ tile the paired
  // edges and the four corners are one sample each, whose reads cost 1/2, 1/4).
  double cost = 0;
  std::string terms;
  for (Site x : spec.sites) {
    cost += site_cost(x);
    terms +=
        fmt::format("{}{} {}", terms.empty() ? "" : " + ", site_text(x), format_cost(site_cost(x)));
  }
  if (std::abs(cost - spec.n) > 1e-9)
    throw ParameterError("family",
                         fmt::format(" {} says n = {} but the placement costs {} ({})", family,
                                     format_cost(spec.n), format_cost(cost), terms));
  return spec;
}

std::mt19937_64 start_rng(uint64_t seed, uint64_t index) {
  return std::mt19937_64(splitmix(splitmix(seed) ^ (index + 1) * 0xd1b54a32d192ed03ULL));
}

void set_filter_weights(Pattern& p, const Filter& filter) {
  for (int k = 0; k < p.set_count(); ++k) {
    const auto reads = kernel_samples(p, k);
    std::vector<double> w;
    double sum = 0;
    for (const auto& r : reads) {
      w.push_back(filter.value(r.pos.x) * filter.value(r.pos.y));
      sum += w.back();
    }
    for (double& v : w) v = sum > 0 ? v / sum : 1.0 / reads.size();
    p.weights[k] = w;
  }
}

Pattern seed_pattern(const FamilySpec& spec, SeedKind kind, std::mt19937_64& rng,
                     const Filter& filter) {
  const auto along = [](std::mt19937_64& r) {
    return uniform_real(r, -0.5 + kEdgeMargin, 0.5 - kEdgeMargin);
  };
  const double limit = 0.5 - kEdgeMargin;
  const int side = static_cast<int>(std::lround(std::sqrt(spec.s)));
  const int inside =
      static_cast<int>(std::count(spec.sites.begin(), spec.sites.end(), Site::kInside));
  const auto tile_inside = tile_points(spec.mirrored ? 1 : side, inside, kind, rng, limit);
  auto make_set = [&](int k) {
    const std::vector<Vec2>& in = tile_inside[k];
    // Paired sites of a 1x1 sharing tile share one coordinate: right takes
    // the y of a left, top the x of a bottom.
    std::vector<double> left_y, bottom_x;
    for (Site x : spec.sites) {
      if (x == Site::kLeft) left_y.push_back(along(rng));
      if (x == Site::kBottom) bottom_x.push_back(along(rng));
    }
    const bool paired = spec.s == 1;
    std::vector<Vec2> set;
    size_t next_inside = 0, l = 0, b = 0, r = 0, t = 0;
    for (Site x : spec.sites) {
      switch (x) {
        case Site::kInside:
          set.push_back(in[next_inside++]);
          break;
        case Site::kLeft:
          set.push_back({-0.5, left_y[l++]});
          break;
        case Site::kBottom:
          set.push_back({bottom_x[b++], -0.5});
          break;
        case Site::kRight:
          set.push_back({0.5, paired ? left_y[r++] : along(rng)});
          break;
        case Site::kTop:
          set.push_back({paired ? bottom_x[t++] : along(rng), 0.5});
          break;
        default:
          set.push_back(info(x).fixed);
      }
    }
    return set;
  };

  Pattern p;
  if (spec.mirrored) {
    std::vector<Vec2> base = make_set(0);
    p = mirrored_tile_pattern("optimized", base,
                              std::vector<double>(base.size(), 1.0 / base.size()));
  } else {
    p.name = "optimized";
    p.tile_w = p.tile_h = side;
    p.footprint = spec.footprint;
    for (int k = 0; k < spec.s; ++k) p.sets.push_back(make_set(k));
    for (int k = 0; k < spec.s; ++k) {
      const size_t reads = kernel_samples(p, k).size();
      p.weights.push_back(std::vector<double>(reads, 1.0 / reads));
    }
    if (spec.footprint.size > 1) set_filter_weights(p, filter);
  }
  p.description = fmt::format("optimized {}", spec.text());
  return p;
}

}  // namespace aapat
