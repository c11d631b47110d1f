#include "aapat/temporal/sequence/sequence_generators.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "aapat/core/portable_math.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/unit_random.h"

namespace aapat {
namespace {

uint64_t splitmix_finalizer(uint64_t x) {  // splitmix64's finalizer: a hash of the key
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Sobol's first two dimensions at index i as 32-bit fractions: the van der
// Corput sequence (bit reversal) and the dimension of the polynomial x + 1,
// direction numbers m_k = m_{k-1} xor 2 m_{k-1} (1, 3, 5, 15, 17, 51, ...).
uint32_t sobol(uint32_t i, int dim) {
  uint32_t v = 1u << 31, out = 0;
  for (int k = 0; i >> k; ++k) {
    if ((i >> k) & 1) out ^= dim == 0 ? (1u << (31 - k)) : v;
    v ^= v >> 1;  // the next direction number: m_{k+1} = m_k xor 2 m_k, shifted
  }
  return out;
}

// Owen's nested uniform scramble: bit b flips by a hash of the seed, the
// dimension and the bits above it, so every subinterval is permuted alike.
uint32_t owen_scramble(uint32_t v, uint64_t seed, int dim) {
  uint32_t out = 0;
  for (int b = 31; b >= 0; --b) {
    const uint64_t prefix = b == 31 ? 0 : (uint64_t(v) >> (b + 1)) | (1ull << (31 - b));
    const uint32_t flip =
        static_cast<uint32_t>(splitmix_finalizer(seed * 0x100000001b3ull + uint64_t(dim) * 977 +
                                                 splitmix_finalizer(prefix)) &
                              1);
    out |= (((v >> b) & 1u) ^ flip) << b;
  }
  return out;
}

Sequence jitter_sequence(std::string name, std::string description, const std::vector<Vec2>& at) {
  Sequence s{std::move(name), std::move(description), {}, {}};
  for (size_t f = 0; f < at.size(); ++f)
    s.frames.push_back(jitter_frame(at[f], fmt::format("{} frame {}", s.name, f)));
  return s;
}

const Pattern& one_pixel(const std::optional<Pattern>& p, std::string_view what) {
  if (!p) throw Error(fmt::format("sequence {}: give the pattern to take apart (--pattern)", what));
  if (p->set_count() != 1 || p->footprint.size != 1 || p->footprint.plus)
    throw Error(
        fmt::format("sequence {}: {} is a {} pattern; it takes a one-pixel pattern "
                    "P(1,1,n)",
                    what, p->name, family(*p)));
  return *p;
}

double torus_distance_squared(Vec2 a, Vec2 b) {
  double dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
  dx = std::min(dx, 1 - dx);
  dy = std::min(dy, 1 - dy);
  return dx * dx + dy * dy;
}

// How far a candidate lies from the samples taken (the squared torus distance
// to the nearest); for the first, minus its distance to the centre, so the
// larger the better either way.
double spread(Vec2 candidate, const std::vector<Vec2>& taken) {
  if (taken.empty()) return -torus_distance_squared(candidate, {0, 0});
  double nearest = std::numeric_limits<double>::infinity();
  for (const Vec2 v : taken) nearest = std::min(nearest, torus_distance_squared(candidate, v));
  return nearest;
}

// The samples of `p` ordered: each next one the remaining sample that keeps
// the prefix most stratified per axis (the fewest samples in one of m equal
// strata of x and of y), ties to the farthest from those taken (torus), then
// the lower index; the first the nearest the centre.
std::vector<Vec2> rooks_order(std::vector<Vec2> left) {
  std::vector<Vec2> taken;
  while (!left.empty()) {
    const int m = static_cast<int>(taken.size()) + 1;
    size_t best = 0;
    double best_score = std::numeric_limits<double>::infinity(), best_far = -1;
    for (size_t i = 0; i < left.size(); ++i) {
      std::vector<int> sx(static_cast<size_t>(m)), sy(static_cast<size_t>(m));
      auto stratum = [&](double v) {
        return std::clamp(static_cast<int>(std::floor((v + 0.5) * m)), 0, m - 1);
      };
      int worst = 0;
      for (const Vec2 v : taken) {
        worst = std::max({worst, ++sx[static_cast<size_t>(stratum(v.x))],
                          ++sy[static_cast<size_t>(stratum(v.y))]});
      }
      worst = std::max({worst, ++sx[static_cast<size_t>(stratum(left[i].x))],
                        ++sy[static_cast<size_t>(stratum(left[i].y))]});
      const double far = spread(left[i], taken);
      if (worst < best_score || (worst == best_score && far > best_far)) {
        best_score = worst;
        best_far = far;
        best = i;
      }
    }
    taken.push_back(left[best]);
    left.erase(left.begin() + static_cast<long>(best));
  }
  return taken;
}

// Farthest point first (torus distance), starting nearest the centre.
std::vector<Vec2> blue_noise_order(std::vector<Vec2> left) {
  std::vector<Vec2> taken;
  while (!left.empty()) {
    size_t best = 0;
    double best_far = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < left.size(); ++i) {
      const double far = spread(left[i], taken);
      if (far > best_far) best_far = far, best = i;
    }
    taken.push_back(left[best]);
    left.erase(left.begin() + static_cast<long>(best));
  }
  return taken;
}

// Pattern p's samples in K frames, sample i in frame i mod K, equal weights.
Sequence split(const Pattern& p, int frames, std::string name, std::string description) {
  const int n = static_cast<int>(p.sets[0].size());
  if (frames < 1 || n % frames != 0)
    throw Error(fmt::format("sequence split: {} samples do not split into {} frames of equal size",
                            n, frames));
  Sequence s{std::move(name), std::move(description), {}, {}};
  for (int f = 0; f < frames; ++f) {
    std::vector<Vec2> at;
    for (int i = f; i < n; i += frames) at.push_back(p.sets[0][static_cast<size_t>(i)]);
    const std::vector<double> w(at.size(), 1.0 / static_cast<double>(at.size()));
    s.frames.push_back(single_pixel_pattern(fmt::format("{} frame {}", s.name, f), at, w));
  }
  return s;
}

}  // namespace

double radical_inverse_of(uint64_t i, int base) {
  double f = 1.0 / base, r = 0;
  for (; i; i /= static_cast<uint64_t>(base), f /= base)
    r += f * static_cast<double>(i % static_cast<uint64_t>(base));
  return r;
}

namespace {

// Halton point i in bases b1, b2 as a jitter about the pixel centre.
Vec2 halton_jitter(uint64_t i, int b1, int b2) {
  return {radical_inverse_of(i, b1) - 0.5, radical_inverse_of(i, b2) - 0.5};
}

}  // namespace

const SequenceRegistry& sequence_registry() {
  static const SequenceRegistry kRegistry(
      "sequence",
      {{{"halton",
         "Halton jitter: (h_b1(i), h_b2(i)) - 1/2 for i = start, start + 1, ...",
         "Halton 1970; FSR 2's ffxFsr2GetJitterOffset (bases 2, 3, from index 1)",
         {{"b1", "2", "base of x"},
          {"b2", "3", "base of y"},
          {"frames", "8", "phases"},
          {"start", "1", "first index (1 skips the corner, index 0)"}}},
        [](const Spec& s, const std::optional<Pattern>&) {
          const int b1 = s.whole("b1", 2, 97), b2 = s.whole("b2", 2, 97),
                    frames = s.whole("frames", 1, kMaxSequenceFrames),
                    start = s.whole("start", 0, 1 << 30);
          std::vector<Vec2> at;
          for (int i = start; i < start + frames; ++i)
            at.push_back(halton_jitter(uint64_t(i), b1, b2));
          return jitter_sequence(s.canonical(), "Halton jitter", at);
        }},
       {{"bevy-halton",
         "Bevy 0.17's jitter: the pixel centre, then Halton(2,3) - 1/2 from index 1",
         "bevy v0.17.2 crates/bevy_anti_alias/src/taa/mod.rs:380-390 (vec2(0.0, 0.0) first)",
         {{"frames", "8", "phases (the centre and frames - 1 Halton points)"}}},
        [](const Spec& s, const std::optional<Pattern>&) {
          const int frames = s.whole("frames", 1, kMaxSequenceFrames);
          std::vector<Vec2> at{{0, 0}};
          for (int i = 1; i < frames; ++i) at.push_back(halton_jitter(uint64_t(i), 2, 3));
          return jitter_sequence(s.canonical(), "Bevy's Halton jitter", at);
        }},
       {{"ue4-halton",
         "Unreal Engine 4's jitter: Halton(2,3) (u1, u2) warped to a Gaussian of deviation "
         "sigma windowed to radius 1/2 (Box-Muller: r = sigma sqrt(-2 ln((1 - u1) w + u1)), "
         "w = exp(-(1/2)^2 / (2 sigma^2)), angle 2 pi u2)",
         "UE4 SceneVisibility.cpp, r.TemporalAASamples 8: Halton(Index + 1, 2 and 3), "
         "Sigma = 0.47f * r.TemporalAAFilterSize (1)",
         {{"frames", "8", "phases"},
          {"sigma", "0.47", "deviation in pixels"},
          {"start", "1", "first index"}}},
        [](const Spec& s, const std::optional<Pattern>&) {
          const int frames = s.whole("frames", 1, kMaxSequenceFrames),
                    start = s.whole("start", 0, 1 << 30);
          const double sigma = s.in_range("sigma", 1e-3, 16, true);
          const double window = portable_exp(-0.5 * (0.5 / sigma) * (0.5 / sigma));
          std::vector<Vec2> at;
          for (int i = start; i < start + frames; ++i) {
            const double u1 = radical_inverse_of(uint64_t(i), 2),
                         u2 = radical_inverse_of(uint64_t(i), 3);
            const double r = sigma * std::sqrt(-2 * portable_log((1 - u1) * window + u1)),
                         a = 2 * kPi * u2;
            at.push_back({std::clamp(r * portable_cos(a), -0.5, 0.5),
                          std::clamp(r * portable_sin(a), -0.5, 0.5)});
          }
          return jitter_sequence(s.canonical(), "Unreal Engine 4's Gaussian-warped Halton", at);
        }},
       {{"r2",
         "Roberts' R2 jitter: (1/2 + n/g, 1/2 + n/g^2) mod 1 - 1/2, g the plastic number",
         "Roberts 2018, 'The unreasonable effectiveness of quasirandom sequences'",
         {{"frames", "16", "phases"}, {"start", "1", "first n"}}},
        [](const Spec& s, const std::optional<Pattern>&) {
          const int frames = s.whole("frames", 1, kMaxSequenceFrames),
                    start = s.whole("start", 0, 1 << 30);
          const double g = kPlasticNumber;
          std::vector<Vec2> at;
          for (int n = start; n < start + frames; ++n) {
            const double x = 0.5 + n / g, y = 0.5 + n / (g * g);
            at.push_back({x - std::floor(x) - 0.5, y - std::floor(y) - 0.5});
          }
          return jitter_sequence(s.canonical(), "R2 jitter", at);
        }},
       {{"sobol",
         "Sobol jitter, the first two dimensions, Owen-scrambled by the seed",
         "Sobol 1967; Owen 1995 (nested uniform scrambling)",
         {{"frames", "16", "phases"}, {"seed", "1", "scrambling seed (0: unscrambled)"}}},
        [](const Spec& s, const std::optional<Pattern>&) {
          const int frames = s.whole("frames", 1, kMaxSequenceFrames);
          const uint64_t seed = static_cast<uint64_t>(s.whole("seed", 0, 1 << 30));
          std::vector<Vec2> at;
          for (int i = 0; i < frames; ++i) {
            uint32_t x = sobol(uint32_t(i), 0), y = sobol(uint32_t(i), 1);
            if (seed != 0) x = owen_scramble(x, seed, 0), y = owen_scramble(y, seed, 1);
            at.push_back({x * 0x1.0p-32 - 0.5, y * 0x1.0p-32 - 0.5});
          }
          return jitter_sequence(s.canonical(), "Owen-scrambled Sobol jitter", at);
        }},
       {{"random",
         "white-noise jitter: every frame uniform in the pixel, independently",
         "aapat: the baseline any structured jitter must beat; the points of `aapat generate "
         "random --seed S` less 1/2",
         {{"frames", "16", "phases"}, {"seed", "1", "random seed"}}},
        [](const Spec& s, const std::optional<Pattern>&) {
          const int frames = s.whole("frames", 1, kMaxSequenceFrames);
          std::mt19937_64 rng(static_cast<uint64_t>(s.whole("seed", 0, 1 << 30)));
          std::vector<Vec2> at(static_cast<size_t>(frames));
          for (Vec2& v : at) {  // x before y, as the point generator draws them
            const double x = unit_double(rng);
            v = {x - 0.5, unit_double(rng) - 0.5};
          }
          return jitter_sequence(s.canonical(), "white-noise jitter", at);
        }},
       {{"display-lattice",
         "the render offsets at which display pixel centres fall at ratio R (the upscale "
         "model's display phases less 1/2: -1/3, 0, 1/3 at 1.5), n per axis, frame k at "
         "(c[k mod n], c[(k + floor(k / n)) mod n]): every n frames take each offset once per "
         "axis, every n^2 each lattice point once",
         "aapat: docs/temporal.md, 'Under motion'",
         {{"ratio", "1.5", "display / render resolution"},
          {"frames", "", "phases (default: n^2, n display phases per axis)"}}},
        [](const Spec& s, const std::optional<Pattern>&) {
          const std::vector<double> phases = upscale_phases(s.in_range("ratio", 1, 16));
          const int n = static_cast<int>(phases.size());
          const int frames = s.given("frames") ? s.whole("frames", 1, kMaxSequenceFrames) : n * n;
          std::vector<Vec2> at;
          for (int k = 0; k < frames; ++k)
            at.push_back({phases[size_t(k % n)] - 0.5, phases[size_t((k + k / n) % n)] - 0.5});
          return jitter_sequence(s.canonical(), "display-phase lattice jitter", at);
        }},
       {{"split",
         "a one-pixel pattern's samples in K frames, sample i in frame i mod K",
         "aapat: alternating MSAA; any pattern file split into frames",
         {{"frames", "2", "frames"}}},
        [](const Spec& s, const std::optional<Pattern>& p) {
          const Pattern& base = one_pixel(p, "split");
          return split(base, s.whole("frames", 1, kMaxSequenceFrames),
                       fmt::format("{} split", base.name), "a pattern split into frames");
        }},
       {{"rooks-order",
         "a one-pixel pattern's samples one per frame, each prefix as stratified per axis as it "
         "can be",
         "aapat: N-rooks prefixes",
         {}},
        [](const Spec&, const std::optional<Pattern>& p) {
          const Pattern& base = one_pixel(p, "rooks-order");
          return jitter_sequence(fmt::format("{} rooks-order", base.name),
                                 "samples ordered for stratified prefixes",
                                 rooks_order(base.sets[0]));
        }},
       {{"blue-noise-order",
         "a one-pixel pattern's samples one per frame, farthest point first",
         "aapat: blue-noise prefixes",
         {}},
        [](const Spec&, const std::optional<Pattern>& p) {
          const Pattern& base = one_pixel(p, "blue-noise-order");
          return jitter_sequence(fmt::format("{} blue-noise-order", base.name),
                                 "samples ordered farthest point first",
                                 blue_noise_order(base.sets[0]));
        }},
       {{"msaa-alternating",
         "the standard MSAA pattern of samples x frames, split into frames of `samples`",
         "Direct3D standard positions (data/); alternating MSAA",
         {{"samples", "2", "samples per frame"}, {"frames", "2", "frames"}}},
        [](const Spec& s, const std::optional<Pattern>&) {
          const int per = s.whole("samples", 1, 8), frames = s.whole("frames", 1, 16);
          const int total = per * frames;
          if (total != 2 && total != 4 && total != 8 && total != 16)
            throw ParameterError("sequence", fmt::format(" msaa-alternating: {} x {} = {} samples: "
                                                         "the standard patterns have 2, 4, 8 or 16",
                                                         per, frames, total));
          return split(catalog_pattern(fmt::format("msaa-{}", total)), frames, s.canonical(),
                       "standard MSAA alternated over frames");
        }}});
  return kRegistry;
}

Sequence make_sequence(std::string_view spec, const std::optional<Pattern>& pattern) {
  Sequence s = sequence_registry().make(spec, pattern);
  s.provenance.emplace_back("generator", std::string(spec));
  if (pattern) s.provenance.emplace_back("pattern", pattern->name);
  validate(s);
  return s;
}

}  // namespace aapat
