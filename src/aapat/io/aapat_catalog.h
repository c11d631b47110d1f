// The aapat catalog: for every budget and API, the best pattern aapat found
// under the objective the study recommends (data/patterns/*.json, written
// by scripts/make-catalog.sh with their provenance and embedded in the
// binary): aapat-N (one pixel, N samples), aapat-shared-N (Hasselgren's
// P(4,1+,N)), aapat-2x2-N (2x2-pixel kernels), aapat-quincunx-2 (Quincunx's
// P(1,1+,2): corners shared by four pixels), each but the last also on an
// API's lattice (aapat-8-d3d12-tier1, aapat-shared-2-vulkan, ...); the free
// entries then refined under the perceptual objective and on content
// (scripts/make-catalog.sh, docs/catalog.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/pattern.h"
#include "aapat/core/spec.h"

namespace aapat {

// Every catalog name, sorted, with a line saying what it is.
std::vector<SpecInfo> aapat_catalog();
bool in_aapat_catalog(std::string_view name);

// "The best pattern at N samples per pixel", one answer whatever its family:
// per cost (samples per pixel, shared samples counted by their share), the
// free entry refined on content with the lowest recorded mean FLIP on the
// tuning views (provenance "rendered"; scripts/make-catalog.sh's last stage
// measures every entry on the same views), and the other entries of the cost.
// `aapat list`, the explorer and docs/catalog.md take it from here.
struct BestAtCost {
  double cost = 0;
  std::string name;
  double value = 0;                 // its mean FLIP on the tuning views
  std::vector<std::string> rivals;  // the cost's other refined entries
};
std::vector<BestAtCost> best_per_cost();      // by cost
std::vector<SpecInfo> best_per_cost_infos();  // as `aapat list` shows them
// Throws Error naming the known names for an unknown one.
Pattern aapat_catalog_pattern(std::string_view name);

}  // namespace aapat
