#include "aapat/generate/point_generators.h"
#include "aapat/generate/portable_random.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <numeric>
#include <random>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/interrupt.h"
#include "aapat/core/metric.h"
#include "aapat/core/text.h"
#include "aapat/generate/dart_grid.h"
#include "aapat/generate/maximal_poisson.h"
#include "aapat/generate/unit_random.h"
#include "aapat/work/byte_codec.h"

namespace aapat {
namespace {

using Params = std::map<std::string, double, std::less<>>;

int square_side(int n, std::string_view name) {
  const int k = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
  if (k * k != n)
    throw Error(fmt::format("{}: n = {} must be a square number (k x k strata)", name, n));
  return k;
}

// The radius of the densest (hexagonal) packing of n points in the unit square.
double packing_radius(int n) {
  return std::sqrt(2 / (std::sqrt(3.0) * n));
}

// Points binned in a g x g grid on the unit torus, for nearest-neighbour
// questions that look only at the cells near a point.
class TorusGrid {
 public:
  explicit TorusGrid(int g) : g_(g), cells_(static_cast<size_t>(g) * g) {}
  int side() const { return g_; }
  void add(Vec2 p) { cells_[index(cell(p.y), cell(p.x))].push_back(p); }
  // The distance from c to the nearest point (infinity when empty): rings of
  // cells outwards until no nearer point can remain. Stops early, returning
  // a value <= `beat`, once a point at or within `beat` is found: the caller
  // only wants candidates farther than that.
  double nearest(Vec2 c, double beat = -1) const {
    const int cx = cell(c.x), cy = cell(c.y);
    double best = INFINITY;
    for (int r = 0; r <= g_ / 2 + 1; ++r) {
      // Every point in ring r or beyond is at least (r - 1) / g away.
      if ((r - 1.0) / g_ > best) break;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          if (std::max(std::abs(dx), std::abs(dy)) != r) continue;
          for (const Vec2& e : cells_[index(cy + dy, cx + dx)]) {
            best = std::min(best, torus_distance(e, c));
            if (best <= beat) return best;
          }
        }
      if (2 * r + 1 >= g_) break;  // the rings have covered every cell
    }
    return best;
  }

