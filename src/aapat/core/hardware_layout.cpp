#include "aapat/core/hardware_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/lattice.h"

namespace aapat {
namespace {

constexpr int kSide = kLatticeSteps;  // lattice points per pixel side

int wrap(int v, int n) {
  return ((v % n) + n) % n;
}

// A pattern-local position (pixel centre 0, y up) in the API's lattice units,
// 16 meaning the far border (the neighbour's 0).
LatticePoint lattice_point(Vec2 v, bool y_down) {
  return {
      static_cast<int>(std::lround(kSide * v.x + kSide / 2)),
      static_cast<int>(std::lround(y_down ? kSide / 2 - kSide * v.y : kSide * v.y + kSide / 2))};
}

// The tile pixel (and so the set and kernel) of grid pixel (gx, gy).
int tile_index(const Pattern& p, int gx, int gy, int grid_h, bool y_down) {
  const int tx = wrap(gx, p.tile_w), ty = wrap(y_down ? grid_h - 1 - gy : gy, p.tile_h);
  return ty * p.tile_w + tx;
}

}  // namespace

const std::vector<ApiProfile>& api_profiles() {
  static const std::vector<ApiProfile> kProfiles = {
      {"d3d12-tier1", "Direct3D 12 tier 1: one pattern for every pixel, up to 16 samples",
       Api::kD3D12, 1, 16, true, false},
      {"d3d12-tier2",
       "Direct3D 12 tier 2: a 2x2-pixel grid of patterns, at most 4 samples per pixel", Api::kD3D12,
       2, 4, true, false},
      {"vulkan",
       "VK_EXT_sample_locations: a grid up to maxSampleLocationGridSize (4x4 assumed; query it), "
       "positions in the guaranteed [0, 0.9375]",
       Api::kVulkan, 4, 16, true, true},
      {"metal", "Metal setSamplePositions: one pattern per pass, up to 8 samples", Api::kMetal, 1,
       8, true, false},
      {"gl",
       "OpenGL ARB_sample_locations: a grid up to SAMPLE_LOCATION_PIXEL_GRID_* (4x4 assumed; "
       "query it), y up",
       Api::kOpenGL, 4, 16, false, true},
  };
  return kProfiles;
}

const ProfileRegistry& profile_registry() {
  static const ProfileRegistry kRegistry = [] {
    std::vector<ProfileRegistry::Entry> list;
    for (const ApiProfile& p : api_profiles())
      list.push_back({{p.name, p.summary, "the API's programmable sample positions", {}},
                      [&p](const Spec&) { return &p; }});
    return ProfileRegistry("API profile", std::move(list));
  }();
  return kRegistry;
}

const ApiProfile& api_profile(std::string_view name) {
  return *profile_registry().make(name);
}

double HardwareLayout::reads() const {
  double sum = 0;
  for (const auto& t : taps) sum += static_cast<double>(t.size());
  return taps.empty() ? 0 : sum / static_cast<double>(taps.size());
}

LatticePoint HardwareLayout::slot(int g, int i) const {
  const auto& own = positions[g];
  if (i < static_cast<int>(own.size())) return own[i];
  return own.empty() ? LatticePoint{kSide / 2, kSide / 2} : own[0];
}

HardwareLayout hardware_layout(const Pattern& p, const ApiProfile& profile, int grid_w,
                               int grid_h) {
  validate(p);
  if (const std::string off = off_lattice_sample(p, kSide); !off.empty())
    throw Error(
        fmt::format("{}: {}; snap it first (aapat export {} --snap, or aapat snap {} --lattice "
                    "16 -o FILE)",
                    p.name, off, p.name, p.name));
  if (grid_w == 0 || grid_h == 0) {
    grid_w = p.tile_w;
    grid_h = p.tile_h;
    if (!profile.grid_choice && (grid_w > 1 || grid_h > 1)) grid_w = grid_h = profile.max_grid;
  }
  if (grid_w < 1 || grid_h < 1 || grid_w > profile.max_grid || grid_h > profile.max_grid ||
      (!profile.grid_choice && grid_w != grid_h) || grid_w % p.tile_w != 0 ||
      grid_h % p.tile_h != 0)
    throw Error(
        fmt::format("{}: a {}x{} tile does not fit {}'s pixel grid ({}x{} asked, at most "
                    "{}x{}, a multiple of the tile)",
                    p.name, p.tile_w, p.tile_h, profile.name, grid_w, grid_h, profile.max_grid,
                    profile.max_grid));
  HardwareLayout L;
  L.profile = profile.name;
  L.grid_w = grid_w;
  L.grid_h = grid_h;
  L.footprint = p.footprint;
  L.name = p.name;
  const bool down = profile.y_down;
  const int pixels = grid_w * grid_h;
  L.positions.resize(pixels);
  L.taps.resize(pixels);
  size_t most = 1;
  for (int g = 0; g < pixels; ++g) {
    const int s = tile_index(p, g % grid_w, g / grid_w, grid_h, down);
    for (size_t i = 0; i < p.sets[s].size(); ++i) {
      const LatticePoint q = lattice_point(p.sets[s][i], down);
      if (q.x < kSide && q.y < kSide) {
        L.positions[g].push_back(q);
      } else if (!p.footprint.plus) {
        throw Error(
            fmt::format("{}: sets[{}][{}] lies on a border it does not share, which {} "
                        "cannot address; snap it (aapat snap) or use a 1+ footprint",
                        p.name, s, i, profile.name));
      }
    }
    most = std::max(most, L.positions[g].size());
  }
  while (L.sample_count < static_cast<int>(most)) L.sample_count *= 2;
  const int allowed = pixels > 1 && profile.api == Api::kD3D12 ? 4 : profile.max_samples;
  if (L.sample_count > allowed)
    throw Error(
        fmt::format("{}: {} samples per pixel (as {}x MSAA) is more than {} allows with a "
                    "{}x{} grid ({})",
                    p.name, most, L.sample_count, profile.name, grid_w, grid_h, allowed));
  const double o = p.footprint.size == 1 ? 0.0 : 0.5;  // even footprints reconstruct at a corner
  for (int g = 0; g < pixels; ++g) {
    const int gx = g % grid_w, gy = g / grid_w;
    const int k = tile_index(p, gx, gy, grid_h, down);
    const auto reads = kernel_samples(p, k);
    for (size_t r = 0; r < reads.size(); ++r) {
      const Vec2 local = p.sets[reads[r].set][reads[r].index];
      const int i = static_cast<int>(std::lround(reads[r].pos.x + o - local.x)),
                j = static_cast<int>(std::lround(reads[r].pos.y + o - local.y));
      Tap t{i, down ? -j : j, 0, p.weights[k][r]};
      LatticePoint q = lattice_point(local, down);
      if (q.x == kSide) {
        ++t.dx;
        q.x = 0;
      }
      if (q.y == kSide) {
        ++t.dy;
        q.y = 0;
      }
      const auto& owner = L.positions[wrap(gy + t.dy, grid_h) * grid_w + wrap(gx + t.dx, grid_w)];
      const auto it = std::find(owner.begin(), owner.end(), q);
      if (it == owner.end())
        throw Error(fmt::format("{}: kernel {} reads a sample no pixel owns", p.name, k));
      t.sample = static_cast<int>(it - owner.begin());
      L.taps[g].push_back(t);
    }
  }
  return L;
}

Pattern pattern_from_layout(const HardwareLayout& L) {
  if (L.footprint.size != 1)
    throw Error(
        fmt::format("a {} footprint cannot be read back (1 and 1+ can)", L.footprint.text()));
  const bool down = api_profile(L.profile).y_down;
  Pattern p;
  p.name = L.name;
  p.tile_w = L.grid_w;
  p.tile_h = L.grid_h;
  p.footprint = L.footprint;
  p.sets.resize(L.grid_w * L.grid_h);
  p.weights.resize(p.sets.size());
  for (int g = 0; g < L.grid_w * L.grid_h; ++g) {
    const int gx = g % L.grid_w, gy = g / L.grid_w;
    const int k = tile_index(p, gx, gy, L.grid_h, down);
    // The file's own terms in messages: its pixel (x, y), not the pattern's kernel index.
    double sum = 0;
    for (const Tap& t : L.taps[g]) {
      if (!std::isfinite(t.weight) || std::abs(t.weight) > kMaxWeightMagnitude)
        throw Error(fmt::format("pixel ({}, {}): tap weight {} is out of range [-{}, {}]", gx, gy,
                                t.weight, kMaxWeightMagnitude, kMaxWeightMagnitude));
      sum += t.weight;
    }
    if (L.taps[g].empty() || std::abs(sum - 1) > 1e-6)
      throw Error(
          fmt::format("pixel ({}, {}): the resolve weights sum to {:.9g}, not 1", gx, gy, sum));
    for (const Tap& t : L.taps[g]) {
      const auto& owner =
          L.positions[wrap(gy + t.dy, L.grid_h) * L.grid_w + wrap(gx + t.dx, L.grid_w)];
      if (t.sample < 0 || t.sample >= static_cast<int>(owner.size()))
        throw Error(fmt::format("pixel ({}, {}): a tap reads sample {} of a pixel with {}", gx, gy,
                                t.sample, owner.size()));
      const double ax = t.dx + owner[t.sample].x / double(kSide),
                   ay = t.dy + owner[t.sample].y / double(kSide);
      p.sets[k].push_back({ax - 0.5, down ? 0.5 - ay : ay - 0.5});
      p.weights[k].push_back(t.weight);
    }
  }
  const bool uniform =
      std::all_of(p.sets.begin(), p.sets.end(), [&](const auto& s) { return s == p.sets[0]; }) &&
      std::all_of(p.weights.begin(), p.weights.end(),
                  [&](const auto& w) { return w == p.weights[0]; });
  if (uniform) {
    p.tile_w = p.tile_h = 1;
    p.sets.resize(1);
    p.weights.resize(1);
  }
  try {
    validate(p);
  } catch (const Error& e) {
    throw Error(fmt::format("the layout makes no valid pattern: {}", e.what()));
  }
  return p;
}

}  // namespace aapat
