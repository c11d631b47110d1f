// Pattern families P(s, r, n) as the optimizer's command line names them,
// with an optional placement of the base pixel's samples (SITES), and the
// random seed patterns the multi-start draws from them.
#pragma once

#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/core/pattern.h"
#include "aapat/generate/point_processes.h"

namespace aapat {

enum class Site {
  kInside,
  kLeft,
  kRight,
  kBottom,
  kTop,
  kBottomLeft,
  kBottomRight,
  kTopLeft,
  kTopRight
};

std::string site_text(Site s);
double site_cost(Site s);  // 1 inside, 1/2 on an edge, 1/4 on a corner

struct FamilySpec {
  int s = 1;                // distinct sets (a square tile)
  Footprint footprint;      // r
  double n = 1;             // samples per pixel
  std::vector<Site> sites;  // where each sample of a base set sits
  bool mirrored = false;    // P(4,1+,n): the base set mirrored over a 2x2 tile
  std::string text() const;
};

// Parses "P(4,1+,1.25)" and "left,right,bottom,top"; checks that the
// placement's cost equals n and that the sites fit the family, saying why not.
FamilySpec parse_family(std::string_view family, std::string_view placement);
// The family alone (s, r, n, mirrored), no sites: what a search over every
// placement needs before it has one.
FamilySpec family_shape(std::string_view family);

// A random pattern of the family: inside samples by `kind`, border samples
// uniform along their edge, weights equal for one-pixel footprints and the
// filter's h(x) h(y) (normalized) for larger ones.
Pattern seed_pattern(const FamilySpec& spec, SeedKind kind, std::mt19937_64& rng,
                     const Filter& filter);

// Weights h(x) h(y) of the filter at each kernel's sample offsets, normalized
// (Laine-Aila Table 3's "Mitchell weights"); equal where they sum to <= 0.
void set_filter_weights(Pattern& p, const Filter& filter);

// The random stream of start `index` of a run seeded with `seed`: the same
// for any thread count or order.
std::mt19937_64 start_rng(uint64_t seed, uint64_t index);

}  // namespace aapat