 private:
  int cell(double v) const { return std::min(g_ - 1, static_cast<int>(v * g_)); }
  size_t index(int y, int x) const {
    return static_cast<size_t>((y % g_ + g_) % g_) * g_ + (x % g_ + g_) % g_;
  }
  int g_;
  std::vector<std::vector<Vec2>> cells_;
};

// Dart throwing near its jamming density takes tens of darts per point and
// grows faster than n once the grid leaves the cache: larger sets are refused.
void check_dart_count(int n, std::string_view name) {
  if (n > kMaxPoissonPoints)
    throw Error(fmt::format(
        "{}: about {} points exceed the limit of {} for dart throwing (use jittered or halton for "
        "larger sets)",
        name, n, kMaxPoissonPoints));
}

std::vector<Vec2> poisson(int n, double radius, std::mt19937_64& rng,
                          const ItemsProgress& progress) {
  const auto u = [](std::mt19937_64& r) { return unit_double(r); };
  std::vector<Vec2> pts;
  Hundredths done(progress);
  DartGrid grid(radius);
  // Dart throwing with rejection; give up after many misses in a row.
  const int patience = 1000 + 100 * n;
  for (int misses = 0; misses < patience && static_cast<int>(pts.size()) < n;) {
    throw_if_interrupted();
    const Vec2 c{u(rng), u(rng)};
    if (!grid.any_within(c, radius)) {
      pts.push_back(c);
      grid.add(c);
      misses = 0;
      done.at(static_cast<double>(pts.size()) / n);
    } else {
      ++misses;
    }
  }
  return pts;
}

// Mitchell's best candidate: q x i candidates for point i, so the work grows
// as q n^2 / 2 nearest-point queries. The grid is rebuilt as the points
// multiply, so that each query visits a few cells, and a candidate stops as
// soon as a point nearer than the best so far shows it cannot win.
std::vector<Vec2> best_candidate(int n, double q, std::mt19937_64& rng,
                                 const ItemsProgress& progress) {
  Hundredths done(progress);  // point i costs q i queries: the work is (i / n)^2
  const auto u = [](std::mt19937_64& r) { return unit_double(r); };
  std::vector<Vec2> p;
  auto grid_for = [](size_t points) {
    return std::max(1, static_cast<int>(std::sqrt(points * 2.0)));
  };
  TorusGrid grid(1);
  for (int i = 0; i < n; ++i) {
    throw_if_interrupted();
    done.at(static_cast<double>(i) * i / (static_cast<double>(n) * n));
    if (grid_for(p.size()) > grid.side()) {  // about 1 point in 2 cells; O(n^1.5) rebuilding
      grid = TorusGrid(grid_for(p.size()));
      for (const Vec2& v : p) grid.add(v);
    }
    const int tries = std::max(1, static_cast<int>(q * i));
    Vec2 best{u(rng), u(rng)};
    double best_d = i > 0 ? grid.nearest(best) : 0;
    for (int t = 1; t < tries; ++t) {
      const Vec2 c{u(rng), u(rng)};
      const double d = grid.nearest(c, best_d);  // exact whenever it beats best_d
      if (d > best_d) best_d = d, best = c;
    }
    p.push_back(best);
    grid.add(best);
  }
  return p;
}

// N-queens: of all solutions (the first 20,000 in lexicographic order past
// N = 12), the one with the lowest E2 against Mitchell-Netravali (1/3, 1/3)
// with the default acuity table; ties go to the first in that order.
std::vector<Vec2> search_n_queens(int n) {
  const auto solutions = n_queens_solutions(n, n <= 12 ? 1000000 : 20000);
  if (solutions.empty()) throw Error(fmt::format("n-queens: there is no solution for N = {}", n));
  const Metric metric(make_filter(kDefaultFilter), laine_aila_acuity());
  double best = INFINITY;
  std::vector<Vec2> best_points;
  for (const auto& q : solutions) {
    std::vector<Vec2> pts, local;
    for (int r = 0; r < n; ++r) {
      pts.push_back({(q[r] + 0.5) / n, (r + 0.5) / n});
      local.push_back({pts.back().x - 0.5, pts.back().y - 0.5});
    }
    const double e2 = metric.kernel_error(make_kernel(local, std::vector<double>(n, 1.0))).e2;
    if (e2 < best - 1e-12) {
      best = e2;
      best_points = pts;
    }
  }
  return best_points;
}

// The search takes a second for N = 16, and a renderer asks once per pixel:
// each N is searched once per process.
std::vector<Vec2> best_n_queens(int n) {
  static std::mutex mutex;
  static std::map<int, std::vector<Vec2>> found;
  const std::lock_guard lock(mutex);
  auto it = found.find(n);
  if (it == found.end()) it = found.emplace(n, search_n_queens(n)).first;
  return it->second;
}

// The table the registry is built from: spec as listed ("halton:b1=2,b2=3"), summary, source.
struct GeneratorText {
  std::string spec, summary, source;
};

struct Entry {
  GeneratorText info;
  std::vector<std::pair<std::string, double>> params;  // name, default (NAN: derived from n)
  std::function<std::vector<Vec2>(int, const Params&, std::mt19937_64&, const ItemsProgress&)> make;
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> kEntries = {
      {{"regular", "k x k cell centres (n = k^2)", "regular supersampling"},
       {},
       [](int n, const Params&, std::mt19937_64&, const ItemsProgress&) {
         const int k = square_side(n, "regular");
         std::vector<Vec2> p;
         for (int j = 0; j < k; ++j)
           for (int i = 0; i < k; ++i) p.push_back({(i + 0.5) / k, (j + 0.5) / k});
         return p;
       }},
      {{"random", "n independent uniform points", "Pelikan, 'random sampling'"},
       {},
       [](int n, const Params&, std::mt19937_64& rng, const ItemsProgress&) {
         std::vector<Vec2> p(n);
         for (auto& v : p) v = {unit_double(rng), unit_double(rng)};
         return p;
       }},
      {{"jittered", "one uniform point in each of k x k strata (n = k^2)", "Pelikan; Cook 1986"},
       {},
       [](int n, const Params&, std::mt19937_64& rng, const ItemsProgress&) {
         const int k = square_side(n, "jittered");
         std::vector<Vec2> p;
         p.reserve(static_cast<size_t>(n));  // a reference draws 1024 per pixel
         // Dividing by a power of two is multiplying by its inverse, exactly:
         // the same bits without two divisions a point (a reference's k is 32).
         const bool power_of_two = (k & (k - 1)) == 0;
         const double inverse = 1.0 / k;
         for (int j = 0; j < k; ++j)
           for (int i = 0; i < k; ++i) {
             const double u = unit_double(rng), v = unit_double(rng);
             p.push_back(power_of_two ? Vec2{(i + u) * inverse, (j + v) * inverse}
                                      : Vec2{(i + u) / k, (j + v) / k});
           }
         return p;
       }},
      {{"semi-jittered:amount=0.5",
        "jittered within a centred part of each stratum (amount = its side; 1 is jittered)",
        "Pelikan, 'partial jittering'"},
       {{"amount", 0.5}},
       [](int n, const Params& prm, std::mt19937_64& rng, const ItemsProgress&) {
         const int k = square_side(n, "semi-jittered");
         const double a = prm.at("amount");
         if (!(a >= 0 && a <= 1))
           throw Error(fmt::format("semi-jittered: amount = {} is out of range [0, 1]", a));
         const auto u = [a](std::mt19937_64& r) { return uniform_real(r, -a / 2, a / 2); };
         std::vector<Vec2> p;
         for (int j = 0; j < k; ++j)
           for (int i = 0; i < k; ++i)
             p.push_back({(i + 0.5 + u(rng)) / k, (j + 0.5 + u(rng)) / k});
         return p;
       }},
      {{"n-rooks", "one point per row and column: a random permutation of a jittered diagonal",
        "Shirley 1991; Pelikan"},
       {},
       [](int n, const Params&, std::mt19937_64& rng, const ItemsProgress&) {
         std::vector<int> perm(n);
         std::iota(perm.begin(), perm.end(), 0);
         shuffle(perm.begin(), perm.end(), rng);
         const auto u = [](std::mt19937_64& r) { return unit_double(r); };
         std::vector<Vec2> p;
         for (int i = 0; i < n; ++i) p.push_back({(i + u(rng)) / n, (perm[i] + u(rng)) / n});
         return p;
       }},
      {{"n-queens", "N x N grid cells, none sharing a row, column or diagonal; lowest E2 of all",
        "Goss & Wu 2000, Sec. 3.2.2.1 (criterion: docs/analysis.md)"},
       {},
       [](int n, const Params&, std::mt19937_64&, const ItemsProgress&) {
         // Past 20 the lexicographic search for the first solutions takes seconds to minutes.
         if (n < 1 || n > kMaxNQueens)
           throw Error(fmt::format("n-queens: N = {} is out of range 1..{}", n, kMaxNQueens));
         return best_n_queens(n);
       }},
      {{"poisson:radius=R",
        "dart throwing with rejection on the torus (R defaults to 0.75 x densest)",
        "Cook 1986; Pelikan 'Poisson disk sampling'"},
       {{"radius", NAN}},
       [](int n, const Params& prm, std::mt19937_64& rng, const ItemsProgress& progress) {
         check_dart_count(n, "poisson");
         const bool given = !std::isnan(prm.at("radius"));
         double r = given ? prm.at("radius") : 0.75 * packing_radius(n);
         if (given && !(r > 0 && r <= 1))
           throw Error(fmt::format("poisson: radius = {} is out of range (0, 1]", r));
         auto p = poisson(n, r, rng, progress);
         // The default radius shrinks by 5% until n points fit (dart throwing
         // jams near 55% coverage, so an unlucky draw can stop short).
         while (!given && static_cast<int>(p.size()) < n) {
           r *= 0.95;
           p = poisson(n, r, rng, progress);
         }
         if (static_cast<int>(p.size()) < n)
           throw Error(
               fmt::format("poisson: only {} of {} points fit at radius {}; use a smaller "
                           "radius",
                           p.size(), n, r));
         return p;
       }},
      {{"poisson-maximal:radius=R", "dart throwing until no more points fit (n sets R by default)",
        "maximal Poisson disk; Ebeida et al. 2011"},
       {{"radius", NAN}},
       [](int n, const Params& prm, std::mt19937_64& rng, const ItemsProgress& progress) {
         const bool given = !std::isnan(prm.at("radius"));
         const double r = given ? prm.at("radius") : 0.75 * packing_radius(n);
         if (!given && !(r >= kMinMaximalPoissonRadius))
           throw Error(fmt::format(
               "poisson-maximal: n = {} asks for radius {}, below the smallest, {} (a maximal "
               "set of radius r has about 0.7 / r^2 points)",
               n, r, kMinMaximalPoissonRadius));
         return maximal_poisson_disk(r, rng, progress);
       }},
      {{"best-candidate:q=10",
        "Mitchell's best candidate: of q x (points so far) random candidates, the farthest",
        "Mitchell 1987; Pelikan"},
       {{"q", 10}},
       [](int n, const Params& prm, std::mt19937_64& rng, const ItemsProgress& progress) {
         const double q = prm.at("q");
         if (!(q >= 1 && q <= 1000))
           throw Error(fmt::format("best-candidate: q = {} is out of range 1..1000", q));
         // q n^2 / 2 candidate queries: refuse what would run for minutes.
         if (q * n * static_cast<double>(n) / 2 > kMaxBestCandidateQueries)
           throw Error(fmt::format(
               "best-candidate: n = {} with q = {} asks for {:.3g} candidates, over the limit of "
               "{:.3g} (n <= {} at q = 10); use poisson for large sets",
               n, q, q * n * static_cast<double>(n) / 2, kMaxBestCandidateQueries,
               static_cast<int>(std::sqrt(2 * kMaxBestCandidateQueries / 10))));
         return best_candidate(n, q, rng, progress);
       }},
      {{"hammersley:b=2", "(i / n, g_b(i)), i = 0..n-1", "Pelikan 'Hammersley'"},
       {{"b", 2}},
       [](int n, const Params& prm, std::mt19937_64&, const ItemsProgress&) {
         std::vector<Vec2> p;
         for (int i = 0; i < n; ++i)
           p.push_back(
               {static_cast<double>(i) / n, radical_inverse(i, static_cast<int>(prm.at("b")))});
         return p;
       }},
      {{"halton:b1=2,b2=3", "(g_b1(i), g_b2(i)), i = 1..n", "Halton 1970; Pelikan"},
       {{"b1", 2}, {"b2", 3}},
       [](int n, const Params& prm, std::mt19937_64&, const ItemsProgress&) {
         std::vector<Vec2> p;
         for (int i = 1; i <= n; ++i)
           p.push_back({radical_inverse(i, static_cast<int>(prm.at("b1"))),
                        radical_inverse(i, static_cast<int>(prm.at("b2")))});
         return p;
       }},
      {{"larcher-pillichshammer", "(i / n, LP(i)): a (0, m, 2)-net for n = 2^m",
        "Larcher & Pillichshammer 2001; Kollig & Keller 2002; Pelikan"},
       {},
       [](int n, const Params&, std::mt19937_64&, const ItemsProgress&) {
         std::vector<Vec2> p;
         for (int i = 0; i < n; ++i)
           p.push_back(
               {static_cast<double>(i) / n, larcher_pillichshammer(static_cast<uint32_t>(i))});
         return p;
       }},
  };
  return kEntries;
}

std::string base_name(const std::string& spec) {
  return spec.substr(0, spec.find(':'));
}

}  // namespace

