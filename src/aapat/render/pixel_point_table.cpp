#include "aapat/render/pixel_point_table.h"

#include <tbb/parallel_for.h>

#include <list>
#include <mutex>
#include <tuple>

#include "aapat/generate/point_generators.h"

namespace aapat {

PixelPointTable::PixelPointTable(std::string_view spec, int samples, uint64_t seed, int x0, int y0,
                                 int x1, int y1)
    : x0_(x0), y0_(y0), x1_(x1), y1_(y1) {
  const PointGenerator generator = make_point_generator(spec);
  const auto width = static_cast<size_t>(x1 - x0);
  struct Row {
    std::vector<Vec2> points;
    std::vector<size_t> counts;  // per pixel: a generator may give fewer points than asked
  };
  std::vector<Row> rows(static_cast<size_t>(y1 - y0));
  // A row's points do not depend on the others'.
  tbb::parallel_for(y0, y1, [&](int b) {
    Row& row = rows[static_cast<size_t>(b - y0)];
    for (int a = x0; a < x1; ++a) {
      const std::vector<Vec2> p = pixel_points(generator, samples, seed, a, b);
      row.points.insert(row.points.end(), p.begin(), p.end());
      row.counts.push_back(p.size());
    }
  });
  offsets_.reserve(width * rows.size() + 1);
  offsets_.push_back(0);
  for (const Row& row : rows) {
    for (const size_t count : row.counts) offsets_.push_back(offsets_.back() + count);
    points_.insert(points_.end(), row.points.begin(), row.points.end());
  }
}

namespace {

struct Key {
  std::string spec;
  int samples;
  uint64_t seed;
  int x0, y0, x1, y1;
  bool operator==(const Key& o) const {
    return std::tie(spec, samples, seed, x0, y0, x1, y1) ==
           std::tie(o.spec, o.samples, o.seed, o.x0, o.y0, o.x1, o.y1);
  }
};

struct Kept {
  Key key;
  std::shared_ptr<const PixelPointTable> table;
};

}  // namespace

std::shared_ptr<const PixelPointTable> shared_pixel_points(std::string_view spec, int samples,
                                                           uint64_t seed, int x0, int y0, int x1,
                                                           int y1) {
  const double bytes = double(x1 - x0) * double(y1 - y0) * samples * sizeof(Vec2);
  if (x1 <= x0 || y1 <= y0 || samples < 1 || bytes > double(kMaxSharedPixelTableBytes))
    return nullptr;
  static std::mutex mutex;
  static std::list<Kept> kept;  // the most recently used first
  static size_t kept_bytes = 0;
  Key key{std::string(spec), samples, seed, x0, y0, x1, y1};
  {
    const std::lock_guard lock(mutex);
    for (auto it = kept.begin(); it != kept.end(); ++it)
      if (it->key == key) {
        kept.splice(kept.begin(), kept, it);
        return kept.front().table;
      }
  }
  // Drawn outside the lock; two threads that ask at once draw the same points.
  auto table = std::make_shared<const PixelPointTable>(spec, samples, seed, x0, y0, x1, y1);
  const std::lock_guard lock(mutex);
  for (const Kept& k : kept)
    if (k.key == key) return k.table;
  kept.push_front({std::move(key), table});
  kept_bytes += table->bytes();
  while (kept_bytes > kMaxSharedPixelTablesBytes && kept.size() > 1) {
    kept_bytes -= kept.back().table->bytes();
    kept.pop_back();
  }
  return table;
}

}  // namespace aapat