double radical_inverse(uint64_t i, int base) {
  double inv = 1.0 / base, f = inv, r = 0;
  for (; i > 0; i /= base, f *= inv) r += f * static_cast<double>(i % base);
  return r;
}

double larcher_pillichshammer(uint32_t i) {
  uint32_t r = 0;
  for (uint32_t v = 1u << 31; i; i >>= 1, v |= v >> 1)
    if (i & 1) r ^= v;
  return r / 4294967296.0;
}

namespace {

// Row r of the backtracking: `cols`, `left` and `right` mark the columns of
// row r that a queen above attacks vertically or along a diagonal (the
// diagonal masks shift by one column per row). Free columns are taken lowest
// first, so the solutions come in lexicographic order.
void place_queens(int n, int r, uint64_t cols, uint64_t left, uint64_t right, std::vector<int>& q,
                  size_t limit, std::vector<std::vector<int>>& out) {
  if (r == n) {
    out.push_back(q);
    return;
  }
  const uint64_t all = (1ULL << n) - 1;
  for (uint64_t free = all & ~(cols | left | right); free && out.size() < limit; free &= free - 1) {
    const uint64_t bit = free & (~free + 1);
    q[r] = std::countr_zero(free);
    place_queens(n, r + 1, cols | bit, ((left | bit) << 1) & all, (right | bit) >> 1, q, limit,
                 out);
  }
}

}  // namespace

std::vector<std::vector<int>> n_queens_solutions(int n, size_t limit) {
  std::vector<std::vector<int>> out;
  std::vector<int> q(n);
  if (n >= 1 && n <= 32) place_queens(n, 0, 0, 0, 0, q, limit, out);
  return out;
}

namespace {

// What each parameter means, for the listing.
std::string meaning_of(const std::string& key) {
  if (key == "amount") return "side of the jittered part of each stratum (1: jittered)";
  if (key == "radius") return "minimum distance (default: 0.75 of the densest packing's for n)";
  if (key == "q") return "candidates per point, times the points placed so far";
  if (key == "b") return "radical-inverse base, 2..64";
  if (key == "b1") return "base of x, 2..64";
  return "base of y, 2..64";
}

}  // namespace

const GeneratorRegistry& generator_registry() {
  static const GeneratorRegistry kRegistry = [] {
    std::vector<GeneratorRegistry::Entry> list;
    for (const Entry& e : entries()) {
      SpecInfo info{base_name(e.info.spec), e.info.summary, e.info.source, {}};
      for (const auto& [key, value] : e.params)
        info.params.push_back(
            {key, std::isnan(value) ? "" : fmt::format("{}", value), meaning_of(key)});
      list.push_back({info, [&e](const Spec& spec) -> PointGenerator {
                        Params prm;
                        for (const auto& [key, value] : e.params)
                          prm[key] = spec.optional_number(key).value_or(value);
                        for (const char* base : {"b", "b1", "b2"})
                          if (prm.contains(base)) spec.whole(base, 2, 64);
                        const std::string name = spec.name();
                        return
                            [&e, prm, name](int n, uint64_t seed, const ItemsProgress& progress) {
                              if (n < 1 || n > kMaxGeneratedPoints)
                                throw Error(fmt::format("{}: n = {} is out of range 1..{}", name, n,
                                                        kMaxGeneratedPoints));
                              std::mt19937_64 rng(seed);
                              return e.make(n, prm, rng, progress);
                            };
                      }});
    }
    return GeneratorRegistry("generator", std::move(list));
  }();
  return kRegistry;
}

PointGenerator make_point_generator(std::string_view spec) {
  return generator_registry().make(spec);
}

std::vector<Vec2> generate_points(std::string_view spec, int n, uint64_t seed,
                                  const ItemsProgress& progress) {
  return make_point_generator(spec)(n, seed, progress);
}

std::vector<std::vector<Vec2>> generate_point_sets(std::string_view spec, int n, uint64_t seed,
                                                   int sets, const ItemsProgress& progress) {
  if (!(sets >= 1 && sets <= kMaxPointSets))
    throw ParameterError("sets", fmt::format(" {}: expected 1 to {}", sets, kMaxPointSets));
  if (static_cast<int64_t>(sets) * n > kMaxGeneratedPointsInAll)
    throw ParameterError(
        "sets", fmt::format(" {} of {} points each: {} points in all, over the limit of {} (16 "
                            "bytes each in memory)",
                            sets, n, static_cast<int64_t>(sets) * n, kMaxGeneratedPointsInAll));
  const PointGenerator generator = make_point_generator(spec);
  if (sets == 1) return {generator(n, seed, progress)};  // its own progress, in hundredths
  const std::vector<std::string> bytes = run_work_items(
      sets,
      [&](int r) {
        return ByteWriter().put_all(generator(n, seed + static_cast<uint64_t>(r), {})).take();
      },
      // The counts only: a finished item's result is its points' bytes, no note.
      [&](int done, int total, const std::string&) {
        if (progress) progress(done, total, "");
      });
  std::vector<std::vector<Vec2>> out;
  for (const std::string& b : bytes) {
    ByteReader reader(b);
    out.push_back(reader.get_all<Vec2>());
    reader.finish();
  }
  return out;
}

Pattern points_to_pattern(const std::vector<Vec2>& unit_points, std::string name) {
  std::vector<Vec2> local;
  for (const Vec2& p : unit_points) local.push_back({p.x - 0.5, p.y - 0.5});
  return single_pixel_pattern(std::move(name), local,
                              std::vector<double>(local.size(), 1.0 / local.size()));
}

uint64_t seed_for_pixel(uint64_t seed, int x, int y) {
  uint64_t h = seed ^ 0x9e3779b97f4a7c15ULL;
  for (uint64_t v : {static_cast<uint64_t>(static_cast<uint32_t>(x)),
                     static_cast<uint64_t>(static_cast<uint32_t>(y))}) {
    h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h = (h ^ (h >> 31)) * 0xbf58476d1ce4e5b9ULL;  // SplitMix64 finalizer
    h ^= h >> 29;
  }
  return h;
}

std::vector<Vec2> pixel_points(std::string_view spec, int n, uint64_t seed, int x, int y) {
  return pixel_points(make_point_generator(spec), n, seed, x, y);
}

std::vector<Vec2> pixel_points(const PointGenerator& generator, int n, uint64_t seed, int x,
                               int y) {
  std::vector<Vec2> p = generator(n, seed_for_pixel(seed, x, y), {});
  for (Vec2& v : p) v = {v.x - 0.5, v.y - 0.5};
  return p;
}

Pattern tile_pattern(std::string_view spec, int n, uint64_t seed, int k) {
  if (k < 1 || k > 32) throw ParameterError("tile", fmt::format(": {} is out of range 1..32", k));
  Pattern p;
  p.name = fmt::format("{}-{}x{}-tile", spec.substr(0, spec.find(':')), k, k);
  p.tile_w = p.tile_h = k;
  for (int y = 0; y < k; ++y)
    for (int x = 0; x < k; ++x) {
      p.sets.push_back(pixel_points(spec, n, seed, x, y));
      p.weights.push_back(std::vector<double>(p.sets.back().size(), 1.0 / p.sets.back().size()));
    }
  return p;
}

}  // namespace aapat
